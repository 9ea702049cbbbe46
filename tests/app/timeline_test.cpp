// The riders in the viewer without a window: the timeline strip's Play button and the Play /
// pause key (Shift+Space) drive the clock, riding along places the camera with the rider at the
// timeline's time, and Orbit, Space (reset), the framing keys, an orbit drag, a deleted rider or
// another file end the ride.
#include "app/viewer/actions.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/file_safety.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/viewer_state.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/riders.hpp"
#include "support/file_support.hpp"
#include "support/rider_test_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace {

using sweep::viewer::ViewerState;
namespace viewer = sweep::viewer;
using sweep::editor::CommandId;
using sweep::editor::Key;

constexpr const char* kRiders = sweep::test::kTwoRidersOnAKnot;

void load(ViewerState& s, const char* text, glm::ivec2 window = {1280, 800}) {
  s.layout = sweep::editor::compute_layout(window, window, 1.0f, true);
  ASSERT_TRUE(viewer::show_document(s, sweep::io::parse_swp(text, "riders.swp"), "riders.swp")) << s.error;
}

/// Where the camera should be riding along with rider `name` at `time`.
sweep::render::Camera expected_ride(const ViewerState& s, const std::string& name, double time,
                                    sweep::render::RideView view) {
  const int index = s.doc().find(name);
  sweep::render::Camera camera = s.camera;
  sweep::render::ride_camera(camera, sweep::rider_frame(s.doc(), s.session.scene(), index, time),
                             sweep::rider_size(s.doc(), s.session.scene(), index), view);
  return camera;
}

void expect_same_view(const sweep::render::Camera& a, const sweep::render::Camera& b) {
  EXPECT_NEAR(glm::length(a.eye() - b.eye()), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(a.forward() - b.forward()), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(a.up() - b.up()), 0.0, 1e-9);
}

TEST(Timeline, ADocumentWithRidersGetsTheStripAndPlayPauseIsEnabledOnlyThen) {
  ViewerState s;
  sweep::editor::CommandTable commands;
  viewer::bind_commands(commands, s);
  load(s, "circ c 16 1\n");
  EXPECT_EQ(s.layout.timeline_height, 0.0f);
  EXPECT_FALSE(commands.enabled(CommandId::PlayPause)) << "no riders";
  load(s, kRiders);
  EXPECT_GT(s.layout.timeline_height, 0.0f) << "the layout the file is framed in has the strip";
  ASSERT_TRUE(commands.enabled(CommandId::PlayPause));
  EXPECT_TRUE(commands.press({Key::Space, false, true}));
  EXPECT_TRUE(s.playback.playing());
  EXPECT_TRUE(commands.press({Key::Space, false, true}));
  EXPECT_FALSE(s.playback.playing());
  EXPECT_TRUE(commands.press({Key::Space, false, false}));
  EXPECT_FALSE(s.playback.playing()) << "Space alone resets the camera";
}

TEST(Timeline, AnotherFileStopsTheClockAtZero) {
  ViewerState s;
  load(s, kRiders);
  s.playback.play();
  s.playback.scrub(2.0, 6.0);
  load(s, kRiders);
  EXPECT_FALSE(s.playback.playing());
  EXPECT_EQ(s.playback.time(), 0.0);
}

TEST(Timeline, ThePlayButtonAndTheTimeSliderDriveTheClock) {
  sweep::test::HeadlessImGui imgui;
  ViewerState s;
  sweep::editor::CommandTable commands;
  viewer::bind_commands(commands, s);
  load(s, kRiders, {800, 600});  // the headless display's size
  const auto draw = [&commands](ViewerState& state) { viewer::panels::timeline_panel(state, commands); };
  imgui.frame(s, draw);
  const glm::vec2 play = imgui.position(s, draw, "play");
  ASSERT_GE(play.x, 0.0f) << "the strip shows its Play button";
  EXPECT_GT(play.y, 600.0f - s.layout.status_height - s.layout.timeline_height - 1.0f) << "at the bottom";
  imgui.drag(s, draw, play, play);
  EXPECT_TRUE(s.playback.playing());
  imgui.drag(s, draw, play, play);
  EXPECT_FALSE(s.playback.playing());

  const glm::vec2 time = imgui.position(s, draw, "time");
  ASSERT_GE(time.x, 0.0f);
  imgui.drag(s, draw, time, time + glm::vec2(120.0f, 0.0f));
  EXPECT_GT(s.playback.time(), 0.5) << "dragged to the right: later";
  EXPECT_LE(s.playback.time(), 6.0);
}

