#pragma once
// The viewer's camera: an orbit around a target with arcball rotation, zoom, pan, framing and
// preset views. Plain maths on GLM with no GL, so it is unit-tested without a context.
#include "model/evaluation/riders.hpp"
#include "model/evaluation/scene.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>

namespace sweep::render {

/// An axis-aligned box; empty until something is added.
struct Bounds {
  glm::dvec3 min{std::numeric_limits<double>::infinity()};
  glm::dvec3 max{-std::numeric_limits<double>::infinity()};

  bool empty() const { return min.x > max.x; }
  void add(const glm::dvec3& point);
  void add(const Bounds& other);
  glm::dvec3 center() const;
  /// Half the diagonal: the radius of a sphere around center() holding the box. 0 when empty.
  double radius() const;
};

/// Bounds of every curve sample and mesh vertex of the objects i with visible(i) true
/// (all objects when `visible` is empty). Non-finite points are skipped.
Bounds scene_bounds(const Scene& scene, const std::vector<bool>& visible = {});

enum class Projection { Perspective, Orthographic };
enum class ViewPreset { Front, Top, Side };

/// Orbit camera. The eye sits at target + orientation * (0, 0, distance) looking at target;
/// orientation maps camera axes (x right, y up, -z forward) to world axes and is kept a unit
/// quaternion, so the view basis stays orthonormal however many drags it sees.
class Camera {
 public:
  /// Default yaw and pitch (degrees) used by reset() and by `sweep render` without --yaw/--pitch.
  static constexpr double kDefaultYaw = 30.0;
  static constexpr double kDefaultPitch = 20.0;

  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 target{0.0};
  double distance = 5.0;
  double scene_radius = 1.0;  // sets the near and far planes
  double vertical_fov = glm::radians(40.0);
  Projection projection = Projection::Perspective;
  /// Moves the picture's centre by this much in normalized device coordinates (x right, y up),
  /// so the scene can be centred in the part of a window that a side panel leaves free.
  glm::dvec2 lens_shift{0.0};

  /// Orbit angles in degrees: yaw turns about +y (positive moves the eye towards +x),
  /// pitch lifts the eye above the xz-plane (90 looks straight down).
  void set_yaw_pitch(double yaw_degrees, double pitch_degrees);
  /// Front looks along -z (the xy-plane of planar curves faces the viewer), top along -y,
  /// side along -x.
  void set_view(ViewPreset preset);
  /// Centres `bounds` and moves back until its bounding sphere fits the view at `aspect`
  /// (width / height, > 0), or a part of it `height_share` (in (0, 1]) of its height high,
  /// as wide as `aspect` times the whole height (the part lens_shift centres the picture in).
  /// An empty box frames the unit sphere at the origin.
  void frame(const Bounds& bounds, double aspect, double height_share = 1.0);
  /// Default orientation (kDefaultYaw, kDefaultPitch), then frame(bounds, aspect, height_share).
  void reset(const Bounds& bounds, double aspect, double height_share = 1.0);

  /// Arcball rotation for a drag from `from` to `to`, both in arcball coordinates (the
  /// viewport mapped so its inscribed circle is the unit circle, y up; see arcball_point()).
  /// The scene turns with the pointer.
  void arcball_rotate(const glm::dvec2& from, const glm::dvec2& to);
  /// Multiplies the distance (and the orthographic extent) by factor > 0.
  void zoom(double factor);
  /// Moves the target by `delta` in arcball coordinates so the scene follows the pointer.
  void pan(const glm::dvec2& delta);

  glm::dvec3 eye() const;
  glm::dvec3 right() const;
  glm::dvec3 up() const;
  glm::dvec3 forward() const;
  glm::dmat4 view_matrix() const;
  /// Looks from `eye` at `target` (apart) with `up` (not along the view) pointing up in the picture.
  void look_at(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);
  /// Perspective or orthographic projection for a viewport of this aspect (width / height).
  glm::dmat4 projection_matrix(double aspect) const;
  /// Half the height of the view at the target's depth; the orthographic extent.
  double half_height_at_target() const;
};

/// How a camera rides along with a rider: from behind and above it looking along its way (chase),
/// or from its own place (first person).
enum class RideView : std::uint8_t { Chase, FirstPerson };

/// Places `camera` with a rider whose frame is `frame` (model +x, +y, +z along N, B, T) and whose
/// model has the size `size` (model/evaluation/riders.hpp). Chase: 3 radii behind along -T looking 2 radii
/// ahead from 1.2 radii above along B; for a rider with a train close behind it, from above the
/// train (the model's top plus 1.5 radii, at least 2.4 radii) looking 4 radii ahead, so the next
/// car does not fill the picture and the track ahead shows. First person: from just above the
/// model's top (plus a tenth of its radius), looking along T. Up is B, so the camera rolls with
/// the rider (with `up`, riders stay upright). Precondition: frame orthonormal, size.radius > 0.
void ride_camera(Camera& camera, const Frame& frame, const RiderSize& size, RideView view);

/// Maps a pointer position in pixels (origin top left) in a viewport of `size` pixels to
/// arcball coordinates: centre (0, 0), y up, the inscribed circle of the viewport has radius 1.
glm::dvec2 arcball_point(const glm::dvec2& pixel, const glm::dvec2& size);

}  // namespace sweep::render
