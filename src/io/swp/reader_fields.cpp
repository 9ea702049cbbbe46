// The SWP reader's fixed fields: each kind lists them once (`fields` in model/object.hpp) and
// the visitor here reads them, checking each at its token (see swp/detail/reader.hpp).
#include "io/swp/detail/reader.hpp"

#include "model/caps.hpp"

#include <algorithm>
#include <type_traits>

namespace sweep::io::swp_detail {

/// Reads the fields a kind lists (object.hpp explains each call).
struct Parser::FieldReader {
  Parser& parser;
  Object& object;
  const Document& doc;
  Token last;                 // the token of the field just read
  bool clauses_read = false;  // the kind read its clauses already (before its points)

  void steps(int& steps) {
    steps = parser.read_steps();
    last = parser.steps_token_;
  }

  template <typename Check>
  void check(Check check) {
    parser.require(last, check());
  }

  void number(FieldName name, double& value) { value = parser.read_number({name.role}, &last); }
  template <typename Check>
  void number(FieldName name, double& value, Check problem) {
    number(name, value);
    check(problem);
  }

  void integer(FieldName name, int& value, int low, int high) {
    value = static_cast<int>(parser.read_integer(std::string(name.role), low, high, &last));
  }
  template <typename Check>
  void integer(FieldName name, int& value, int low, int high, Check problem) {
    integer(name, value, low, high);
    check(problem);
  }

  void reference(const char* role, int& index, bool planar_only) {
    last = parser.lexer_.peek();
    if (std::string_view(role) == "profile") parser.profile_token_ = last;
    if (std::string_view(role) == "the second rail") parser.rail2_token_ = last;
    index = parser.read_reference(doc, role, planar_only);
  }

  void samples(std::int64_t samples) { parser.check_samples(samples); }
  void samples_by(std::int64_t samples, const char* field) {
    const std::string cause =
        "STEPS " + std::string(parser.steps_token_.text) + " and " + field + " " + std::string(last.text) + " give";
    if (const auto breach = parser.caps_.add_samples(samples, cause)) parser.fail(last, breach->expected, breach->note);
  }

  void vertices(VerticesAt at) {
    const Token keyword{TokenType::Word, sweep::keyword(object.kind()), object.location.line, object.location.column};
    const ObjectAt object_at = [this](int i) -> const Object& { return doc.objects[static_cast<std::size_t>(i)]; };
    const auto vertices_of = [this](int i) { return parser.vertex_estimates_[static_cast<std::size_t>(i)]; };
    parser.check_mesh(at == VerticesAt::Steps ? parser.steps_token_ : keyword,
                      object_counts(object, object_at, vertices_of).vertices);
  }

  /// A count, its kind's rule and the caps, then the clauses and the points.
  template <typename Kind>
  void points(Kind& kind, const char* what) {
    Token count_token;
    const std::int64_t count = parser.read_integer(what, 0, limits::kMaxControlPoints, &count_token);
    parser.require(count_token, Kind::count_problem(count));
    parser.count_points(count, count_token, "this curve");
    if constexpr (std::is_base_of_v<StepsPart, Kind>) {
      parser.check_samples(Kind::pieces(count) * kind.steps + 1);
    } else {
      parser.check_samples(count, &count_token);
    }
    parser.read_clauses(object, doc, "'[' to start " + point_text(1, count));
    parser.read_points(object, count);
    clauses_read = true;
  }

  void custom(BezierPatchSurface&) { clauses_read = true, parser.read_bezier_patch(object, doc); }
  void custom(BSplinePatchSurface&) { clauses_read = true, parser.read_bspline_patch(object, doc); }
  void custom(PolygonMeshSurface&) { clauses_read = true, parser.read_polygon_mesh(object, doc); }
  void custom(SubdivisionSurface&) { parser.read_subdivision(object, doc); }
  void custom(MaterialLook&) { clauses_read = true, parser.read_material(object); }  // its own clauses
  void custom(RiderObject& rider) { rider.model = parser.read_model_reference(doc); }
};

void Parser::read_fields(Object& object, const Document& doc) {
  FieldReader reader{*this, object, doc, {}};
  std::visit([&reader](auto& kind) { std::decay_t<decltype(kind)>::fields(kind, reader); }, object.data);
  if (reader.clauses_read) return;
  read_clauses(object, doc, expected_keyword());
  if (is_surface(object.kind())) check_curves(object, doc);
  if (object.kind() == ObjectKind::Subdivision) check_subdivision(object, doc);
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

}  // namespace sweep::io::swp_detail
