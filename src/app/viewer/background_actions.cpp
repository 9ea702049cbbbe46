// Opening a large file and exporting a large document off the drawing thread (issue 29, "never
// freezing"): the parse, or the export's evaluation and writing, runs as an
// editor::BackgroundTask; what it found is applied on the drawing thread when the viewer polls.
// Small files and documents are done at once, as before: no frame of delay for everyday work.
#include "app/viewer/actions.hpp"
#include "io/svg/export.hpp"
#include "io/swp/read.hpp"
#include "model/caps.hpp"

#include <filesystem>
#include <memory>
#include <numeric>
#include <system_error>
#include <utility>

namespace sweep::viewer {
namespace {

/// Files from this size on are parsed in the background (the reader reads about 250 MB/s:
/// BM_ParseMillionControlPoints; 8 MiB takes about 30 ms).
constexpr std::uintmax_t kBackgroundOpenBytes = 8u << 20;

bool large_file(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return !error && size >= kBackgroundOpenBytes;
}

bool large_document(const Document& doc) {
  std::vector<int> all(doc.objects.size());
  std::iota(all.begin(), all.end(), 0);
  return evaluation_work(doc, all) > editor::kViewerBackgroundWork;
}

/// "wrote PATH (...)" for every file of `report`, then its warnings, one a line.
std::string export_status(const io::ExportReport& report) {
  std::string text;
  for (const std::string& line : io::written_lines(report)) text += (text.empty() ? "" : "\n") + line;
  for (const std::string& warning : report.warnings) text += "\n" + warning;
  return text;
}

/// Reads `path`: the document, or the message to show (file:line:column for a parse error).
struct ReadResult {
  std::optional<Document> doc;
  std::string error;
};
ReadResult read_document(const std::string& path) {
  try {
    return {io::load_swp_file(path), {}};
  } catch (const io::ParseError& e) {
    return {std::nullopt, e.what()};
  } catch (const std::exception& e) {
    return {std::nullopt, path + ": " + e.what()};
  }
}

/// Runs `work` in the background, superseding (cancelling) any task in flight.
void start_task(ViewerState& s, std::string label, editor::BackgroundTask::Work work) {
  if (s.task) {
    s.task->cancel();
    s.retired_tasks.push_back(std::move(s.task));
  }
  s.task = std::make_unique<editor::BackgroundTask>(std::move(label), std::move(work));
}

}  // namespace

bool open_file(ViewerState& s, const std::string& path) {
  if (!large_file(path)) {
    ReadResult read = read_document(path);
    if (!read.doc) {
      s.error = read.error;
      return false;
    }
    return show_document(s, std::move(*read.doc), path);
  }
  const std::string label = "Opening " + std::filesystem::path(path).filename().string();
  start_task(s, label, [&s, path](const std::atomic<bool>&) -> editor::BackgroundTask::Finish {
    auto read = std::make_shared<ReadResult>(read_document(path));
    return [&s, read, path] {
      if (read->doc) {
        show_document(s, std::move(*read->doc), path);
      } else {
        s.error = read->error;
      }
    };
  });
  s.status = label + " ...";
  return true;
}

/// What an export did: the status line and, for 3MF and STL, the printability findings.
struct ExportOutcome {
  std::string status;
  std::vector<PrintFinding> findings;
};

/// The findings as the Export panel lists them, the objects named by their ids in `ids` (the
/// session's ids of the exported document's objects, by index).
PrintFindings finding_rows(const std::string& path, const std::vector<PrintFinding>& findings,
                           const std::vector<editor::ObjectId>& ids) {
  PrintFindings out{path, {}};
  for (const PrintFinding& f : findings) {
    const std::string shown = "line " + std::to_string(f.line) + (f.fails ? ": " : ": note: ") + f.text;
    out.rows.push_back({ids[f.object], f.message, shown, f.where, f.fails});
  }
  return out;
}

std::vector<editor::ObjectId> object_ids(const editor::EditSession& session) {
  std::vector<editor::ObjectId> ids(session.document().objects.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = session.id_of(static_cast<int>(i));
  return ids;
}

void export_document(ViewerState& s, const std::string& prefix, io::ExportFormat format, io::GlbEncoding encoding) {
  const std::string resolved = resolve_output_path(prefix, output_folder(s), default_output_stem(s)).string();
  const std::string failed = std::string("export ") + io::export_format_label(format) + " failed: ";
  // The session's scene has texture coordinates only where drawn; OBJ and glb write them everywhere.
  const EvaluationOptions options = io::export_evaluation(s.session.evaluation(), format);
  const io::PrintOptions print{s.fields.print_height_mm};
  // `cancelled` (the background task's flag) is looked at before writing.
  const auto write = [resolved, format, encoding, options, print](const Document& doc, const std::string& file,
                                                                  const std::atomic<bool>* cancelled) {
    const Scene scene = evaluate_document(doc, options);
    if (cancelled != nullptr && *cancelled) return ExportOutcome{};
    io::ExportReport report = io::export_surfaces(doc, scene, file, resolved, format, encoding, print);
    return ExportOutcome{report.files.empty() ? io::no_surfaces_message(file) : export_status(report),
                         std::move(report.findings)};
  };
  const std::vector<editor::ObjectId> ids = object_ids(s.session);
  const bool for_print = format == io::ExportFormat::ThreeMf || format == io::ExportFormat::Stl;
  const std::string checked = for_print ? resolved : std::string();  // the findings' file: none
  if (!large_document(s.doc())) {
    try {
      ExportOutcome outcome = write(s.doc(), s.session.file(), nullptr);
      s.status = std::move(outcome.status);
      s.print_findings = finding_rows(checked, outcome.findings, ids);
      s.error.clear();
    } catch (const std::exception& e) {  // "cannot write PATH: CAUSE", or the surface's file:line:column
      s.error = failed + e.what();
    }
    return;
  }
  // The task works on a copy: the document may change while it runs.
  auto doc = std::make_shared<const Document>(s.doc());
  const std::string file = s.session.file();
  start_task(s, "Exporting " + std::filesystem::path(resolved).filename().string(),
             [&s, doc, file, write, failed, ids,
              checked](const std::atomic<bool>& cancelled) -> editor::BackgroundTask::Finish {
               ExportOutcome outcome;
               std::string error;
               try {
                 if (!cancelled) outcome = write(*doc, file, &cancelled);
               } catch (const std::exception& e) {
                 error = failed + e.what();
               }
               return [&s, status = outcome.status, rows = finding_rows(checked, outcome.findings, ids), error] {
                 s.status = status;
                 s.print_findings = rows;
                 s.error = error;
               };
             });
}

void export_planar_curves(ViewerState& s, const std::string& prefix) {
  const std::string resolved = resolve_output_path(prefix, output_folder(s), default_output_stem(s)).string();
  const std::string& file = s.session.file();
  try {
    const io::SvgExport written = io::export_curves_svg(s.doc(), file.empty() ? "untitled" : file, resolved);
    // Nothing to write is said as OBJ's is, in the status: not an error (the CLI exits 0).
    s.status = written.curves == 0 ? io::no_planar_curves_message(file.empty() ? "the document" : file)
                                   : io::written_line(written);
    s.error.clear();
  } catch (const std::exception& e) {  // "cannot write PATH: CAUSE"
    s.error = std::string("export SVG failed: ") + e.what();
  }
}

bool poll_task(ViewerState& s) {
  std::erase_if(s.retired_tasks, [](const std::unique_ptr<editor::BackgroundTask>& t) { return t->finished(); });
  if (!s.task || !s.task->finished()) return false;
  const std::unique_ptr<editor::BackgroundTask> task = std::move(s.task);
  if (const editor::BackgroundTask::Finish finish = task->take()) finish();
  return true;
}

void cancel_task(ViewerState& s) {
  if (!s.task) return;
  s.status = "cancelled: " + s.task->label();
  s.task->cancel();
  s.retired_tasks.push_back(std::move(s.task));
}

}  // namespace sweep::viewer
