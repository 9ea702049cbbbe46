#include "app/viewer/file_safety.hpp"

#include "app/viewer/actions.hpp"
#include "desktop/recent_files.hpp"
#include "io/files/atomic_file.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/riders.hpp"

#include <imgui.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <system_error>

namespace sweep::viewer {
namespace {

using Question = FileSafety::Question;

/// A folder problem goes to the error panel, after what is there already.
void report(ViewerState& s, const std::string& problem) {
  if (problem.empty()) return;
  s.error += (s.error.empty() ? "" : "\n") + problem;
}

/// Scripted runs (tests) hear about reloads and recovery copies on stdout.
void say(const ViewerState& s, const std::string& line) {
  if (!s.report_saves) return;
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

/// Replaces the document by `doc` read from the same file, keeping the camera, the display,
/// and visibility and selection of the objects by name.
void show_reloaded(ViewerState& s, Document doc) {
  std::map<std::string, bool> visible;
  for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
    visible[display_name(s.doc(), static_cast<int>(i))] = s.views.visible(s.session.id_of(static_cast<int>(i)));
  }
  const int selected = s.selected();
  const std::string selected_name = selected >= 0 ? display_name(s.doc(), selected) : std::string();
  const render::Camera camera = s.camera;
  const editor::Playback playback = s.playback;
  const RideAlong ride = s.ride;
  const int rider = s.session.index_of(ride.rider);
  const std::string rider_name = rider >= 0 ? s.doc().objects[std::size_t(rider)].name : std::string();
  const std::string path = s.session.file();
  if (!show_document(s, std::move(doc), path)) return;
  s.camera = camera;
  s.frame_when_evaluated = false;  // the camera stays where the user had it
  s.playback = playback;
  s.playback.scrub(playback.time(), longest_loop(s.doc()));  // the loop may be shorter now
  // A ride goes on with the rider of the same name.
  const int new_rider = rider_name.empty() ? -1 : s.doc().find(rider_name);
  if (new_rider >= 0 && is_rider(s.doc().objects[std::size_t(new_rider)].kind())) {
    s.ride = ride;
    s.ride.rider = s.session.id_of(new_rider);
  }
  for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
    const auto it = visible.find(display_name(s.doc(), static_cast<int>(i)));
    if (it != visible.end()) s.views.set_visible(s.session.id_of(static_cast<int>(i)), it->second);
  }
  if (!selected_name.empty()) select_by_name(s, selected_name);
  s.status = "reloaded " + path + " (changed on disk)";
  const int now_selected = s.selected();
  std::string line = "reloaded " + path;
  if (now_selected >= 0) (line += " selected ") += display_name(s.doc(), now_selected);
  say(s, line);
}

/// The file changed on disk: reload it, or ask first when there are edits it would drop.
void file_changed(ViewerState& s) {
  if (s.session.dirty()) {
    s.safety.question = Question::Reload;
    say(s, "question changed on disk");
    return;
  }
  reload_from_disk(s);
}

}  // namespace

void init_file_safety(ViewerState& s, const editor::Environment& env, bool live_reload) {
  s.safety.live_reload = live_reload;
  const editor::UserFolder state = editor::state_folder(env);
  if (state.ok()) {
    s.safety.recovery.emplace(state.path);
  } else {
    report(s, state.problem + " (no crash recovery this run)");
  }
  const editor::UserFolder config = editor::config_folder(env);
  if (!config.ok()) {
    report(s, config.problem);
    return;
  }
  if (const std::string problem = editor::ensure_folder(config); !problem.empty()) {
    report(s, problem + " (recent files and the window layout are not kept)");
    return;
  }
  s.safety.recent_file = config.path / "recent-files.txt";
  s.recent = editor::load_recent(s.safety.recent_file);
  s.safety.ini_file = (config.path / "imgui.ini").string();
  // ImGui would write the layout with fopen, in place: a failure part way would leave half a
  // file. It is read here and written by save_window_layout, atomically.
  ImGui::GetIO().IniFilename = nullptr;
  std::error_code error;
  if (std::filesystem::is_regular_file(s.safety.ini_file, error))
    ImGui::LoadIniSettingsFromDisk(s.safety.ini_file.c_str());
}

void save_window_layout(ViewerState& s, bool now) {
  ImGuiIO& io = ImGui::GetIO();
  if (!now && !io.WantSaveIniSettings) return;
  io.WantSaveIniSettings = false;
  if (s.safety.ini_file.empty()) return;
  std::size_t size = 0;
  const char* text = ImGui::SaveIniSettingsToMemory(&size);
  try {
    io::write_file_atomically(s.safety.ini_file, std::string_view(text, size));
    s.safety.layout_problem.clear();
  } catch (const std::exception& e) {
    // Once per problem: ImGui asks again every few seconds while the layout changes.
    if (s.safety.layout_problem == e.what()) return;
    s.safety.layout_problem = e.what();
    report(s, std::string("window layout not kept: ") + e.what());
  }
}

void remember_recent_file(ViewerState& s, const std::string& path) {
  editor::remember_recent(s.recent, path);
  if (s.safety.recent_file.empty()) return;
  report(s, editor::save_recent(s.safety.recent_file, s.recent));
}

