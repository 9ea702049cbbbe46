#pragma once
// SVG path data (the `d` attribute; SVG 1.1 section 8.3, "The grammar for path data") as cubic
// Bezier subpaths. Every command, absolute and relative: M L H V C S Q T A Z, a moveto's extra
// coordinate pairs read as linetos, a command letter's repeats without the letter. Numbers follow
// the grammar, not blanks: "1.5.5" is 1.5 and .5, "-1-2" is -1 and -2, "1e-3" one number, and
// the arc's flags are single characters ("a1 1 0 001 1" has flags 0 and 0, then 1 1).
//
// Conversion: a cubic is copied; a line gets its handles at 1/3 and 2/3; a quadratic is raised to
// the cubic that is the same curve (degree elevation); an arc is cut into cubics of at most 90
// degrees (geometry/curves/elliptical_arc.hpp states the tolerance). Z draws the line back to the
// subpath's first point unless it is there already (or within 1e-9 of the subpath's largest
// coordinate, what relative coordinates summed up miss it by), and the subpath's last point is
// then exactly its first.
#include <glm/vec2.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace sweep::io::svg_detail {

/// One subpath: 3n+1 control points (n >= 1 cubic pieces); closed when it ended with Z.
struct BezierSubpath {
  std::vector<glm::dvec2> points;
  bool closed = false;
};

/// The subpaths of path data, or the first problem ("expected a number after 'C' in path data,
/// found 'x'"); a subpath with no drawing command (a moveto alone) gives none.
struct PathParse {
  std::vector<BezierSubpath> subpaths;
  std::string error;  // empty on success
};

/// Reads path data. `max_points` caps the control points of all subpaths together (a huge `d`
/// stops with an error naming the cap instead of growing without bound).
PathParse parse_path_data(std::string_view data, std::size_t max_points);

/// A list of numbers separated by blanks and/or one comma (a polyline's `points`, a viewBox), by
/// the same number grammar; on a problem the error names `what` ("in points").
struct NumberList {
  std::vector<double> numbers;
  std::string error;  // empty on success
};
NumberList parse_number_list(std::string_view text, std::string_view what, std::size_t max_numbers);

}  // namespace sweep::io::svg_detail
