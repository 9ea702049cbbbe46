#include "core/swp_writer.hpp"

#include "core/atomic_file.hpp"

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

void append_reference(std::string& out, const Document& doc, int index) {
  out += ' ';
  if (index < 0 || static_cast<std::size_t>(index) >= doc.objects.size() ||
      doc.objects[static_cast<std::size_t>(index)].name.empty()) {
    out += '.';  // not a valid reference; the reader says so
  } else {
    out += doc.objects[static_cast<std::size_t>(index)].name;
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
    switch (o.kind) {
      case ObjectKind::Bezier2:
      case ObjectKind::Bezier3:
      case ObjectKind::BSpline2:
      case ObjectKind::BSpline3: {
        const bool planar = is_planar_curve(o.kind);
        out += ' ' + std::to_string(o.steps) + ' ' + std::to_string(o.points.size()) + '\n';
        ++line;
        for (const auto& p : o.points) {
          out += '[';
          append_number(out, p.x);
          out += ' ';
          append_number(out, p.y);
          if (!planar) {
            out += ' ';
            append_number(out, p.z);
          }
          out += "]\n";
          ++line;
        }
        break;
      }
      case ObjectKind::Circle:
        out += ' ' + std::to_string(o.steps) + ' ';
        append_number(out, o.radius);
        out += '\n';
        ++line;
        break;
      case ObjectKind::SurfaceOfRevolution:
        out += ' ' + std::to_string(o.steps);
        append_reference(out, doc, o.profile);
        out += '\n';
        ++line;
        break;
      case ObjectKind::GeneralizedCylinder:
        append_reference(out, doc, o.profile);
        append_reference(out, doc, o.sweep);
        out += '\n';
        ++line;
        break;
    }
    out += '\n';
    ++line;
  }
  return out;
}

void save_swp_file(const std::filesystem::path& path, const Document& doc) {
  write_file_atomically(path, write_swp(doc));
}

}  // namespace sweep
