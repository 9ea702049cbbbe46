// Attribution (issue 43, item 4): one object's control point moved, an object added, removed and
// recoloured, each said in words naming the object; the object-id pass, fingerprints and sidecars
// it rests on.
#include "io/swp/read.hpp"
#include "model/material.hpp"
#include "render/draw_list.hpp"
#include "snapshot/attribution.hpp"
#include "snapshot/fingerprint.hpp"
#include "snapshot/object_ids.hpp"
#include "snapshot/run_render.hpp"
#include "snapshot/sidecar.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep::snapshot {
namespace {

/// Two surfaces of revolution side by side and a curve: "bowl" and "cup" of profile "p" / "q".
const char* const kTwoBowls =
    "bez2 p 8 4\n[0 -1] [1 -1] [1.2 0] [1 1]\n"
    "bez2 q 8 4\n[0 -1] [0.5 -1] [0.6 0] [0.5 1]\n"
    "srev bowl 24 p\n"
    "srev cup 24 q\n";

struct Case {
  Document doc;
  Scene scene;
  CaseSpec spec;
};

Case load(const std::string& text, Mode mode = Mode::Smooth) {
  Case c;
  c.doc = io::parse_swp(text, "test.swp");
  c.scene = evaluate_document(c.doc);
  c.spec.name = "test-smooth";
  c.spec.mode = mode;
  return c;
}

Sidecar sidecar_of(const Case& c, const render::Camera& camera) {
  const render::DrawList list = render::draw_list(c.doc, c.scene);
  IdPassContent content;
  content.surfaces = c.spec.mode != Mode::Frames;
  const IdMap ids = object_ids(list, camera, c.spec.size, content);
  std::vector<Fingerprint> objects = fingerprints(c.doc, c.scene, ids, {});
  IdMap labels = relabel(ids, objects);
  return make_sidecar(c.spec, "test renderer", camera, std::move(objects), std::move(labels));
}

const ObjectChange* change_of(const Attribution& a, const std::string& object) {
  for (const ObjectChange& c : a.changes) {
    if (c.object == object) return &c;
  }
  return nullptr;
}

TEST(ObjectIds, EveryObjectCoversPixelsAndTheBackgroundTheRest) {
  const Case c = load(kTwoBowls);
  const render::Camera camera = fitted_camera(c.scene, c.spec);
  const IdMap ids = object_ids(render::draw_list(c.doc, c.scene), camera, c.spec.size, IdPassContent{});
  ASSERT_EQ(ids.ids.size(), 320u * 240u);
  const std::size_t bowl = ids.coverage(2), cup = ids.coverage(3);
  EXPECT_GT(bowl, 1000u);
  EXPECT_GT(cup, 100u);
  EXPECT_LT(bowl + cup + ids.coverage(0) + ids.coverage(1), ids.ids.size());  // background remains
}

TEST(ObjectIds, FramesModeDrawsCurvesAndControlPointsButNoSurfaces) {
  const Case c = load(kTwoBowls, Mode::Frames);
  const render::Camera camera = fitted_camera(c.scene, c.spec);
  IdPassContent content;
  content.surfaces = false;
  content.control_points = true;
  const IdMap ids = object_ids(render::draw_list(c.doc, c.scene), camera, c.spec.size, content);
  EXPECT_EQ(ids.coverage(2), 0u);
  EXPECT_GT(ids.coverage(0), 20u);  // the profile p: its curve and its control points
}

TEST(Sidecar, RoundTripsThroughJson) {
  const Case c = load(kTwoBowls);
  const Sidecar s = sidecar_of(c, fitted_camera(c.scene, c.spec));
  const Sidecar back = parse_sidecar(sidecar_json(s));
  EXPECT_EQ(back.renderer, "test renderer");
  EXPECT_EQ(back.mode, Mode::Smooth);
  EXPECT_EQ(back.setup, s.setup);
  EXPECT_EQ(back.ids.ids, s.ids.ids);
  ASSERT_EQ(back.objects.size(), s.objects.size());
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].name, s.objects[i].name);
    EXPECT_EQ(back.objects[i].hash, s.objects[i].hash);
    EXPECT_EQ(back.objects[i].samples, s.objects[i].samples);
    EXPECT_EQ(back.objects[i].coverage, s.objects[i].coverage);
  }
  EXPECT_EQ(back.camera.distance, s.camera.distance);
  EXPECT_EQ(back.camera.target, s.camera.target);
}

TEST(Sidecar, AnUnknownNameIsRefusedByItsKey) {
  const Case c = load(kTwoBowls);
  const std::string text = sidecar_json(sidecar_of(c, fitted_camera(c.scene, c.spec)));
  const std::string seam = "\"seam\": \"full\"";
  ASSERT_NE(text.find(seam), std::string::npos) << text;
  std::string wavy = text;
  wavy.replace(wavy.find(seam), seam.size(), "\"seam\": \"wavy\"");
  try {
    parse_sidecar(wavy);
    FAIL() << "a seam named wavy was read";
  } catch (const SidecarError& e) {
    EXPECT_STREQ(e.what(), "unexpected content: unknown seam 'wavy'");
  }
}

