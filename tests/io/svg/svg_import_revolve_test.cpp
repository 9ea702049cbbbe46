// `sweep import DRAWING.svg OUT.swp --revolve` (svg/import.hpp, model/evaluation/revolve_curves.hpp): each
// imported curve NAME becomes the profile NAME_profile of `srev NAME 48 NAME_profile`, its points
// unchanged; profile names stay valid and unique; the vase of swp/vase.svg faces outwards,
// drawn either way round.
#include "io/svg/import.hpp"

#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/revolve_curves.hpp"
#include "model/evaluation/scene.hpp"
#include "model/file_limits.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep {
namespace {

Document drawing(const std::string& body, io::DrawingImport what) {
  return io::parse_svg_drawing("<svg xmlns=\"http://www.w3.org/2000/svg\">\n" + body + "\n</svg>\n", "t.svg", "shape",
                               1.0, what);
}

std::vector<std::string> names(const Document& doc) {
  std::vector<std::string> out;
  for (const Object& o : doc.objects) out.push_back(o.name);
  return out;
}

const std::string kTwoPaths =
    "<path id=\"vase\" d=\"M0 10 H 5 C 8 10 8 0 5 -10\"/>\n<path id=\"cup\" d=\"M0 0 L 3 0 3 4\"/>";

TEST(SvgImportRevolve, EachCurveBecomesItsProfileFollowedByItsSurface) {
  const Document doc = drawing(kTwoPaths, io::DrawingImport::Revolved);
  EXPECT_EQ(names(doc), (std::vector<std::string>{"vase_profile", "vase", "cup_profile", "cup"}));
  ASSERT_EQ(doc.objects.size(), 4u);
  for (const int profile : {0, 2}) {
    const Object& curve = doc.objects[static_cast<std::size_t>(profile)];
    const Object& surface = doc.objects[static_cast<std::size_t>(profile + 1)];
    EXPECT_EQ(curve.kind(), ObjectKind::Bezier2);
    EXPECT_EQ(surface.kind(), ObjectKind::SurfaceOfRevolution);
    EXPECT_EQ(surface.as<ProfilePart>().profile, profile) << surface.name;
    EXPECT_EQ(surface.as<CopiesPart>().copies, io::kRevolvedSteps);
    EXPECT_FALSE(surface.as<CapsPart>().caps);
  }
  EXPECT_EQ(io::kRevolvedSteps, 48);
  // As a file: the profile, then the surface that names it, read back as the same document.
  const std::string text = io::write_swp(doc);
  EXPECT_NE(text.find("bez2 vase_profile 16 7\n"), std::string::npos) << text;
  EXPECT_NE(text.find("srev vase 48 vase_profile\n"), std::string::npos) << text;
  EXPECT_NE(text.find("srev cup 48 cup_profile\n"), std::string::npos) << text;
  EXPECT_EQ(io::parse_swp(text, "t.swp"), doc);
}

TEST(SvgImportRevolve, TheProfilesAreTheCurvesUnchanged) {
  const Document curves = drawing(kTwoPaths, io::DrawingImport::Curves);
  const Document revolved = drawing(kTwoPaths, io::DrawingImport::Revolved);
  ASSERT_EQ(curves.objects.size(), 2u);
  ASSERT_EQ(revolved.objects.size(), 4u);
  for (std::size_t i = 0; i < curves.objects.size(); ++i) {
    Object profile = revolved.objects[2 * i];
    EXPECT_EQ(profile.name, curves.objects[i].name + "_profile");
    profile.name = curves.objects[i].name;
    EXPECT_EQ(profile, curves.objects[i]);  // kind, steps and every point exactly
  }
}

TEST(SvgImportRevolve, ATakenProfileNameGetsANumber) {
  // "vase_profile" is an element's id, so vase's profile is vase_profile_2; an element without an
  // id takes the default name, as without --revolve.
  const Document doc = drawing(
      "<path id=\"vase\" d=\"M0 0 H 1 V 1\"/>\n<path id=\"vase_profile\" d=\"M0 0 H 2 V 1\"/>\n<path d=\"M0 0 H 3\"/>",
      io::DrawingImport::Revolved);
  EXPECT_EQ(names(doc), (std::vector<std::string>{"vase_profile_2", "vase", "vase_profile_profile", "vase_profile",
                                                  "shape_profile", "shape"}));
  for (std::size_t i = 1; i < doc.objects.size(); i += 2) {
    EXPECT_EQ(doc.objects[i].as<ProfilePart>().profile, static_cast<int>(i) - 1);
  }
  EXPECT_EQ(io::parse_swp(io::write_swp(doc), "t.swp"), doc);
}

TEST(SvgImportRevolve, LongNamesStayValidAndUnique) {
  // Two curves whose names differ only past where NAME_profile is cut to the longest name.
  const std::string stem(limits::kMaxNameLength - 3, 'a');
  Document doc;
  for (const char* end : {"bcd", "bce"}) {
    Object curve;
    curve.set_kind(ObjectKind::Bezier2);
    curve.name = stem + end;
    curve.as<StepsPart>().steps = 16;
    curve.as<PointsPart>().points = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 0),
                                     glm::dvec3(1, 2, 0)};
    doc.objects.push_back(curve);
  }
  const Document revolved = revolve_curves(doc, 48);
  ASSERT_EQ(revolved.objects.size(), 4u);
  const std::string& first = revolved.objects[0].name;
  const std::string& second = revolved.objects[2].name;
  EXPECT_EQ(first, std::string(limits::kMaxNameLength - 8, 'a') + "_profile");
  EXPECT_EQ(second, std::string(limits::kMaxNameLength - 10, 'a') + "_profile_2");
  EXPECT_EQ(revolved.objects[1].name, stem + "bcd");
  EXPECT_EQ(revolved.objects[3].name, stem + "bce");
  for (const Object& o : revolved.objects) EXPECT_TRUE(is_valid_object_name(o.name)) << o.name;
  EXPECT_EQ(io::parse_swp(io::write_swp(revolved), "t.swp"), revolved);
}

