// Stateful property test of the edit session (issue 29): random sequences of the edits the
// editor offers (moves, inserts and deletes of points, STEPS, radii, twist, materials, create,
// rename, delete object), undo, redo, save, reload from disk and recovery from a recovery copy,
// run on an EditSession and on a model (the same model-layer operations on a plain Document with
// a list of undo and redo documents). After every step: the session's document is the model's;
// it writes and reads back equal (Save's format-preserving text: to the file's precision); its recovery copy reads back
// as it; the unsaved flag is clear only when the document is the file's and set whenever it differs; the object ids of
// a state come back with it through undo and redo. An "undo all, redo all" step checks that undoing to the start writes
// the file it started from byte for byte and that redoing to the end gives the document before the undos. Failures
// shrink to a minimal sequence (rapidcheck). RC_PARAMS="max_success=2000" runs a longer search than CI's default.
#include "desktop/recovery.hpp"
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;

// A file with curves of several kinds, surfaces on them and a material, written as a person
// would (uneven spacing, a blank line, numbers as typed) so that format preservation is tested.
constexpr const char* kStart =
    "bez2 profile 4 7\n"
    "[0.5 0]\n[1.2  0.4]\n[0.9 1.1]\n[0.4 1.5]\n[0.45 1.9]\n[0.7 2.2]\n[0.8 2.6]\n"
    "\n"
    "circ path 16 2.0\n"
    "bsp3 spine 4 5\n[0 0 0]\n[1 0 1]\n[2 1 1]\n[3 1 0]\n[4 2 0]\n"
    "material clay color 0.8 0.5 0.3\n"
    "srev vase 12 profile\n"
    "gcyl tube profile path\n";

/// The text the session's save writes for `doc` (as save_swp_file chooses for the editor).
std::string saved_text(const Document& doc) {
  return doc.source.text ? io::write_swp_preserving(doc) : io::write_swp_rounded(doc);
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Model {
  Document doc;
  std::vector<Document> undo;     // the documents undo goes back to, the oldest first
  std::vector<Document> redo;     // the documents redo goes forward to, the next last
  std::string file_text;          // what the file on disk holds
  std::string start_text;         // what the file held when the history began (load or reload)
  bool history_from_load = true;  // the oldest undo state is start_text as loaded
};

struct Sut {
  fs::path folder;
  fs::path file;
  EditSession session;
  RecoveryStore recovery;
  std::vector<std::vector<ObjectId>> ids_at;  // the ids of each undo depth's state, when reached
};

using Command = rc::state::Command<Model, Sut>;

std::vector<ObjectId> ids(const EditSession& session) {
  std::vector<ObjectId> out;
  for (const Object& object : session.document().objects) out.push_back(object.id);
  return out;
}

/// Save keeps the file's style: a number an edit computed (a Bezier joint removed) is written in
/// the file's precision, within the writer's tolerance (1e-6 of the document's extent,
/// io/swp/detail/patch_tokens.hpp, issue 25). So a document and what Save made of it are the same objects
/// with every point within that tolerance (1e-4 of a unit here, generously).
bool same_within_precision(const Document& doc, const Document& back) {
  if (back.objects.size() != doc.objects.size()) return false;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& a = doc.objects[i];
    const Object& b = back.objects[i];
    if (a.name != b.name || a.kind() != b.kind()) return false;
    const auto pa = points_of(a);
    const auto pb = points_of(b);
    if (pa.size() != pb.size()) return false;
    for (std::size_t k = 0; k < pa.size(); ++k) {
      const double size = 1.0 + std::max({std::abs(pa[k].x), std::abs(pa[k].y), std::abs(pa[k].z)});
      if (glm::length(pa[k] - pb[k]) > 1e-4 * size) return false;
    }
    if (pa.empty() && !(a == b)) return false;  // no points: the rest must match exactly
  }
  return true;
}

