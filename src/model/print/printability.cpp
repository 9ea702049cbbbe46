#include "model/print/printability.hpp"

#include "base/precondition.hpp"
#include "geometry/mesh/intersections.hpp"
#include "geometry/mesh/shell_contact.hpp"
#include "geometry/mesh/shell_topology.hpp"
#include "geometry/mesh/wall_thickness.hpp"
#include "geometry/thread_pool.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace sweep {
namespace {

/// Millimetres with one decimal ("0.3") or two below a millimetre ("0.31"), as messages say them.
std::string mm(double value) {
  char text[32];
  std::snprintf(text, sizeof text, std::abs(value) < 1.0 ? "%.2f" : "%.1f", value);
  return text;
}

std::string count_text(std::size_t count, std::size_t limit, const char* what) {
  return (count >= limit ? "at least " : "") + std::to_string(count) + " " + what;
}

/// Makes the findings of one model: the document for names and lines, the source for messages.
class Checker {
 public:
  Checker(const Document& doc, const PrintModel& model, const std::string& source, const PrintCheckOptions& options)
      : doc_(doc), model_(model), source_(source), options_(options) {}

  std::vector<PrintFinding> run() {
    std::vector<ShellTopology> topology;
    bvhs_.reserve(model_.parts.size());  // one hierarchy per part, for every check
    for (const PrintPart& part : model_.parts) {
      bvhs_.emplace_back(part.shell, worker_count());
      topology.push_back(check_part(part, bvhs_.back()));
      closed_.push_back(topology.back().closed_manifold() && topology.back().consistently_oriented());
    }
    if (!options_.together) return std::move(findings_);
    check_pairs(topology);
    check_floating();
    return std::move(findings_);
  }

 private:
  std::string at(std::size_t object) const {
    const SourceLocation& l = doc_.objects[object].location;
    return source_ + ":" + std::to_string(l.line) + ":" + std::to_string(l.column);
  }

  std::string line_of(std::size_t object) const { return std::to_string(doc_.objects[object].location.line); }

  void add(PrintCheck check, const PrintPart& part, const glm::dvec3& where_mm, const std::string& text,
           std::optional<std::size_t> other = std::nullopt) {
    const bool note = check == PrintCheck::Overlap;
    findings_.push_back({check, part.object, other, where_mm, unplaced(model_.placement, where_mm), text,
                         doc_.objects[part.object].location.line,
                         at(part.object) + (note ? ": note: " : ": warning: ") + text, !note});
  }

  std::string surface(const PrintPart& part) const { return "surface '" + part.name + "'"; }

  ShellTopology check_part(const PrintPart& part, const TriangleBvh& bvh) {
    const ShellTopology t = shell_topology(part.shell);
    const std::string name = surface(part);
    if (t.boundary_edges > 0) {
      add(PrintCheck::Open, part, t.boundary_at,
          name + " is open: " + std::to_string(t.boundary_loops) + (t.boundary_loops == 1 ? " hole (" : " holes (") +
              std::to_string(t.boundary_edges) + " boundary edges); a printer needs a closed solid");
    }
    if (t.non_manifold_edges > 0) {
      add(PrintCheck::NonManifold, part, t.non_manifold_at,
          name + " has " + std::to_string(t.non_manifold_edges) +
              " non-manifold edges (each of more than two triangles)");
    }
    if (!t.consistently_oriented()) {
      add(PrintCheck::Orientation, part, t.misoriented_at,
          name + " is not consistently oriented: " + std::to_string(t.misoriented_edges) +
              " edges join triangles that face opposite ways");
    } else if (t.closed_manifold() && t.volume < 0.0) {
      add(PrintCheck::Orientation, part, part.shell.positions.front(),
          name + " is inside out: its triangles face into the solid");
    }
    const IntersectingPairs self = self_intersections(bvh, options_.intersection_limit);
    if (self.count > 0) {
      add(PrintCheck::SelfIntersection, part, self.first_point,
          name + " passes through itself (" +
              count_text(self.count, options_.intersection_limit, "pairs of crossing triangles") + ")");
    }
    if (t.closed_manifold() && t.consistently_oriented() && t.volume > 0.0) check_walls(part, bvh);
    return t;
  }

