#include "io/swp/write.hpp"

#include "io/files/atomic_file.hpp"
#include "model/clauses.hpp"

#include <charconv>
#include <cmath>

namespace sweep::io {
namespace {

void append_number(std::string& out, double value) {
  char buf[32];
  // Shortest form that reads back to the same double.
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

/// ' ' and the number.
void append_field(std::string& out, double value) {
  out += ' ';
  append_number(out, value);
}

void append_field(std::string& out, int value) {
  out += ' ';
  out += std::to_string(value);
}

void append_reference(std::string& out, const Document& doc, int index) {
  out += ' ';
  if (index < 0 || static_cast<std::size_t>(index) >= doc.objects.size() ||
      doc.objects[static_cast<std::size_t>(index)].name.empty()) {
    out += '.';  // not a valid reference; the reader says so
  } else {
    out += doc.objects[static_cast<std::size_t>(index)].name;
  }
}

/// The optional clauses that differ from their defaults, on the line of the fixed fields: a
/// document without them is written exactly as before clauses existed.
void append_clauses(std::string& out, const Document& doc, const Object& o) {
  for (const SwpClause& clause : swp_clauses(o.kind())) {
    if (clause.flag) {
      if (clause_flag(clause, o)) (out += ' ') += clause.key;
      continue;
    }
    if (clause.reference && clause_reference(clause, o) >= 0) {
      (out += ' ') += clause.key;
      append_reference(out, doc, clause_reference(clause, o));
      continue;
    }
    if (clause.vector) {
      const glm::dvec3 value = *clause.vector(const_cast<Object&>(o));
      if (value == glm::dvec3(0.0)) continue;
      (out += ' ') += clause.key;
      for (int axis = 0; axis < 3; ++axis) append_field(out, value[axis]);
      continue;
    }
    if (!clause.field) continue;
    const double value = clause_number(clause, o);
    if (value == clause.default_value) continue;  // NaN is written, and refused by the reader
    out += ' ';
    out += clause.key;
    append_field(out, value);
  }
}

/// "[x y]" or "[x y z]", one a line; returns the number of lines.
int append_points(std::string& out, const Object& o) {
  const bool planar = is_planar_curve(o.kind());
  const std::span<const glm::dvec3> points = points_of(o);
  for (const auto& p : points) {
    out += '[';
    append_number(out, p.x);
    out += ' ';
    append_number(out, p.y);
    if (!planar) append_field(out, p.z);
    out += "]\n";
  }
  return static_cast<int>(points.size());
}

/// A mesh's faces, "[i j k]" one a line; returns the number of lines.
int append_faces(std::string& out, const PolygonMeshSurface& o) {
  std::size_t corner = 0;
  for (const int size : o.face_sizes) {
    out += '[';
    for (int k = 0; k < size && corner < o.face_vertices.size(); ++k, ++corner) {
      if (k > 0) out += ' ';
      out += std::to_string(o.face_vertices[corner]);
    }
    out += "]\n";
  }
  return static_cast<int>(o.face_sizes.size());
}

/// A material's clauses that differ from the defaults (material.hpp), in the reader's order.
void append_material(std::string& out, const MaterialLook& o) {
  if (o.color != glm::dvec3(kDefaultColor[0], kDefaultColor[1], kDefaultColor[2])) {
    out += " color";
    for (int c = 0; c < 3; ++c) append_field(out, o.color[c]);
  }
  if (o.shininess != kDefaultShininess) {
    out += " shininess";
    append_field(out, o.shininess);
  }
  if (!o.texture.empty()) (out += " texture ") += o.texture;
  if (o.checker > 0) {
    out += " checker";
    append_field(out, o.checker);
  }
  if (!o.bump.empty()) {
    (out += " bump ") += o.bump;
    append_field(out, o.bump_height);
  }
}

/// The fields after the name, on the keyword's line, as each kind lists them (`fields`,
/// object.hpp); the checks and counts the reader makes of them write nothing.
struct FieldWriter {
  std::string& out;
  const Document& doc;

  void count(std::size_t n) { out += ' ' + std::to_string(n); }

  void steps(int steps) { append_field(out, steps); }
  void number(FieldName, double value, auto&&...) { append_field(out, value); }
  void integer(FieldName, int value, int, int, auto&&...) { append_field(out, value); }
  void reference(const char*, int index, bool) { append_reference(out, doc, index); }
  void points(const auto& kind, const char*) { count(kind.points.size()); }
  void samples(std::int64_t) {}
  void samples_by(std::int64_t, const char*) {}
  void vertices(VerticesAt) {}

  void custom(const BezierPatchSurface& s) {
    append_field(out, s.steps);
    count(s.points.size() / 16);
  }
  void custom(const BSplinePatchSurface& s) {
    append_field(out, s.steps);
    append_field(out, s.rows);
    append_field(out, s.columns);
  }
  void custom(const PolygonMeshSurface& s) {
    count(s.points.size());
    count(s.face_sizes.size());
  }
  void custom(const SubdivisionSurface& s) {
    append_field(out, s.levels);
    append_reference(out, doc, s.source);
  }
  void custom(const MaterialLook& m) { append_material(out, m); }
  void custom(const RiderObject& r) { append_reference(out, doc, r.model); }
};

/// Appends the object's lines (each ending in '\n'); returns how many.
int append_object(std::string& out, const Document& doc, const Object& o) {
  out += keyword(o.kind());
  out += ' ';
  out += o.name.empty() ? std::string(".") : o.name;
  FieldWriter writer{out, doc};
  std::visit([&writer](const auto& kind) { std::decay_t<decltype(kind)>::fields(kind, writer); }, o.data);
  append_clauses(out, doc, o);
  out += '\n';
  int lines = 1 + (has_editable_points(o.kind()) ? append_points(out, o) : 0);
  if (const auto* cage = o.find<PolygonMeshSurface>()) lines += append_faces(out, *cage);
  return lines;
}

}  // namespace

std::string object_text(const Document& doc, const Object& object) {
  std::string out;
  append_object(out, doc, object);
  return out;
}

std::string write_swp(const Document& doc, std::vector<int>* first_lines) {
  std::string out;
  int line = 1;
  if (first_lines) first_lines->clear();
  for (const Object& o : doc.objects) {
    if (first_lines) first_lines->push_back(line);
    line += append_object(out, doc, o);
    out += '\n';  // a blank line between objects
    ++line;
  }
  return out;
}

void save_swp_file(const std::filesystem::path& path, const Document& doc, NewDocumentNumbers numbers) {
  if (doc.source.text) {
    write_file_atomically(path, write_swp_preserving(doc));
  } else {
    write_file_atomically(path, numbers == NewDocumentNumbers::Rounded ? write_swp_rounded(doc) : write_swp(doc));
  }
}

}  // namespace sweep::io