void after_document_shown(ViewerState& s) {
  FileSafety& f = s.safety;
  f.watcher.watch(f.live_reload ? s.session.file() : std::string());
  f.timer.clear();
  f.seen_revision = s.session.revision();
  f.changed_on_disk = false;
  if (!f.recovery) return;
  const std::optional<std::filesystem::path> copy = f.recovery->newer_copy(s.session.file());
  if (!copy) return;
  try {
    f.differences = editor::document_differences(s.doc(), io::load_swp_file(*copy));
  } catch (const std::exception& e) {
    f.differences = {std::string("the copy cannot be read: ") + e.what()};
  }
  f.copy = *copy;
  f.question = Question::Recover;
  say(s, "recovery copy " + copy->string());
}

void after_saved(ViewerState& s, const std::string& previous_file) {
  FileSafety& f = s.safety;
  if (f.recovery) {
    f.recovery->remove(previous_file);
    f.recovery->remove(s.session.file());
  }
  f.timer.clear();
  f.changed_on_disk = false;
  f.watcher.watch(f.live_reload ? s.session.file() : std::string());
}

void note_edits(ViewerState& s, double now) {
  FileSafety& f = s.safety;
  if (s.session.in_step() || s.session.revision() == f.seen_revision) return;
  f.seen_revision = s.session.revision();
  if (s.session.dirty()) {
    f.timer.edited(now);
  } else if (f.recovery) {
    f.timer.clear();
    f.recovery->remove(s.session.file());  // undone back to the saved file
  }
}

bool poll_background(ViewerState& s, double now) {
  FileSafety& f = s.safety;
  bool redraw = false;
  if (f.recovery && f.timer.due(now) && !s.session.in_step()) {
    f.timer.written(now);
    if (s.session.dirty()) {
      const std::string problem = f.recovery->write(s.doc(), s.session.file());
      if (!problem.empty()) {
        s.error = "recovery copy: " + problem;
        redraw = true;
      } else {
        say(s, "recovery written " + f.recovery->copy_path(s.session.file()).string());
      }
    }
  }
  // One question at a time: a change while one is open is seen once it is answered.
  if (f.live_reload && f.question == Question::None && f.watcher.changed(now)) {
    file_changed(s);
    redraw = true;
  }
  return redraw;
}

double background_wait(const ViewerState& s, double now) {
  double wait = s.safety.timer.wait_time(now);
  if (s.safety.live_reload) {
    const double poll = s.safety.watcher.wait_time(now);
    if (poll >= 0.0 && (wait < 0.0 || poll < wait)) wait = poll;
  }
  return wait;
}

void on_clean_quit(ViewerState& s) {
  save_window_layout(s, true);
  if (s.safety.recovery) s.safety.recovery->remove(s.session.file());
}

void discard_changes(ViewerState& s) {
  s.unsaved.choose_discard();
  s.safety.timer.clear();
  if (s.safety.recovery) s.safety.recovery->remove(s.session.file());
}

void recover_copy(ViewerState& s) {
  FileSafety& f = s.safety;
  f.question = Question::None;
  Document recovered;
  try {
    recovered = io::load_swp_file(f.copy);
  } catch (const std::exception& e) {
    s.error = std::string("cannot recover: ") + e.what();
    return;
  }
  // One undo step on top of the saved file: undo shows what the file has.
  // Objects the copy has unchanged keep their text, so a save rewrites only what was recovered.
  run_edit(s, "recover unsaved edits", [&recovered](Document& doc) { return replace_objects(doc, recovered); });
  s.status = "recovered unsaved edits from " + f.copy.string();
  say(s, "recovered " + f.copy.string());
}

void dismiss_copy(ViewerState& s) {
  s.safety.question = Question::None;
  if (s.safety.recovery) s.safety.recovery->remove(s.session.file());
}

void reload_from_disk(ViewerState& s) {
  FileSafety& f = s.safety;
  f.question = Question::None;
  const std::string path = s.session.file();
  // Another program may be writing it still: a version that changed while it was read is not
  // shown (nor its error); the watcher reports the next one once it has settled.
  const editor::FileStamp before = editor::file_stamp(path);
  const auto read_whole = [&] {
    if (editor::file_stamp(path) == before) return true;
    f.watcher.retry();
    say(s, "reload skipped " + path + " (changed while read)");
    return false;
  };
  try {
    Document doc = io::load_swp_file(path);
    if (!read_whole()) return;
    f.watcher.accept();
    show_reloaded(s, std::move(doc));
  } catch (const io::ParseError& e) {
    if (!read_whole()) return;
    f.watcher.accept();
    s.error = e.what();  // the last good scene stays; a fixed file reloads again
    say(s, std::string("reload failed ") + e.what());
  } catch (const std::exception& e) {
    f.watcher.accept();
    s.error = path + ": " + e.what();
  }
}

void keep_my_edits(ViewerState& s) {
  s.safety.question = Question::None;
  s.safety.changed_on_disk = true;
  s.safety.watcher.accept();
  s.status = "kept your edits; " + s.session.file() + " changed on disk, and Save will ask before replacing it";
}

void overwrite_changed_file(ViewerState& s) {
  s.safety.question = Question::None;
  s.safety.changed_on_disk = false;
  save_to(s, s.session.file());
}

}  // namespace sweep::viewer
