#include "api/document_state.hpp"

#include "io/swp/read.hpp"
#include "model/edit/edit_support.hpp"

#include <array>

// The public Document's edits: each is one step of the document's history, checked by the
// model's edit operations (the viewer's), and evaluated again where it changed.

namespace sweep::v0 {
namespace detail {

int DocumentState::index_of(std::string_view object) const {
  const int index = doc.find(object);
  if (index >= 0) return index;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {  // an unnamed object by its display name
    if (::sweep::display_name(doc, int(i)) == object) return int(i);
  }
  throw Error("no object named '" + std::string(object) + "' in " + name);
}

void DocumentState::reevaluate(const ::sweep::Change& change) {
  if (change.objects.empty() && !change.structure) return;
  if (scene.use_count() > 1) scene = std::make_shared<::sweep::Scene>(*scene);  // views keep the old one
  if (change.structure || scene->objects.size() != doc.objects.size()) {
    *scene = ::sweep::evaluate_document(doc, options);
    return;
  }
  for (const int index : change.objects) ::sweep::reevaluate(*scene, doc, index, options);
}

void DocumentState::edit(const std::string& label, const std::function<::sweep::Change(::sweep::Document&)>& change) {
  history.begin(doc, label);
  ::sweep::Change changed;
  try {
    changed = change(doc);
  } catch (...) {
    history.cancel(doc);
    throw_public_error();
  }
  history.end(doc);
  reevaluate(changed);
}

void throw_public_error() {
  try {
    throw;
  } catch (const Error&) {
    throw;
  } catch (const ::sweep::io::ParseError& e) {
    throw Error(e.what(), e.file(), e.line(), e.column());
  } catch (const std::exception& e) {
    throw Error(e.what());
  }
}

::sweep::EvaluationOptions internal_options(const EvaluationOptions& options) {
  const bool frames = options.frames == "rmf" || options.frames == "projection";
  const bool seam =
      options.seam == "full" || options.seam == "symmetric" || options.seam == "index" || options.seam == "none";
  if (!frames) throw Error("frames must be rmf or projection, not '" + options.frames + "'");
  if (!seam) throw Error("seam must be full, symmetric, index or none, not '" + options.seam + "'");
  if (!(options.tolerance >= 0.0)) throw Error("the tolerance must be 0 or more");
  ::sweep::EvaluationOptions out = ::sweep::evaluation_options(options.frames, options.seam, options.tolerance);
  if (options.uvs) out.texture_coordinates = ::sweep::TextureCoordinates::Everywhere;
  return out;
}

}  // namespace detail

namespace {

/// The curve parameter a field names ("alpha", "R", ...), if any.
std::optional<::sweep::CurveParameter> parameter_named(std::string_view field) {
  for (const ::sweep::CurveParameter p :
       {::sweep::CurveParameter::Alpha, ::sweep::CurveParameter::Tension, ::sweep::CurveParameter::Continuity,
        ::sweep::CurveParameter::Bias, ::sweep::CurveParameter::Radius, ::sweep::CurveParameter::Pitch,
        ::sweep::CurveParameter::Turns, ::sweep::CurveParameter::MajorRadius, ::sweep::CurveParameter::KnotP,
        ::sweep::CurveParameter::KnotQ, ::sweep::CurveParameter::Tolerance}) {
    if (::sweep::parameter_name(p) == field) return p;
  }
  return std::nullopt;
}

}  // namespace

std::array<double, 3> Document::point(std::string_view object, int point) const {
  const int index = state_->index_of(object);
  const ::sweep::PointsPart* points = state_->doc.objects[std::size_t(index)].find<::sweep::PointsPart>();
  if (points == nullptr) throw Error("'" + std::string(object) + "' has no control points");
  try {
    ::sweep::edit_support::check_point_index(state_->doc, index, point);  // the edits' own message
  } catch (...) {
    detail::throw_public_error();
  }
  const glm::dvec3& p = points->points[std::size_t(point)];
  return {p.x, p.y, p.z};
}

void Document::move_point(std::string_view object, int point, const std::array<double, 3>& position) {
  const int index = state_->index_of(object);
  state_->edit("move point " + std::to_string(point) + " of " + std::string(object), [&](::sweep::Document& doc) {
    return ::sweep::move_point(doc, index, point, {position[0], position[1], position[2]});
  });
}

void Document::set_field(std::string_view object, std::string_view field, double value) {
  const int index = state_->index_of(object);
  const std::string label = "set " + std::string(field) + " of " + std::string(object);
  if (field == "steps" || field == "levels") {
    if (!(value >= 0.0 && value <= 1e9) || value != double(int(value))) {
      throw Error(std::string(field) + " must be a whole number, not " + std::to_string(value));
    }
    state_->edit(label, [&](::sweep::Document& doc) { return ::sweep::set_steps_or_levels(doc, index, int(value)); });
  } else if (field == "radius" && state_->doc.objects[std::size_t(index)].kind() == ::sweep::ObjectKind::Circle) {
    state_->edit(label, [&](::sweep::Document& doc) { return ::sweep::set_radius(doc, index, value); });
  } else if (const std::optional<::sweep::CurveParameter> parameter = parameter_named(field)) {
    state_->edit(label,
                 [&](::sweep::Document& doc) { return ::sweep::set_curve_parameter(doc, index, *parameter, value); });
  } else {
    throw Error("unknown field '" + std::string(field) +
                "' (steps, levels, radius, alpha, tension, continuity, bias, "
                "pitch, turns, R, P, Q, tolerance)");
  }
}

bool Document::undo() {
  if (!state_->history.can_undo()) return false;
  state_->reevaluate(state_->history.undo(state_->doc));
  return true;
}

bool Document::redo() {
  if (!state_->history.can_redo()) return false;
  state_->reevaluate(state_->history.redo(state_->doc));
  return true;
}

bool Document::can_undo() const {
  return state_->history.can_undo();
}

bool Document::can_redo() const {
  return state_->history.can_redo();
}

bool Document::modified() const {
  return state_->history.dirty();
}

}  // namespace sweep::v0