/// The invariants that hold after every step.
void check_invariants(const Model& model, Sut& sut) {
  const Document& doc = sut.session.document();
  RC_ASSERT(doc == model.doc);
  RC_ASSERT(io::parse_swp(io::write_swp(doc)) == doc);                    // writes and reads back equal
  RC_ASSERT(same_within_precision(doc, io::parse_swp(saved_text(doc))));  // as Save writes it
  const std::string problem = sut.recovery.write(doc, sut.file.string());
  RC_ASSERT(problem.empty());
  RC_ASSERT(io::load_swp_file(sut.recovery.copy_path(sut.file.string())) == doc);  // the copy reads back
  const bool same_as_file = same_within_precision(doc, io::parse_swp(read_file(sut.file)));
  if (!sut.session.dirty()) RC_ASSERT(same_as_file);  // clean: exactly the file
  if (!same_as_file) RC_ASSERT(sut.session.dirty());  // differs: unsaved
  const std::size_t depth = model.undo.size();
  if (sut.ids_at.size() > depth) {
    RC_ASSERT(ids(sut.session) == sut.ids_at[depth]);  // the ids this state had
  } else {
    sut.ids_at.resize(depth + 1);
    sut.ids_at[depth] = ids(sut.session);
  }
}

/// An edit: the same model-layer operation on the model and the session.
struct Edit : Command {
  std::string label;
  EditSession::Operation operation;

  /// The model's document after the operation (nullopt when it refuses or changes nothing).
  std::optional<Document> result(const Model& m) const {
    Document next = m.doc;
    try {
      operation(next);
    } catch (const EditError&) {
      return std::nullopt;
    }
    if (next == m.doc) return std::nullopt;
    return next;
  }
  void apply(Model& m) const override {
    if (std::optional<Document> next = result(m)) {
      m.undo.push_back(m.doc);
      m.redo.clear();
      m.doc = std::move(*next);
    }
  }
  void run(const Model& m, Sut& sut) const override {
    const bool changes = result(m).has_value();
    const bool ok = sut.session.edit(label, operation);
    if (changes) RC_ASSERT(ok);
    Model next = m;
    apply(next);
    if (changes) sut.ids_at.resize(next.undo.size());  // a new state at this depth: its ids anew
    check_invariants(next, sut);
  }
  void show(std::ostream& os) const override { os << label; }
};

int any_object(const Model& m) {
  return *rc::gen::inRange(0, static_cast<int>(std::max<std::size_t>(m.doc.objects.size(), 1)));
}
int any_point() {
  return *rc::gen::inRange(0, 8);
}
glm::dvec3 any_position() {
  return {*rc::gen::inRange(-20, 21) / 8.0, *rc::gen::inRange(-20, 21) / 8.0, *rc::gen::inRange(-4, 5) / 8.0};
}

