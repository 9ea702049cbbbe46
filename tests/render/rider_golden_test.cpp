// The showcase riders in pictures (looked at before committing; regenerate with
// SWEEP_UPDATE_GOLDEN=1): the roller coaster's train from the orbit camera and riding along with
// its last car, and the airplane chased along its knot, each at a fixed time.
#include "golden_support.hpp"
#include "model/evaluation/riders.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep::test {
namespace {

/// The scene at `time` seconds from the golden camera, or riding along with rider `ride` (chase).
render::Image picture_at(const LoadedScene& loaded, double time, const std::string& ride = {}) {
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene, loaded.folder);
  render::add_riders(list, loaded.doc, loaded.scene, time);
  render::Camera camera = golden_camera(loaded.scene);
  if (!ride.empty()) {
    const int index = loaded.doc.find(ride);
    render::ride_camera(camera, rider_frame(loaded.doc, loaded.scene, index, time),
                        rider_size(loaded.doc, loaded.scene, index), render::RideView::Chase);
  }
  render::DisplaySettings settings = settings_for(GoldenMode::Smooth);
  settings.curves = render::CurveMode::Off;
  return shared_renderer().render(list, camera, {kGoldenWidth, kGoldenHeight}, settings);
}

TEST(RiderGolden, RollerCoasterTrainAtThreeSeconds) {
  const LoadedScene loaded = load_starter("artifacts/roller-coaster");
  EXPECT_TRUE(matches_golden(picture_at(loaded, 3.0), "artifact-roller-coaster", limits_for(GoldenMode::Smooth)));
}

TEST(RiderGolden, RollerCoasterRiddenAlongWithTheLeadCar) {
  const LoadedScene loaded = load_starter("artifacts/roller-coaster");
  // The first rider, the lead car (issue 47): the chase camera looks over the train behind it at
  // the track ahead, not from inside the next car.
  EXPECT_TRUE(matches_golden(picture_at(loaded, 3.0, "car1-body"), "artifact-roller-coaster-ride",
                             limits_for(GoldenMode::Smooth)));
}

TEST(RiderGolden, AirplaneChasedAlongItsKnot) {
  // From the orbit camera the plane is a few pixels on its knot: chase it, the trail ahead.
  const LoadedScene loaded = load_starter("artifacts/airplane");
  EXPECT_TRUE(
      matches_golden(picture_at(loaded, 2.0, "plane-fuselage"), "artifact-airplane", limits_for(GoldenMode::Smooth)));
}

}  // namespace
}  // namespace sweep::test
