#include "io/swp_writer.hpp"

#include "io/atomic_file.hpp"
#include "model/clauses.hpp"

#include <charconv>
#include <cmath>

namespace sweep {
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
  for (const SwpClause& clause : swp_clauses(o.kind)) {
    if (clause.flag) {
      if (o.*(clause.flag)) (out += ' ') += clause.key;
      continue;
    }
    if (clause.reference && o.*(clause.reference) >= 0) {
      (out += ' ') += clause.key;
      append_reference(out, doc, o.*(clause.reference));
      continue;
    }
    if (!clause.field) continue;
    const double value = o.*(clause.field);
    if (value == clause.default_value) continue;  // NaN is written, and refused by the reader
    out += ' ';
    out += clause.key;
    append_field(out, value);
  }
}

/// "[x y]" or "[x y z]", one a line; returns the number of lines.
int append_points(std::string& out, const Object& o) {
  const bool planar = is_planar_curve(o.kind);
  for (const auto& p : o.points) {
    out += '[';
    append_number(out, p.x);
    out += ' ';
    append_number(out, p.y);
    if (!planar) append_field(out, p.z);
    out += "]\n";
  }
  return static_cast<int>(o.points.size());
}

/// A mesh's faces, "[i j k]" one a line; returns the number of lines.
int append_faces(std::string& out, const Object& o) {
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
void append_material(std::string& out, const Object& o) {
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

/// The fields after the name, on the keyword's line.
void append_fields(std::string& out, const Document& doc, const Object& o) {
  switch (o.kind) {
    case ObjectKind::Bezier2:
    case ObjectKind::Bezier3:
    case ObjectKind::BSpline2:
    case ObjectKind::BSpline3:
    case ObjectKind::CatmullRom2:
    case ObjectKind::CatmullRom3:
    case ObjectKind::KochanekBartels2:
    case ObjectKind::KochanekBartels3:
      append_field(out, o.steps);
      out += ' ' + std::to_string(o.points.size());
      break;
    case ObjectKind::Polyline2:
    case ObjectKind::Polyline3:
      out += ' ' + std::to_string(o.points.size());
      break;
    case ObjectKind::Circle:
      append_field(out, o.steps);
      append_field(out, o.radius);
      break;
    case ObjectKind::Helix:
      append_field(out, o.steps);
      append_field(out, o.radius);
      append_field(out, o.pitch);
      append_field(out, o.turns);
      break;
    case ObjectKind::TorusKnot:
      append_field(out, o.steps);
      append_field(out, o.knot_p);
      append_field(out, o.knot_q);
      append_field(out, o.major_radius);
      append_field(out, o.radius);
      break;
    case ObjectKind::SurfaceOfRevolution:
      append_field(out, o.steps);
      append_reference(out, doc, o.profile);
      break;
    case ObjectKind::GeneralizedCylinder:
      append_reference(out, doc, o.profile);
      append_reference(out, doc, o.sweep);
      break;
    case ObjectKind::Birail:
      append_reference(out, doc, o.profile);
      append_reference(out, doc, o.sweep);
      append_reference(out, doc, o.rail2);
      break;
    case ObjectKind::BezierPatch:
      append_field(out, o.steps);
      out += ' ' + std::to_string(o.points.size() / 16);
      break;
    case ObjectKind::BSplinePatch:
      append_field(out, o.steps);
      append_field(out, o.rows);
      append_field(out, o.columns);
      break;
    case ObjectKind::PolygonMesh:
      out += ' ' + std::to_string(o.points.size());
      out += ' ' + std::to_string(o.face_sizes.size());
      break;
    case ObjectKind::Subdivision:
      append_field(out, o.steps);
      append_reference(out, doc, o.source);
      break;
    case ObjectKind::Material:
      append_material(out, o);
      break;
  }
}

}  // namespace

std::string write_swp(const Document& doc, std::vector<int>* first_lines) {
  std::string out;
  int line = 1;
  if (first_lines) first_lines->clear();
  for (const Object& o : doc.objects) {
    if (first_lines) first_lines->push_back(line);
    out += keyword(o.kind);
    out += ' ';
    out += o.name.empty() ? std::string(".") : o.name;
    append_fields(out, doc, o);
    append_clauses(out, doc, o);
    out += '\n';
    line += 1 + (has_editable_points(o.kind) ? append_points(out, o) : 0);
    if (o.kind == ObjectKind::PolygonMesh) line += append_faces(out, o);
    out += '\n';  // a blank line between objects
    ++line;
  }
  return out;
}

void save_swp_file(const std::filesystem::path& path, const Document& doc) {
  write_file_atomically(path, write_swp(doc));
}

}  // namespace sweep
