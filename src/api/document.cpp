#include "api/document_state.hpp"

#include "geometry/thread_pool.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <algorithm>
#include <cstddef>

// The public Document: loading, the objects and their geometry as views, curves evaluated at
// parameters, edits with undo, and saving (document_edits.cpp has the edits).

namespace sweep::v0 {
namespace {

static_assert(sizeof(Frame) == sizeof(::sweep::Frame) && offsetof(Frame, T) == offsetof(::sweep::Frame, T) &&
                  offsetof(Frame, N) == offsetof(::sweep::Frame, N) &&
                  offsetof(Frame, B) == offsetof(::sweep::Frame, B),
              "a public Frame is laid out as the internal one, so curve samples are handed out as they are");
static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float),
              "mesh arrays are handed out as floats");

std::string category_of(::sweep::ObjectKind kind) {
  if (::sweep::is_curve(kind)) return "curve";
  if (::sweep::is_surface(kind)) return "surface";
  if (::sweep::is_material(kind)) return "material";
  return "rider";
}

std::span<const float> floats(const auto& vectors) {
  using Vector = typename std::decay_t<decltype(vectors)>::value_type;
  return {reinterpret_cast<const float*>(vectors.data()), vectors.size() * (sizeof(Vector) / sizeof(float))};
}

SurfaceMesh mesh_view(const detail::DocumentState& s, int index) {
  const ::sweep::Mesh& mesh = s.scene->objects[std::size_t(index)].mesh;
  return {::sweep::display_name(s.doc, index),
          std::string(::sweep::keyword(s.doc.objects[std::size_t(index)].kind())),
          floats(mesh.positions),
          floats(mesh.normals),
          floats(mesh.uvs),
          mesh.indices,
          s.scene};
}

CurveView curve_view(const detail::DocumentState& s, int index) {
  const ::sweep::CurveSamples& curve = s.scene->objects[std::size_t(index)].curve;
  return {::sweep::display_name(s.doc, index),
          std::string(::sweep::keyword(s.doc.objects[std::size_t(index)].kind())),
          curve.planar,
          curve.closed,
          {reinterpret_cast<const Frame*>(curve.frames.data()), curve.frames.size()},
          curve.parameters,
          s.scene};
}

/// The index of the object `name`, of the kind `is_kind` asks for ("surface", "curve").
int index_of_kind(const detail::DocumentState& s, std::string_view name, bool (*is_kind)(::sweep::ObjectKind),
                  const char* what) {
  const int index = s.index_of(name);
  if (!is_kind(s.doc.objects[std::size_t(index)].kind())) {
    throw Error("'" + std::string(name) + "' in " + s.name + " is not a " + what);
  }
  return index;
}

/// `parameters`, each within `range` (one beyond it by rounding, within 1e-9 of the range's size,
/// is moved onto its end: `low + (high - low) * i / (n - 1)` may overshoot), or Error; when
/// `ascending`, none may be below the one before it. A copy only when one was moved.
std::span<const double> checked_parameters(std::pair<double, double> range, std::string_view name,
                                           std::span<const double> parameters, bool ascending,
                                           std::vector<double>& moved) {
  const auto [low, high] = range;
  const double slack = 1e-9 * std::max(1.0, high - low);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const double t = parameters[i];
    if (!(t >= low - slack && t <= high + slack)) {
      throw Error("parameter " + std::to_string(t) + " is outside curve '" + std::string(name) + "' (" +
                  std::to_string(low) + " to " + std::to_string(high) + ")");
    }
    if (ascending && i > 0 && t < parameters[i - 1]) {
      throw Error("parameters must ascend (frames are carried along the curve): parameter " + std::to_string(i) +
                  " is below the one before it");
    }
    if ((t < low || t > high) && moved.empty()) moved.assign(parameters.begin(), parameters.end());
  }
  if (moved.empty()) return parameters;
  for (double& t : moved) t = std::clamp(t, low, high);
  return moved;
}

std::unique_ptr<detail::DocumentState> evaluated(::sweep::Document doc, const EvaluationOptions& options,
                                                 std::filesystem::path file, std::string name) {
  auto state = std::make_unique<detail::DocumentState>();
  state->options = detail::internal_options(options);
  state->scene = std::make_shared<::sweep::Scene>(::sweep::evaluate_document(doc, state->options));
  state->doc = std::move(doc);
  state->file = std::move(file);
  state->name = std::move(name);
  return state;
}

}  // namespace

Document::Document(std::unique_ptr<detail::DocumentState> state) : state_(std::move(state)) {}
Document::Document(Document&&) noexcept = default;
Document& Document::operator=(Document&&) noexcept = default;
Document::~Document() = default;