struct MovePoint : Edit {
  explicit MovePoint(const Model& m) {
    const int object = any_object(m), point = any_point();
    const glm::dvec3 to = any_position();
    label = "move point " + std::to_string(point) + " of object " + std::to_string(object);
    operation = [=](Document& d) { return move_point(d, object, point, to); };
  }
};
struct DeletePoint : Edit {
  explicit DeletePoint(const Model& m) {
    const int object = any_object(m), point = any_point();
    label = "delete point " + std::to_string(point) + " of object " + std::to_string(object);
    operation = [=](Document& d) { return delete_point(d, object, point); };
  }
};
struct InsertPoint : Edit {
  explicit InsertPoint(const Model& m) {
    const int object = any_object(m), before = any_point();
    const glm::dvec3 at = any_position();
    label = "insert a point before " + std::to_string(before) + " of object " + std::to_string(object);
    operation = [=](Document& d) { return insert_bspline_point(d, object, before, at); };
  }
};
struct SetSteps : Edit {
  explicit SetSteps(const Model& m) {
    const int object = any_object(m), steps = *rc::gen::inRange(0, 24);
    label = "STEPS " + std::to_string(steps) + " of object " + std::to_string(object);
    operation = [=](Document& d) { return set_steps_or_levels(d, object, steps); };
  }
};
struct SetRadius : Edit {
  explicit SetRadius(const Model& m) {
    const int object = any_object(m);
    const double radius = *rc::gen::inRange(0, 40) / 8.0;
    label = "radius of object " + std::to_string(object);
    operation = [=](Document& d) { return set_radius(d, object, radius); };
  }
};
struct SetTwist : Edit {
  explicit SetTwist(const Model& m) {
    const int object = any_object(m);
    const double degrees = *rc::gen::inRange(-360, 361);
    label = "twist of object " + std::to_string(object);
    operation = [=](Document& d) { return set_twist(d, object, degrees); };
  }
};
struct SetMaterial : Edit {
  explicit SetMaterial(const Model& m) {
    const int surface = any_object(m), material = any_object(m);
    label = "material " + std::to_string(material) + " on object " + std::to_string(surface);
    operation = [=](Document& d) { return set_surface_material(d, surface, material); };
  }
};
struct Rename : Edit {
  explicit Rename(const Model& m) {
    const int object = any_object(m);
    const std::string name = *rc::gen::element<std::string>("a", "b", "profile", "path", "x_1", "bad name");
    label = "rename object " + std::to_string(object) + " to " + name;
    operation = [=](Document& d) { return rename_object(d, object, name); };
  }
};
struct DeleteObject : Edit {
  explicit DeleteObject(const Model& m) {
    const int object = any_object(m);
    label = "delete object " + std::to_string(object);
    operation = [=](Document& d) { return delete_object(d, object); };
  }
};
struct AddCurve : Edit {
  explicit AddCurve(const Model&) {
    const auto shape =
        *rc::gen::element("open B-spline (2D)", "closed B-spline (2D)", "open B-spline (3D)", "Bezier (2D)");
    label = "add a curve";
    operation = [=](Document& d) {
      add_curve(d, shape, unique_name(d, "curve"));
      return Change{{}, true};
    };
  }
};
struct AddMaterial : Edit {
  explicit AddMaterial(const Model&) {
    label = "add a material";
    operation = [](Document& d) {
      add_material(d, unique_name(d, "look"));
      return Change{{}, true};
    };
  }
};

struct Undo : Command {
  void checkPreconditions(const Model& m) const override { RC_PRE(!m.undo.empty()); }
  void apply(Model& m) const override {
    m.redo.push_back(m.doc);
    m.doc = m.undo.back();
    m.undo.pop_back();
  }
  void run(const Model& m, Sut& sut) const override {
    RC_ASSERT(sut.session.undo());
    Model next = m;
    apply(next);
    check_invariants(next, sut);
  }
  void show(std::ostream& os) const override { os << "undo"; }
};

struct Redo : Command {
  void checkPreconditions(const Model& m) const override { RC_PRE(!m.redo.empty()); }
  void apply(Model& m) const override {
    m.undo.push_back(m.doc);
    m.doc = m.redo.back();
    m.redo.pop_back();
  }
  void run(const Model& m, Sut& sut) const override {
    RC_ASSERT(sut.session.redo());
    Model next = m;
    apply(next);
    check_invariants(next, sut);
  }
  void show(std::ostream& os) const override { os << "redo"; }
};

struct Save : Command {
  void apply(Model& m) const override { m.file_text = saved_text(m.doc); }
  void run(const Model& m, Sut& sut) const override {
    RC_ASSERT(sut.session.save(sut.file.string()));
    RC_ASSERT(read_file(sut.file) == saved_text(m.doc));
    RC_ASSERT(!sut.session.dirty());
    check_invariants(m, sut);
  }
  void show(std::ostream& os) const override { os << "save"; }
};