TEST(RideAlong, TheCameraFollowsTheRiderAtTheTimelinesTime) {
  ViewerState s;
  load(s, kRiders);
  const sweep::render::Camera orbit = s.camera;
  viewer::ride_along(s, s.session.id_of(s.doc().find("r1")));
  ASSERT_TRUE(viewer::riding(s));
  expect_same_view(s.camera, expected_ride(s, "r1", 0.0, sweep::render::RideView::Chase));
  EXPECT_EQ(s.camera.lens_shift, s.layout.lens_shift) << "centred in the part the panels leave free";

  s.playback.scrub(1.5, 6.0);
  viewer::follow_rider(s);
  expect_same_view(s.camera, expected_ride(s, "r1", 1.5, sweep::render::RideView::Chase));
  s.ride.view = sweep::render::RideView::FirstPerson;
  viewer::follow_rider(s);
  expect_same_view(s.camera, expected_ride(s, "r1", 1.5, sweep::render::RideView::FirstPerson));

  viewer::stop_riding(s);  // Orbit
  EXPECT_FALSE(viewer::riding(s));
  expect_same_view(s.camera, orbit);
}

TEST(RideAlong, SpaceAndTheFramingKeysGoBackToTheOrbitCamera) {
  ViewerState s;
  sweep::editor::CommandTable commands;
  viewer::bind_commands(commands, s);
  load(s, kRiders);
  const sweep::render::Camera orbit = s.camera;
  for (const sweep::editor::Shortcut key : {sweep::editor::Shortcut{Key::Space}, sweep::editor::Shortcut{Key::Home},
                                            sweep::editor::Shortcut{Key::F}, sweep::editor::Shortcut{Key::Digit1}}) {
    viewer::ride_along(s, s.session.id_of(s.doc().find("r2")));
    ASSERT_TRUE(viewer::riding(s));
    EXPECT_TRUE(commands.press(key)) << sweep::editor::label(key);
    EXPECT_FALSE(viewer::riding(s)) << sweep::editor::label(key);
  }
  viewer::ride_along(s, s.session.id_of(s.doc().find("r2")));
  EXPECT_TRUE(commands.press({Key::Space}));
  expect_same_view(s.camera, orbit);  // reset: the framing the file opened with
}

TEST(RideAlong, AnOrbitDragLeavesTheRideFromWhereTheCameraIs) {
  ViewerState s;
  load(s, kRiders);
  s.camera.projection = sweep::render::Projection::Orthographic;
  viewer::ride_along(s, s.session.id_of(s.doc().find("r1")));
  EXPECT_EQ(s.camera.projection, sweep::render::Projection::Perspective) << "riding is in perspective";
  const sweep::render::Camera riding = s.camera;
  viewer::stop_riding(s, true);
  EXPECT_FALSE(viewer::riding(s));
  expect_same_view(s.camera, riding);
  EXPECT_EQ(s.camera.projection, sweep::render::Projection::Orthographic) << "the orbit camera's projection";
}

