#include "geometry/surfaces/tube_quads.hpp"

#include "base/precondition.hpp"
#include "geometry/thread_pool.hpp"

#include <algorithm>
#include <cstdint>

namespace sweep::surface_detail {
namespace {

/// Calls quad(a, b, c, d, clipped) for the quads of band [band, band + kBandQuads), row after row.
template <typename Quad>
void for_band_quads(const TubeGrid& g, std::size_t band, const Quad& quad) {
  const std::size_t band_end = std::min(g.segments, band + kBandQuads);
  for (std::size_t j = 0; j < g.sweep_segments; ++j) {
    const std::size_t from = g.tube->leave[j];
    const std::size_t jn = (j + 1) % g.rings;
    const std::size_t to = g.tube->arrive[jn];
    const std::size_t shift = jn == 0 ? g.seam_shift : 0;  // only the seam of a closed sweep shifts
    // Rings clipped onto a mitre plane meet there: only such rings are checked for triangles of
    // no area, so a smooth sweep's grid costs no comparison.
    const bool clipped = (*g.moved)[from] || (*g.moved)[to];
    for (std::size_t i = band; i < band_end; ++i) {
      const std::size_t in = (i + 1) % g.ring;
      quad(static_cast<std::uint32_t>(from * g.ring + i), static_cast<std::uint32_t>(from * g.ring + in),
           static_cast<std::uint32_t>(to * g.ring + (i + shift) % g.ring),
           static_cast<std::uint32_t>(to * g.ring + (in + shift) % g.ring), clipped);
    }
  }
}

/// add_quad's six indices at `out`; returns the place after them.
std::uint32_t* put_quad(std::uint32_t* out, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                        bool natural) {
  const std::uint32_t natural_order[6] = {a, b, c, b, d, c};
  const std::uint32_t reversed_order[6] = {a, c, b, b, c, d};
  return std::copy_n(natural ? natural_order : reversed_order, 6, out);
}

}  // namespace

void add_tube_quads(Mesh& mesh, const TubeGrid& g, bool natural, bool sized, int threads) {
  SWEEP_EXPECTS(g.tube && g.moved, "the grid names its rings");
  const std::size_t quads = g.segments * g.sweep_segments;
  SWEEP_EXPECTS(!sized || mesh.indices.size() >= 6 * quads, "sized: room for every quad");
  const std::size_t start = sized ? mesh.indices.size() - 6 * quads : mesh.indices.size();
  const bool any_moved = std::find(g.moved->begin(), g.moved->end(), true) != g.moved->end();
  if (sized && !any_moved) {  // every band has 6 indices per quad: each knows its place
    const std::size_t band_count = (g.segments + kBandQuads - 1) / kBandQuads;
    parallel_chunks(band_count, 1, threads, [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t b = begin; b < end; ++b) {
        std::uint32_t* out = mesh.indices.data() + start + 6 * b * kBandQuads * g.sweep_segments;
        for_band_quads(g, b * kBandQuads,
                       [&](std::uint32_t a, std::uint32_t bb, std::uint32_t c, std::uint32_t d, bool) {
                         out = put_quad(out, a, bb, c, d, natural);
                       });
      }
    });
    return;
  }
  mesh.indices.resize(start);
  for (std::size_t band = 0; band < g.segments; band += kBandQuads) {
    for_band_quads(g, band, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d, bool clipped) {
      if (clipped) {
        add_quad_without_collapsed(mesh.indices, mesh.positions, a, b, c, d, natural);
      } else {
        add_quad(mesh.indices, a, b, c, d, natural);
      }
    });
  }
}

}  // namespace sweep::surface_detail