/// Opens the file again, as the viewer's reload from disk: the history starts over.
struct Reload : Command {
  void apply(Model& m) const override {
    m.doc = io::parse_swp_keeping_source(m.file_text);
    m.undo.clear();
    m.redo.clear();
    m.start_text = m.file_text;
  }
  void run(const Model& m, Sut& sut) const override {
    sut.session.load(io::load_swp_file(sut.file), sut.file.string());
    sut.ids_at.clear();
    Model next = m;
    apply(next);
    RC_ASSERT(!sut.session.dirty());
    check_invariants(next, sut);
  }
  void show(std::ostream& os) const override { os << "reload from disk"; }
};

/// Recovers from the recovery copy, as the viewer does after a crash: the copy's objects as one
/// undo step over the file (replace_objects).
struct Recover : Command {
  void apply(Model& m) const override {
    Document recovered = m.doc;
    replace_objects(recovered, io::parse_swp(io::write_swp(m.doc)));
    if (recovered == m.doc) return;  // the copy is the document: no step (History records none)
    m.undo.push_back(m.doc);
    m.redo.clear();
    m.doc = std::move(recovered);
  }
  void run(const Model& m, Sut& sut) const override {
    RC_ASSERT(sut.recovery.write(sut.session.document(), sut.file.string()).empty());
    const Document copy = io::load_swp_file(sut.recovery.copy_path(sut.file.string()));
    RC_ASSERT(sut.session.edit("recover unsaved edits", [&copy](Document& doc) { return replace_objects(doc, copy); }));
    Model next = m;
    apply(next);
    sut.ids_at.resize(next.undo.size());
    check_invariants(next, sut);
  }
  void show(std::ostream& os) const override { os << "recover"; }
};

/// Undoes to the start, checks the file it started from comes back byte for byte, then redoes to
/// the end and checks the document is the one before the undos (or the last one redo had), and
/// goes back to where it was.
struct UndoAllRedoAll : Command {
  void checkPreconditions(const Model& m) const override { RC_PRE(!m.undo.empty()); }
  void apply(Model&) const override {}
  void run(const Model& m, Sut& sut) const override {
    const Document before = sut.session.document();
    while (sut.session.undo()) {
    }
    RC_ASSERT(sut.session.document() == m.undo.front());
    RC_ASSERT(ids(sut.session) == sut.ids_at.front());
    if (m.history_from_load) RC_ASSERT(saved_text(sut.session.document()) == m.start_text);
    while (sut.session.redo()) {
    }
    // The end of the history: the document before the undos, or the last one it could redo to.
    RC_ASSERT(sut.session.document() == (m.redo.empty() ? before : m.redo.front()));
    for (std::size_t i = 0; i < m.redo.size(); ++i) RC_ASSERT(sut.session.undo());  // back to where it was
    RC_ASSERT(sut.session.document() == before);
    check_invariants(m, sut);
  }
  void show(std::ostream& os) const override { os << "undo all, redo all"; }
};

RC_GTEST_PROP(SessionStateMachine, RandomEditsKeepEveryInvariant, ()) {
  const test::ScratchFolder folder("sweep-session-sm");
  const fs::path file = folder.path() / "model.swp";
  std::ofstream(file, std::ios::binary) << kStart;
  Sut sut{folder.path(), file, EditSession{}, RecoveryStore(folder.path() / "recovery"), {}};
  sut.session.load(io::load_swp_file(file), file.string());
  Model model{io::parse_swp_keeping_source(kStart), {}, {}, kStart, kStart, true};
  sut.ids_at = {ids(sut.session)};
  rc::state::check(
      model, sut,
      rc::state::gen::execOneOfWithArgs<MovePoint, MovePoint, DeletePoint, InsertPoint, SetSteps, SetRadius, SetTwist,
                                        SetMaterial, Rename, DeleteObject, AddCurve, AddMaterial, Undo, Undo, Redo,
                                        Save, Reload, Recover, UndoAllRedoAll>());
}

}  // namespace
}  // namespace sweep::editor