TEST(Sidecar, BadJsonSaysWhat) {
  EXPECT_THROW(parse_sidecar("{"), SidecarError);
  try {
    parse_sidecar("{\"sweep\": 1}");
    FAIL();
  } catch (const SidecarError& e) {
    EXPECT_NE(std::string(e.what()).find("unexpected content"), std::string::npos) << e.what();
  }
}

TEST(Attribution, UnchangedSceneSaysUnchanged) {
  const Case c = load(kTwoBowls);
  const Sidecar s = sidecar_of(c, fitted_camera(c.scene, c.spec));
  const Attribution a = attribute(s, s, nullptr);
  EXPECT_FALSE(a.model_changed);
  ASSERT_NE(change_of(a, "bowl"), nullptr);
  EXPECT_EQ(change_of(a, "bowl")->text, "bowl: unchanged");
}

TEST(Attribution, AMovedControlPointNamesTheObjectAndHowFarItMoved) {
  const Case before = load(kTwoBowls);
  std::string moved = kTwoBowls;
  moved.replace(moved.find("[1 1]"), 5, "[1 1.1]");  // the bowl's rim, 0.1 up
  const Case after = load(moved);
  const render::Camera camera = fitted_camera(before.scene, before.spec);
  const Attribution a = attribute(sidecar_of(before, camera), sidecar_of(after, camera), nullptr);
  EXPECT_TRUE(a.model_changed);
  const ObjectChange* bowl = change_of(a, "bowl");
  ASSERT_NE(bowl, nullptr);
  EXPECT_TRUE(bowl->changed);
  EXPECT_NE(bowl->text.find("bowl: its mesh moved up to 0.1"), std::string::npos) << bowl->text;
  EXPECT_NE(bowl->text.find("bounding box +0.1 in y"), std::string::npos) << bowl->text;
  EXPECT_EQ(change_of(a, "cup")->text, "cup: unchanged");
  EXPECT_EQ(a.changes.front().object, "p");  // changed objects first, in document order
}

TEST(Attribution, AddedRemovedAndRecolouredObjectsAreNamed) {
  const Case before = load(kTwoBowls);
  std::string changed = kTwoBowls;
  changed.replace(changed.find("srev cup 24 q\n"), 14, "");
  changed = "material glass color 0.9 0.2 0.2\n" + changed + "circ lid 16 0.5\n";
  changed.replace(changed.find("srev bowl 24 p"), 14, "srev bowl 24 p material glass");
  const Case after = load(changed);
  const render::Camera camera = fitted_camera(before.scene, before.spec);
  const Attribution a = attribute(sidecar_of(before, camera), sidecar_of(after, camera), nullptr);
  ASSERT_NE(change_of(a, "lid"), nullptr);
  EXPECT_EQ(change_of(a, "lid")->text.rfind("new object 'lid' (covers ", 0), 0u) << change_of(a, "lid")->text;
  ASSERT_NE(change_of(a, "cup"), nullptr);
  EXPECT_EQ(change_of(a, "cup")->text.rfind("object 'cup' removed (it covered ", 0), 0u);
  ASSERT_NE(change_of(a, "bowl"), nullptr);
  EXPECT_EQ(change_of(a, "bowl")->text, "material of 'bowl' changed") << change_of(a, "bowl")->text;
}

TEST(Attribution, DifferingPixelsAreCountedAgainstTheObjectsTheyShow) {
  const Case c = load(kTwoBowls);
  const Sidecar s = sidecar_of(c, fitted_camera(c.scene, c.spec));
  ImageDiff diff;
  diff.same_size = true;
  diff.width = 320;
  diff.height = 240;
  diff.classes.assign(320u * 240u, PixelClass::Same);
  std::size_t marked = 0;
  for (std::size_t p = 0; p < s.ids.ids.size() && marked < 5; ++p) {
    if (s.ids.ids[p] != 0 && s.objects[s.ids.ids[p] - 1u].name == "bowl") {
      diff.classes[p] = PixelClass::Differs;
      ++marked;
    }
  }
  diff.classes[0] = PixelClass::Differs;  // a corner: background in both
  const Attribution a = attribute(s, s, &diff);
  EXPECT_EQ(change_of(a, "bowl")->text, "bowl: 5 pixels differ");
  EXPECT_NE(change_of(a, ""), nullptr);
  EXPECT_EQ(change_of(a, "")->text, "background: 1 pixel differs (no object in either picture)");
}

TEST(Attribution, ThousandsAreSeparated) {
  EXPECT_EQ(grouped_count(0), "0");
  EXPECT_EQ(grouped_count(999), "999");
  EXPECT_EQ(grouped_count(1204), "1,204");
  EXPECT_EQ(grouped_count(12345678), "12,345,678");
}

}  // namespace
}  // namespace sweep::snapshot
