// The SWP reader's curve kinds: control-point curves and their points, circles, helices, torus
// knots (see swp_reader.hpp).
#include "io/swp_reader.hpp"

#include "geometry/helix.hpp"
#include "geometry/limits.hpp"
#include "model/curve_parameters.hpp"

#include <algorithm>
#include <cmath>

namespace sweep::swp_detail {

void Parser::read_control_point_curve(Object& object, const Document& doc) {
  object.as<StepsPart>().steps = read_steps();
  Token count_token;
  const std::int64_t count = read_integer("a control point count", 0, limits::kMaxControlPoints, &count_token);
  check_point_count(object.kind(), count, count_token);
  count_points(count, count_token, "this curve");
  check_samples(piece_count(object.kind(), count) * object.as<StepsPart>().steps + 1);
  read_clauses(object, doc, "'[' to start " + point_text(1, count));
  read_points(object, count);
}

void Parser::read_polyline(Object& object, const Document& doc) {
  Token count_token;
  const std::int64_t count = read_integer("a point count", 0, limits::kMaxControlPoints, &count_token);
  check_point_count(object.kind(), count, count_token);
  count_points(count, count_token, "this curve");
  check_samples(count, &count_token);
  read_clauses(object, doc, "'[' to start " + point_text(1, count));
  read_points(object, count);
}

void Parser::check_point_count(ObjectKind kind, std::int64_t count, const Token& count_token) {
  if (kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3) {
    if (count < 4 || (count - 1) % 3 != 0)
      fail(count_token, "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)");
  } else if (is_interpolating(kind)) {
    if (count < kMinInterpolatingPoints) {
      fail(count_token, "expected at least " + std::to_string(kMinInterpolatingPoints) + " " + spline_family(kind) +
                            " control points");
    }
  } else if (count < 4) {
    fail(count_token, "expected at least 4 B-spline control points");
  }
}

void Parser::read_points(Object& object, std::int64_t count) {
  const bool planar = is_planar_curve(object.kind());
  // Reserve no more than the rest of the file could hold ("[0 0]" is 5 bytes), so a huge count in
  // a short file costs nothing.
  std::vector<glm::dvec3>& points = object.as<PointsPart>().points;
  points.reserve(
      static_cast<std::size_t>(std::min<std::int64_t>(count, static_cast<std::int64_t>(lexer_.remaining() / 5 + 1))));
  for (std::int64_t i = 0; i < count; ++i) {
    const Token open = lexer_.next();
    if (open.type != TokenType::Open) fail(open, "expected '[' to start " + point_text(i + 1, count));
    glm::dvec3 p{0.0};
    p.x = read_number({"x", i + 1, count});
    p.y = read_number({"y", i + 1, count});
    if (!planar) p.z = read_number({"z", i + 1, count});
    const Token close = lexer_.next();
    if (close.type != TokenType::Close) {
      fail(close, "expected ']' to end " + point_text(i + 1, count) +
                      (planar ? " (2D points have 2 coordinates)" : " (3D points have 3 coordinates)"));
    }
    points.push_back(p);
  }
}

void Parser::read_circle(Object& object) {
  CircleCurve& circle = object.as<CircleCurve>();
  circle.steps = read_steps();
  check_samples(std::int64_t{circle.steps} + 1);
  Token radius_token;
  circle.radius = read_number({"radius"}, &radius_token);
  require(radius_token, check_radius(circle.radius));
}

void Parser::read_helix(Object& object) {
  HelixCurve& helix = object.as<HelixCurve>();
  helix.steps = read_steps();
  Token token;
  helix.radius = read_number({"radius"}, &token);
  require(token, check_radius(helix.radius));
  helix.pitch = read_number({"pitch"});
  helix.turns = read_number({"turns"}, &token);
  require(token, check_turns(helix.turns));
  // ceil(STEPS * TURNS) + 1: TURNS is what makes a helix long, so the error is there. Both
  // are capped (1e5, 1e12), so the product is far from the end of int64.
  const auto samples = static_cast<std::int64_t>(std::ceil(helix.steps * helix.turns)) + 1;
  const std::string cause =
      "STEPS " + std::string(steps_token_.text) + " and TURNS " + std::string(token.text) + " give";
  if (const auto breach = caps_.add_samples(samples, cause)) fail(token, breach->expected, breach->note);
}

void Parser::read_torus_knot(Object& object) {
  TorusKnotCurve& knot = object.as<TorusKnotCurve>();
  knot.steps = read_steps();
  check_samples(std::int64_t{knot.steps} + 1);
  knot.knot_p = static_cast<int>(read_integer("P", 1, kMaxKnotWinding));
  Token token;
  knot.knot_q = static_cast<int>(read_integer("Q", 1, kMaxKnotWinding, &token));
  require(token, check_knot_pq(knot.knot_p, knot.knot_q));
  knot.major_radius = read_number({"torus radius R"});
  knot.radius = read_number({"tube radius r"}, &token);
  require(token, check_knot_radii(knot.major_radius, knot.radius));
}

}  // namespace sweep::swp_detail
