// Camera maths without GL: the view basis stays orthonormal under any number of arcball drags,
// framing puts the whole scene in view, presets look where they say.
#include "render/camera.hpp"
#include "render/display_settings.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_access.hpp>

#include <array>
#include <cmath>

namespace sweep::render {
namespace {

void expect_orthonormal(const Camera& camera, double tolerance) {
  const glm::dvec3 r = camera.right();
  const glm::dvec3 u = camera.up();
  const glm::dvec3 f = camera.forward();
  EXPECT_NEAR(glm::length(r), 1.0, tolerance);
  EXPECT_NEAR(glm::length(u), 1.0, tolerance);
  EXPECT_NEAR(glm::length(f), 1.0, tolerance);
  EXPECT_NEAR(glm::dot(r, u), 0.0, tolerance);
  EXPECT_NEAR(glm::dot(r, f), 0.0, tolerance);
  EXPECT_NEAR(glm::dot(u, f), 0.0, tolerance);
  // Right-handed: right x up = -forward (the camera looks down its -z).
  EXPECT_NEAR(glm::length(glm::cross(r, u) + f), 0.0, tolerance);
}

std::array<glm::dvec3, 8> corners(const Bounds& b) {
  return {glm::dvec3{b.min.x, b.min.y, b.min.z}, {b.max.x, b.min.y, b.min.z}, {b.min.x, b.max.y, b.min.z},
          {b.max.x, b.max.y, b.min.z},           {b.min.x, b.min.y, b.max.z}, {b.max.x, b.min.y, b.max.z},
          {b.min.x, b.max.y, b.max.z},           {b.max.x, b.max.y, b.max.z}};
}

/// Every corner of the box projects inside the viewport and the depth range.
void expect_in_view(const Camera& camera, const Bounds& bounds, double aspect) {
  const glm::dmat4 clip = camera.projection_matrix(aspect) * camera.view_matrix();
  for (const glm::dvec3& corner : corners(bounds)) {
    const glm::dvec4 p = clip * glm::dvec4(corner, 1.0);
    ASSERT_GT(p.w, 0.0);
    const glm::dvec3 ndc = glm::dvec3(p) / p.w;
    EXPECT_LE(std::abs(ndc.x), 1.0) << "x of corner " << corner.x << " " << corner.y << " " << corner.z;
    EXPECT_LE(std::abs(ndc.y), 1.0) << "y";
    EXPECT_LE(std::abs(ndc.z), 1.0) << "depth";
  }
}

Bounds box(glm::dvec3 min, glm::dvec3 max) {
  Bounds b;
  b.add(min);
  b.add(max);
  return b;
}

TEST(Camera, ArcballKeepsAnOrthonormalBasisAfterManyDrags) {
  Camera camera;
  camera.reset(box({-1, -1, -1}, {1, 1, 1}), 1.5);
  // Ten thousand small drags in varied directions, some starting outside the ball.
  for (int i = 0; i < 10000; ++i) {
    const double a = 0.37 * i;
    const glm::dvec2 from{0.9 * std::cos(a), 0.7 * std::sin(1.3 * a)};
    const glm::dvec2 to = from + glm::dvec2{0.02 * std::cos(2.1 * a), 0.03 * std::sin(a)};
    camera.arcball_rotate(from, to);
  }
  expect_orthonormal(camera, 1e-9);
  EXPECT_NEAR(glm::length(camera.orientation), 1.0, 1e-12);
  EXPECT_TRUE(std::isfinite(camera.eye().x) && std::isfinite(camera.eye().y) && std::isfinite(camera.eye().z));
  EXPECT_NEAR(glm::length(camera.eye() - camera.target), camera.distance, 1e-9);
}

TEST(Camera, ArcballDragThereAndBackReturns) {
  Camera camera;
  camera.set_yaw_pitch(20.0, 10.0);
  const glm::dquat start = camera.orientation;
  camera.arcball_rotate({0.1, 0.2}, {0.5, -0.3});
  camera.arcball_rotate({0.5, -0.3}, {0.1, 0.2});
  EXPECT_NEAR(std::abs(glm::dot(camera.orientation, start)), 1.0, 1e-12);
}

TEST(Camera, HorizontalDragTurnsAboutTheScreenVertical) {
  // A horizontal drag through the centre turns about the camera's up axis: up does not change.
  Camera camera;
  camera.set_yaw_pitch(0.0, 0.0);
  const glm::dvec3 up = camera.up();
  camera.arcball_rotate({-0.3, 0.0}, {0.3, 0.0});
  EXPECT_NEAR(glm::length(camera.up() - up), 0.0, 1e-12);
  // The scene follows the pointer to the right: the eye moves to the scene's left (-x).
  EXPECT_LT(camera.eye().x, 0.0);
}

TEST(Camera, UpStaysUprightForYawAndPitch) {
  Camera camera;
  for (double yaw = -180.0; yaw <= 180.0; yaw += 15.0) {
    for (double pitch = -85.0; pitch <= 85.0; pitch += 17.0) {
      camera.set_yaw_pitch(yaw, pitch);
      expect_orthonormal(camera, 1e-12);
      EXPECT_NEAR(camera.right().y, 0.0, 1e-12);  // no roll
      EXPECT_GT(camera.up().y, 0.0);
    }
  }
}

TEST(Camera, FramingFitsTheBoundsInView) {
  const std::array<Bounds, 4> scenes = {box({-1, -1, -1}, {1, 1, 1}), box({10, 0, -3}, {40, 2, 3}),
                                        box({-0.001, -5, 0}, {0.001, 5, 0}), box({0, 0, 0}, {1e6, 1e6, 1e6})};
  for (const Bounds& bounds : scenes) {
    for (double aspect : {0.5, 1.0, 4.0 / 3.0, 2.5}) {
      for (auto projection : {Projection::Perspective, Projection::Orthographic}) {
        Camera camera;
        camera.projection = projection;
        camera.reset(bounds, aspect);
        expect_in_view(camera, bounds, aspect);
        for (int i = 0; i < 20; ++i) camera.arcball_rotate({0.0, 0.0}, {0.2, 0.15});
        expect_in_view(camera, bounds, aspect);  // rotating about the centre keeps it in view
      }
    }
  }
}

TEST(Camera, FramingFitsTheBoundsInThePartThePanelsAndStatusBarLeaveFree) {
  // A window W x H whose panels cover `left` and `right` of its width and a status bar `bottom`
  // of its height (shares): the renderer projects for the whole window, shifted by lens_shift.
  struct Window {
    double aspect, left, right, bottom;
  };
  const std::array<Bounds, 3> scenes = {box({-1, -1, -1}, {1, 1, 1}), box({10, 0, -3}, {40, 2, 3}),
                                        box({-0.001, -5, 0}, {0.001, 5, 0})};
  for (const Window w : {Window{1.6, 0.29, 0.28, 0.0275}, Window{1.0, 0.4, 0.2, 0.1}, Window{2.5, 0.1, 0.1, 0.05}}) {
    const double free_width = 1.0 - w.left - w.right;
    for (const Bounds& bounds : scenes) {
      for (auto projection : {Projection::Perspective, Projection::Orthographic}) {
        Camera camera;
        camera.projection = projection;
        camera.lens_shift = {w.left - w.right, w.bottom};
        camera.reset(bounds, free_width * w.aspect, 1.0 - w.bottom);
        const glm::dmat4 clip = camera.projection_matrix(w.aspect) * camera.view_matrix();
        const auto ndc = [&](const glm::dvec3& p) {
          const glm::dvec4 c = clip * glm::dvec4(p, 1.0);
          return glm::dvec2(c) / c.w;
        };
        // The free part in normalized device coordinates: x from -1 + 2 left to 1 - 2 right,
        // y from -1 + 2 bottom to 1.
        for (const glm::dvec3& corner : corners(bounds)) {
          const glm::dvec2 q = ndc(corner);
          EXPECT_GE(q.x, -1.0 + 2.0 * w.left - 1e-9);
          EXPECT_LE(q.x, 1.0 - 2.0 * w.right + 1e-9);
          EXPECT_GE(q.y, -1.0 + 2.0 * w.bottom - 1e-9);
          EXPECT_LE(q.y, 1.0 + 1e-9);
        }
        const glm::dvec2 centre = ndc(bounds.center());
        EXPECT_NEAR(centre.x, w.left - w.right, 1e-9) << "centred between the panels";
        EXPECT_NEAR(centre.y, w.bottom, 1e-9) << "centred above the status bar";
      }
    }
  }
}

TEST(Camera, FramingIsTight) {
  // The bounding sphere touches the narrower side, with a small margin: not lost in the distance.
  Camera camera;
  const Bounds bounds = box({-1, -1, -1}, {1, 1, 1});
  camera.reset(bounds, 1.0);
  const double half_angle = 0.5 * camera.vertical_fov;
  EXPECT_NEAR(camera.distance * std::sin(half_angle), bounds.radius() * 1.05, 1e-9);
  EXPECT_NEAR(glm::length(camera.target - bounds.center()), 0.0, 1e-12);
}

TEST(Camera, EmptyBoundsFrameTheUnitSphere) {
  Camera camera;
  camera.reset(Bounds{}, 1.0);
  EXPECT_TRUE(std::isfinite(camera.distance));
  EXPECT_GT(camera.distance, 1.0);
  EXPECT_EQ(camera.target, glm::dvec3(0.0));
}

TEST(Camera, PresetsLookAlongTheirAxes) {
  Camera camera;
  camera.set_view(ViewPreset::Front);
  EXPECT_NEAR(glm::length(camera.forward() - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(camera.up() - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
  camera.set_view(ViewPreset::Top);
  EXPECT_NEAR(glm::length(camera.forward() - glm::dvec3(0, -1, 0)), 0.0, 1e-12);
  camera.set_view(ViewPreset::Side);
  EXPECT_NEAR(glm::length(camera.forward() - glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(camera.up() - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
}

TEST(Camera, ZoomAndPan) {
  Camera camera;
  camera.reset(box({-1, -1, -1}, {1, 1, 1}), 1.0);
  const double d = camera.distance;
  camera.zoom(0.5);
  EXPECT_NEAR(camera.distance, 0.5 * d, 1e-12);
  camera.zoom(-1.0);  // ignored
  camera.zoom(std::nan(""));
  EXPECT_NEAR(camera.distance, 0.5 * d, 1e-12);
  const glm::dvec3 target = camera.target;
  camera.pan({0.5, 0.0});
  // The scene follows the pointer right, so the target moves left along the camera's right.
  EXPECT_LT(glm::dot(camera.target - target, camera.right()), 0.0);
  EXPECT_NEAR(glm::dot(camera.target - target, camera.up()), 0.0, 1e-12);
}

TEST(Camera, ArcballPointMapsTheInscribedCircle) {
  const glm::dvec2 size{800, 600};
  EXPECT_EQ(arcball_point({400, 300}, size), glm::dvec2(0, 0));
  EXPECT_EQ(arcball_point({400, 0}, size), glm::dvec2(0, 1));  // top edge: y up
  EXPECT_EQ(arcball_point({700, 300}, size), glm::dvec2(1, 0));
}

TEST(Camera, SceneBoundsSkipHiddenAndNonFinite) {
  Scene scene;
  scene.objects.resize(2);
  scene.objects[0].curve.frames.resize(2);
  scene.objects[0].curve.frames[0].V = {1, 2, 3};
  scene.objects[0].curve.frames[1].V = {std::nan(""), 0, 0};
  scene.objects[1].mesh.positions = {glm::vec3(-5.0f), glm::vec3(5.0f)};
  const Bounds all = scene_bounds(scene);
  EXPECT_EQ(all.min, glm::dvec3(-5.0));
  const Bounds first = scene_bounds(scene, {true, false});
  EXPECT_EQ(first.min, glm::dvec3(1, 2, 3));
  EXPECT_EQ(first.max, glm::dvec3(1, 2, 3));
}

/// A frame turned off the axes, at an arbitrary place: T, N, B orthonormal and right-handed.
Frame tilted_frame() {
  Frame f;
  f.V = {1.5, -0.5, 2.0};
  f.T = glm::normalize(glm::dvec3(1.0, 2.0, 2.0));
  f.N = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), f.T));
  f.B = glm::cross(f.T, f.N);
  return f;
}

TEST(RideCamera, ChaseSitsBehindAlongMinusTAndAboveAlongBLookingAhead) {
  const Frame f = tilted_frame();
  const double r = 0.4;
  Camera camera;
  camera.lens_shift = {0.3, 0.1};
  ride_camera(camera, f, RiderSize{r, 0.2, false}, RideView::Chase);
  const glm::dvec3 offset = camera.eye() - f.V;
  EXPECT_NEAR(glm::dot(offset, f.T), -3.0 * r, 1e-9) << "3 radii behind";
  EXPECT_NEAR(glm::dot(offset, f.B), 1.2 * r, 1e-9) << "1.2 radii above";
  EXPECT_NEAR(glm::dot(offset, f.N), 0.0, 1e-9) << "not to a side";
  EXPECT_NEAR(glm::length(camera.target - (f.V + 2.0 * r * f.T)), 0.0, 1e-9) << "looking 2 radii ahead";
  EXPECT_GT(glm::dot(camera.forward(), f.T), 0.9) << "looking along the way";
  EXPECT_GT(glm::dot(camera.up(), f.B), 0.9) << "B up in the picture";
  EXPECT_NEAR(glm::dot(camera.right(), f.B), 0.0, 1e-9) << "no roll against B";
  EXPECT_EQ(camera.lens_shift, glm::dvec2(0.0));
  expect_orthonormal(camera, 1e-9);
}

TEST(RideCamera, WithATrainBehindTheChaseLooksFromAboveItFurtherAhead) {
  const Frame f = tilted_frame();
  const double r = 0.4;
  Camera camera;
  ride_camera(camera, f, RiderSize{r, 0.3, true}, RideView::Chase);
  const glm::dvec3 offset = camera.eye() - f.V;
  EXPECT_NEAR(glm::dot(offset, f.T), -3.0 * r, 1e-9) << "3 radii behind";
  EXPECT_NEAR(glm::dot(offset, f.B), 2.4 * r, 1e-9) << "above the next car: 2.4 radii (top + 1.5 r is less)";
  EXPECT_NEAR(glm::length(camera.target - (f.V + 4.0 * r * f.T)), 0.0, 1e-9) << "looking 4 radii ahead";
  ride_camera(camera, f, RiderSize{r, 0.4, true}, RideView::Chase);
  EXPECT_NEAR(glm::dot(camera.eye() - f.V, f.B), 0.4 + 1.5 * r, 1e-9) << "a tall model: its top + 1.5 radii";
}

TEST(RideCamera, FirstPersonLooksAlongTFromJustAboveTheRider) {
  const Frame f = tilted_frame();
  const double r = 0.4;
  Camera camera;
  ride_camera(camera, f, RiderSize{r, 0.25, false}, RideView::FirstPerson);
  EXPECT_NEAR(glm::length(camera.forward() - f.T), 0.0, 1e-9) << "forward is T";
  EXPECT_NEAR(glm::length(camera.up() - f.B), 0.0, 1e-9) << "up is B";
  EXPECT_NEAR(glm::length(camera.right() + f.N), 0.0, 1e-9) << "so right is T x B = -N";
  EXPECT_NEAR(glm::length(camera.eye() - (f.V + (0.25 + 0.1 * r) * f.B)), 0.0, 1e-9)
      << "a tenth of a radius above the model's top, not inside it";
  expect_orthonormal(camera, 1e-9);
}

TEST(RideCamera, TheDistanceScalesWithTheModel) {
  const Frame f = tilted_frame();
  Camera small;
  Camera big;
  ride_camera(small, f, RiderSize{0.1, 0.05, false}, RideView::Chase);
  ride_camera(big, f, RiderSize{1.0, 0.5, false}, RideView::Chase);
  EXPECT_NEAR(big.distance, 10.0 * small.distance, 1e-9);
}

TEST(DisplaySettings, ModesCycleAndParse) {
  EXPECT_EQ(next(SurfaceMode::Smooth), SurfaceMode::Wireframe);
  EXPECT_EQ(next(SurfaceMode::Wireframe), SurfaceMode::Off);
  EXPECT_EQ(next(SurfaceMode::Off), SurfaceMode::Smooth);
  EXPECT_EQ(next(CurveMode::Curves), CurveMode::Frames);
  EXPECT_EQ(next(CurveMode::Frames), CurveMode::Off);
  EXPECT_EQ(next(CurveMode::Off), CurveMode::Curves);
  EXPECT_EQ(surface_mode_from_name("wire"), SurfaceMode::Wireframe);
  EXPECT_EQ(curve_mode_from_name("frames"), CurveMode::Frames);
  EXPECT_FALSE(surface_mode_from_name("shiny").has_value());
}

}  // namespace
}  // namespace sweep::render