  void check_walls(const PrintPart& part, const TriangleBvh& bvh) {
    const ThinWalls thin = thin_walls(bvh, options_.min_wall_mm);
    if (thin.triangles == 0) return;
    add(PrintCheck::ThinWall, part, thin.where,
        surface(part) + " has walls thinner than " + mm(options_.min_wall_mm) +
            " mm: " + std::to_string(thin.triangles) + " triangles, the thinnest " + mm(thin.thinnest) +
            " mm at a height of " + mm(model_.placement.size.z) + " mm");
  }

  void check_pairs(const std::vector<ShellTopology>& topology) {
    const std::size_t n = model_.parts.size();
    touching_.assign(n * n, false);
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = a + 1; b < n; ++b) {
        const PrintPart& pa = model_.parts[a];
        const PrintPart& pb = model_.parts[b];
        const IntersectingPairs cross = mutual_intersections(bvhs_[a], bvhs_[b], options_.intersection_limit);
        if (cross.count == 0) continue;
        touching_[a * n + b] = touching_[b * n + a] = true;
        const bool solids = topology[a].closed_manifold() && topology[b].closed_manifold();
        const std::string both = "surfaces '" + pa.name + "' and '" + pb.name + "' (line " + line_of(pb.object) + ")";
        if (solids) {
          add(PrintCheck::Overlap, pa, cross.first_point, both + " overlap; a slicer prints them as one solid",
              pb.object);
        } else {
          add(PrintCheck::Intersection, pa, cross.first_point,
              both + " cross (" + count_text(cross.count, options_.intersection_limit, "pairs of triangles") +
                  ") where one is open; a slicer cannot tell inside from outside there",
              pb.object);
        }
      }
    }
  }

  /// Groups of parts that cross or hold one another; a group whose lowest point is above the
  /// plate floats.
  void check_floating() {
    const std::size_t n = model_.parts.size();
    std::vector<std::size_t> group(n);
    std::iota(group.begin(), group.end(), std::size_t{0});
    const auto root = [&group](std::size_t v) {
      while (group[v] != v) v = group[v] = group[group[v]];
      return v;
    };
    for (std::size_t a = 0; a < n; ++a) {
      for (std::size_t b = 0; b < n; ++b) {
        if (a != b && (touching_[a * n + b] || (closed_[a] && holds(model_.parts[a].shell, model_.parts[b].shell)))) {
          group[root(a)] = root(b);
        }
      }
    }
    std::vector<glm::dvec3> lowest(n, glm::dvec3(0.0, 0.0, 1e300));
    std::vector<std::size_t> first(n, n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t g = root(k);
      if (first[g] == n) first[g] = k;
      const glm::dvec3 low = lowest_point(model_.parts[k].shell);
      if (low.z < lowest[g].z) lowest[g] = low;
    }
    for (std::size_t g = 0; g < n; ++g) {
      if (first[g] == n || lowest[g].z <= kOnPlateMillimetres) continue;
      const PrintPart& part = model_.parts[first[g]];
      add(PrintCheck::Floating, part, lowest[g],
          surface(part) + " floats: it touches nothing below it; its lowest point is " + mm(lowest[g].z) +
              " mm above the plate");
    }
  }

  const Document& doc_;
  const PrintModel& model_;
  const std::string& source_;
  const PrintCheckOptions& options_;
  std::vector<TriangleBvh> bvhs_;  // per part: its triangles' hierarchy
  std::vector<bool> closed_;       // per part: a closed, consistently oriented shell
  std::vector<bool> touching_;     // n x n: parts whose triangles cross
  std::vector<PrintFinding> findings_;
};

}  // namespace

std::vector<PrintFinding> check_print(const Document& doc, const PrintModel& model, const std::string& source,
                                      const PrintCheckOptions& options) {
  SWEEP_EXPECTS(options.min_wall_mm > 0.0, "min_wall_mm > 0");
  return Checker(doc, model, source, options).run();
}

const char* print_check_name(PrintCheck check) {
  static constexpr const char* kNames[] = {"open",         "non-manifold", "orientation", "self-intersection",
                                           "intersection", "overlap",      "thin-wall",   "floating"};
  return kNames[static_cast<int>(check)];
}

bool print_fails(const std::vector<PrintFinding>& findings) {
  return std::any_of(findings.begin(), findings.end(), [](const PrintFinding& f) { return f.fails; });
}

}  // namespace sweep