TEST(RideAlong, ADeletedRiderOrAnotherFileEndsTheRide) {
  ViewerState s;
  load(s, kRiders);
  const sweep::render::Camera orbit = s.camera;
  viewer::ride_along(s, s.session.id_of(s.doc().find("r2")));
  ASSERT_TRUE(viewer::run_edit(s, "delete", [](sweep::Document& doc) { return sweep::delete_object(doc, 5); }))
      << s.error;
  viewer::follow_rider(s);
  EXPECT_FALSE(viewer::riding(s));
  expect_same_view(s.camera, orbit);

  viewer::ride_along(s, s.session.id_of(s.doc().find("r1")));
  load(s, kRiders);
  EXPECT_FALSE(viewer::riding(s));
}

TEST(RideAlong, EditingThePathOrTheModelMovesTheRiderAndItsCameraLive) {
  ViewerState s;
  load(s, kRiders);
  viewer::ride_along(s, s.session.id_of(s.doc().find("r1")));
  s.playback.scrub(2.0, 6.0);
  viewer::follow_rider(s);
  const int r1 = s.doc().find("r1");
  const std::uint64_t revision = s.session.scene().objects[std::size_t(r1)].revision;
  const glm::dvec3 before = sweep::rider_frame(s.doc(), s.session.scene(), r1, 2.0).V;
  const glm::dvec3 eye = s.camera.eye();
  // The knot's R, as the Edit panel's field changes it.
  ASSERT_TRUE(viewer::run_edit(s, "R", [](sweep::Document& doc) {
    return sweep::set_curve_parameter(doc, 0, sweep::CurveParameter::MajorRadius, 2.5);
  })) << s.error;
  EXPECT_GT(s.session.scene().objects[std::size_t(r1)].revision, revision) << "the rider's track evaluated again";
  const glm::dvec3 after = sweep::rider_frame(s.doc(), s.session.scene(), r1, 2.0).V;
  EXPECT_GT(glm::length(after - before), 0.05) << "it rides the new path";
  viewer::follow_rider(s);
  EXPECT_GT(glm::length(s.camera.eye() - eye), 0.05) << "and the camera with it";

  // The model's cross-section: a bigger body means a bigger radius, so the chase camera backs off.
  const double distance = s.camera.distance;
  ASSERT_TRUE(viewer::run_edit(s, "radius", [](sweep::Document& doc) { return sweep::set_radius(doc, 1, 0.3); }))
      << s.error;
  viewer::follow_rider(s);
  EXPECT_GT(s.camera.distance, distance * 1.1);
}

TEST(RideAlong, AReloadOfTheFileKeepsTheRideAndTheTime) {
  const sweep::test::ScratchFolder dir;
  const std::filesystem::path file = dir.path() / "riders.swp";
  sweep::test::write_text(file, kRiders);
  ViewerState s;
  s.layout = sweep::editor::compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  ASSERT_TRUE(viewer::open_file(s, file.string())) << s.error;
  viewer::ride_along(s, s.session.id_of(s.doc().find("r2")));
  s.playback.scrub(4.0, 6.0);
  s.playback.play();
  // Another program changes the loop to 3 s.
  std::string text = kRiders;
  text.replace(text.rfind("seconds 6"), 9, "seconds 3");
  text.replace(text.find("seconds 6"), 9, "seconds 3");
  sweep::test::write_text(file, text);
  viewer::reload_from_disk(s);
  ASSERT_EQ(sweep::longest_loop(s.doc()), 3.0) << s.error;
  EXPECT_TRUE(viewer::riding(s));
  EXPECT_EQ(s.session.index_of(s.ride.rider), s.doc().find("r2"));
  EXPECT_TRUE(s.playback.playing());
  EXPECT_EQ(s.playback.time(), 3.0) << "kept, within the shorter loop";
}

TEST(RideAlong, TheModelsRadiusIsItsFarthestVertexFromItsOrigin) {
  ViewerState s;
  load(s, kRiders);
  const double radius = sweep::rider_model_radius(s.doc(), s.session.scene(), s.doc().find("r1"));
  // The capped cylinder: radius 0.15, from z = -0.4 to 0.4.
  EXPECT_NEAR(radius, std::sqrt(0.15 * 0.15 + 0.4 * 0.4), 1e-3);
}

}  // namespace
