#pragma once
// What a document evaluates to, as read-only views: every surface's triangle mesh in the arrays a
// GPU takes (VBO-ready: positions, normals, texture coordinates, indices) and every curve's
// samples with their moving frames. A view keeps what it shows alive: its spans stay valid as
// long as the view (or a copy of it) exists, whatever happens to the document meanwhile (an edit
// evaluates into new storage while views of the old one exist).
#include <sweep/version.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

SWEEP_BEGIN_NAMESPACE

/// One surface's mesh (srev, gcyl, birail, patch, mesh, subd). Triangles are counterclockwise
/// seen from outside, normals point out and have unit length.
struct SurfaceMesh {
  std::string name;                        // the object's name, or "KIND#INDEX" for an unnamed one
  std::string kind;                        // its SWP keyword: "srev", "gcyl", "subd", ...
  std::span<const float> positions;        // x, y, z per vertex
  std::span<const float> normals;          // x, y, z per vertex, unit length
  std::span<const float> uvs;              // u, v per vertex, or empty (EvaluationOptions::uvs)
  std::span<const std::uint32_t> indices;  // 3 per triangle, into the vertices
  std::shared_ptr<const void> owner;       // keeps the arrays alive

  std::size_t vertex_count() const { return positions.size() / 3; }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

/// One sample of a curve: its position V and its frame, tangent T, normal N and binormal B (unit
/// length, right-handed: B = T x N). Planar curves have B = +z and N = B x T; 3D frames start from
/// B = +z and are carried rotation-minimizing (or as EvaluationOptions::frames says).
struct Frame {
  double V[3];
  double T[3];
  double N[3];
  double B[3];
};
static_assert(sizeof(Frame) == 12 * sizeof(double), "a frame is 12 doubles: V, T, N, B");

/// One curve's samples as the document evaluated them (STEPS per cubic piece, or adaptively).
struct CurveView {
  std::string name;
  std::string kind;  // "bsp2", "bez3", "circ", ...
  bool planar = false;
  bool closed = false;
  std::span<const Frame> frames;       // one per sample
  std::span<const double> parameters;  // each sample's curve parameter (see Document::curve_range)
  std::shared_ptr<const void> owner;   // keeps the arrays alive

  std::size_t sample_count() const { return frames.size(); }
};

/// A curve evaluated at parameters asked for (Document::evaluate_curve): one frame per
/// parameter, in order, held by `owner` like the views above (nothing is copied out).
struct CurveFrames {
  std::span<const Frame> frames;
  std::span<const double> parameters;
  std::shared_ptr<const void> owner;
};

SWEEP_END_NAMESPACE
