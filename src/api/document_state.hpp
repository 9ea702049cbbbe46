#pragma once
// What a public sweep::Document holds (include/sweep/document.hpp): the internal document, its
// evaluated scene, the options it was evaluated with and the undo history. Compiled only into
// the library, where SWEEP_DETAIL_INLINE is empty: sweep::v0 is then an ordinary namespace, so the
// public names (v0::Document) and the internal ones (sweep::Document) do not collide.
#include "model/document.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/history.hpp"
#include "model/evaluation/scene.hpp"

#include <sweep/document.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace sweep::v0::detail {

struct DocumentState {
  ::sweep::Document doc;
  /// Shared with the views handed out: an edit evaluates in place when no view holds it, into a
  /// copy otherwise, so a view never sees its arrays change or go.
  std::shared_ptr<::sweep::Scene> scene;
  ::sweep::EvaluationOptions options;
  ::sweep::History history;
  std::filesystem::path file;
  std::string name;  // the file's name in messages

  /// The index of the object named `name`, or Error "no object named 'NAME' in FILE".
  int index_of(std::string_view name) const;
  /// Runs `edit` as one undoable step labelled `label`: on EditError the document is restored and
  /// Error thrown; on success the changed objects are evaluated again.
  void edit(const std::string& label, const std::function<::sweep::Change(::sweep::Document&)>& edit);
  /// Evaluates what `change` touched (everything when it changed the structure).
  void reevaluate(const ::sweep::Change& change);

  /// The state of a public document (DocumentState is its friend).
  static const DocumentState& of(const Document& document) { return *document.state_; }
};

/// The internal evaluation options of the public ones; Error for an unknown frames or seam name.
::sweep::EvaluationOptions internal_options(const EvaluationOptions& options);

/// Called in a catch (...) block: rethrows the exception being handled as sweep::Error (a
/// ParseError keeps its file, line and column; an Error passes as it is).
[[noreturn]] void throw_public_error();

}  // namespace sweep::v0::detail