/// Every triangle counterclockwise seen from where its vertices' normals point, and the normals
/// outward: down under the foot, away from the axis at the widest ring.
void expect_facing_outwards(const Document& doc, const std::string& what) {
  const Scene scene = evaluate_document(doc);
  ASSERT_EQ(scene.objects.size(), 2u) << what;
  const Mesh& mesh = scene.objects[1].mesh;
  ASSERT_GT(mesh.triangle_count(), 0u) << what;
  int counterclockwise = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
        c(mesh.positions[mesh.indices[3 * t + 2]]);
    const glm::dvec3 face = glm::cross(b - a, c - a);
    if (glm::length(face) < 1e-9) continue;  // a quad's half collapsed on the axis
    const glm::dvec3 normals = glm::dvec3(mesh.normals[mesh.indices[3 * t]]) +
                               glm::dvec3(mesh.normals[mesh.indices[3 * t + 1]]) +
                               glm::dvec3(mesh.normals[mesh.indices[3 * t + 2]]);
    EXPECT_GT(glm::dot(face, normals), 0.0) << what << ": triangle " << t;
    ++counterclockwise;
  }
  EXPECT_GT(counterclockwise, 0) << what;
  double lowest = 0.0, widest = 0.0;
  for (const glm::vec3& p : mesh.positions) {
    lowest = std::min(lowest, static_cast<double>(p.y));
    widest = std::max(widest, glm::length(glm::dvec2(p.x, p.z)));
  }
  int foot = 0, belly = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
    const double radius = glm::length(glm::dvec2(p.x, p.z));
    if (p.y == lowest && radius < 20.0) {  // inside the foot's rounded edge: flat
      EXPECT_LT(n.y, -0.999) << what << ": vertex " << v;
      ++foot;
    }
    if (radius > widest - 1e-4) {
      EXPECT_GT(glm::dot(n, glm::dvec3(p.x, 0.0, p.z) / radius), 0.999) << what << ": vertex " << v;
      ++belly;
    }
  }
  EXPECT_GE(foot, io::kRevolvedSteps) << what;
  EXPECT_GE(belly, io::kRevolvedSteps) << what;
}

TEST(SvgImportRevolve, TheVaseFacesOutwardsDrawnEitherWayRound) {
  const Document drawn = io::import_svg_drawing(std::filesystem::path(SWEEP_SWP_DIR) / "vase.svg", "vase", 1.0,
                                                io::DrawingImport::Revolved);
  EXPECT_EQ(names(drawn), (std::vector<std::string>{"vase_profile", "vase"}));
  expect_facing_outwards(drawn, "vase.svg");
  // The same outline from the lip down to the axis (each piece reversed, the arc's sweep flag
  // flipped), without the layer's transform: the same surface, facing the same way.
  const Document reversed = drawing(
      "<path id=\"vase\" d=\"M 19.5,18 A 2,2 0 0 1 22,20 C 18,24 14,30 14,40 C 14,62 38,72 40,95 "
      "C 42,118 33,140 25,140 H 0\"/>",
      io::DrawingImport::Revolved);
  expect_facing_outwards(reversed, "vase.svg reversed");
}

}  // namespace
}  // namespace sweep