Document Document::load(const std::filesystem::path& file, const EvaluationOptions& options) {
  try {
    return Document(evaluated(::sweep::io::load_swp_file(file), options, file, file.string()));
  } catch (...) {
    detail::throw_public_error();
  }
}

Document Document::parse(std::string_view text, std::string_view name, const EvaluationOptions& options) {
  try {
    return Document(
        evaluated(::sweep::io::parse_swp_keeping_source(std::string(text), name), options, {}, std::string(name)));
  } catch (...) {
    detail::throw_public_error();
  }
}

const std::filesystem::path& Document::file() const {
  return state_->file;
}

std::vector<ObjectInfo> Document::objects() const {
  std::vector<ObjectInfo> out;
  const ::sweep::Document& doc = state_->doc;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const ::sweep::Object& object = doc.objects[i];
    const ::sweep::PointsPart* points = object.find<::sweep::PointsPart>();
    out.push_back({::sweep::display_name(doc, int(i)), std::string(::sweep::keyword(object.kind())),
                   category_of(object.kind()), points != nullptr ? int(points->points.size()) : 0});
  }
  return out;
}

std::vector<SurfaceMesh> Document::surfaces() const {
  std::vector<SurfaceMesh> out;
  for (std::size_t i = 0; i < state_->doc.objects.size(); ++i) {
    if (::sweep::is_surface(state_->doc.objects[i].kind())) out.push_back(mesh_view(*state_, int(i)));
  }
  return out;
}

std::vector<CurveView> Document::curves() const {
  std::vector<CurveView> out;
  for (std::size_t i = 0; i < state_->doc.objects.size(); ++i) {
    if (::sweep::is_curve(state_->doc.objects[i].kind())) out.push_back(curve_view(*state_, int(i)));
  }
  return out;
}

SurfaceMesh Document::surface(std::string_view name) const {
  return mesh_view(*state_, index_of_kind(*state_, name, ::sweep::is_surface, "surface"));
}

CurveView Document::curve(std::string_view name) const {
  return curve_view(*state_, index_of_kind(*state_, name, ::sweep::is_curve, "curve"));
}

std::pair<double, double> Document::curve_range(std::string_view name) const {
  // The evaluated samples span the whole range, ends included, however they were sampled.
  const std::vector<double>& parameters =
      state_->scene->objects[std::size_t(index_of_kind(*state_, name, ::sweep::is_curve, "curve"))].curve.parameters;
  return parameters.empty() ? std::pair{0.0, 0.0} : std::pair{parameters.front(), parameters.back()};
}

CurveFrames Document::evaluate_curve(std::string_view name, std::span<const double> parameters) const {
  const int index = index_of_kind(*state_, name, ::sweep::is_curve, "curve");
  std::vector<double> moved;
  parameters = checked_parameters(curve_range(name), name, parameters, true, moved);
  try {
    auto samples = std::make_shared<const ::sweep::CurveSamples>(
        ::sweep::evaluate_curve_at(state_->doc.objects[std::size_t(index)], parameters, state_->options.frames));
    return {
        {reinterpret_cast<const Frame*>(samples->frames.data()), samples->frames.size()}, samples->parameters, samples};
  } catch (...) {
    detail::throw_public_error();
  }
}

std::vector<double> Document::curve_points(std::string_view name, std::span<const double> parameters) const {
  const int index = index_of_kind(*state_, name, ::sweep::is_curve, "curve");
  std::vector<double> moved;
  parameters = checked_parameters(curve_range(name), name, parameters, false, moved);
  const ::sweep::CurveDescriptor curve = ::sweep::describe_curve(state_->doc.objects[std::size_t(index)]);
  std::vector<double> out(parameters.size() * 3);
  ::sweep::parallel_chunks(parameters.size(), 1 << 16, ::sweep::worker_count(),
                           [&](std::size_t begin, std::size_t end, int) {
                             for (std::size_t i = begin; i < end; ++i) {
                               const glm::dvec3 p = ::sweep::curve_position(curve, parameters[i]);
                               out[3 * i] = p.x;
                               out[3 * i + 1] = p.y;
                               out[3 * i + 2] = p.z;
                             }
                           });
  return out;
}

std::string Document::text() const {
  return state_->doc.source.text == nullptr ? ::sweep::io::write_swp(state_->doc)
                                            : ::sweep::io::write_swp_preserving(state_->doc);
}

void Document::save(const std::filesystem::path& file) {
  try {
    ::sweep::io::save_swp_file(file, state_->doc);
  } catch (...) {
    detail::throw_public_error();
  }
  state_->history.mark_saved();
}

}  // namespace sweep::v0
