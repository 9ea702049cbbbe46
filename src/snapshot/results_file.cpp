#include "snapshot/results_file.hpp"

#include "io/files/atomic_file.hpp"
#include "snapshot/capped_read.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>

namespace sweep::snapshot {
namespace {

using nlohmann::json;

constexpr std::uintmax_t kMaxResultsBytes = 256u << 20;
constexpr std::array<Status, kStatusCount> kStatuses = {Status::Pass, Status::Warning, Status::Fail,
                                                        Status::New,  Status::Updated, Status::Error};

template <typename Enum, std::size_t N>
Enum enum_from(const json& j, const std::array<Enum, N>& values, const char* what) {
  const std::string text = j.get<std::string>();
  if (const std::optional<Enum> value = named(values, text)) return *value;
  throw ResultsError(std::string("unknown ") + what + " '" + text + "'");
}

/// A number, finite (JSON has no infinity; an overflowing literal would not read back).
double finite(const json& j) {
  const double value = j.get<double>();
  if (!std::isfinite(value)) throw ResultsError("expected a finite number, found " + j.dump());
  return value;
}

json optional_number(const std::optional<double>& value) {
  return value ? json(*value) : json(nullptr);
}

std::optional<double> optional_from(const json& j) {
  return j.is_null() ? std::nullopt : std::optional<double>(finite(j));
}

/// A picture side as the runs write them: lowest..kMaxSnapshotSide.
int side_from(const json& j, int lowest) {
  if (!j.is_number_integer() || j.get<long long>() < lowest || j.get<long long>() > kMaxSnapshotSide) {
    throw ResultsError("expected a picture side from " + std::to_string(lowest) + " to " +
                       std::to_string(kMaxSnapshotSide) + ", found " + j.dump());
  }
  return j.get<int>();
}

json spec_json(const CaseSpec& s) {
  return {{"name", s.name},
          {"file", s.file.generic_string()},
          {"relative", s.relative.generic_string()},
          {"mode", name_of(s.mode)},
          {"view",
           {{"name", name_of(s.view.name)},
            {"yaw", optional_number(s.view.yaw)},
            {"pitch", optional_number(s.view.pitch)},
            {"distance", optional_number(s.view.distance)}}},
          {"color", name_of(s.color)},
          {"size", {s.size.x, s.size.y}},
          {"tolerance", s.tolerance},
          {"frames", name_of(s.frames)},
          {"seam", name_of(s.seam)},
          {"time", s.time},
          {"threshold", s.diff.threshold},
          {"antialiasing", s.diff.forgive_antialiasing},
          {"shift", s.diff.shift},
          {"max_diff_pixels", s.limits.max_diff_pixels},
          {"max_diff_ratio", s.limits.max_diff_ratio},
          {"suite_location", s.suite_location},
          {"order", s.order}};
}

CaseSpec spec_from(const json& j) {
  CaseSpec s;
  s.name = j.at("name").get<std::string>();
  s.file = j.at("file").get<std::string>();
  s.relative = j.at("relative").get<std::string>();
  s.mode = enum_from(j.at("mode"), kEveryMode, "mode");
  const json& view = j.at("view");
  s.view = {enum_from(view.at("name"), kEveryView, "view"), optional_from(view.at("yaw")),
            optional_from(view.at("pitch")), optional_from(view.at("distance"))};
  s.color = enum_from(j.at("color"), render::kColorModes, "color");
  s.size = {side_from(j.at("size").at(0), 1), side_from(j.at("size").at(1), 1)};
  s.tolerance = finite(j.at("tolerance"));
  s.frames = enum_from(j.at("frames"), kEveryFrames, "frames");
  s.seam = enum_from(j.at("seam"), kEverySeam, "seam");
  s.time = finite(j.at("time"));
  s.diff = {finite(j.at("threshold")), j.at("antialiasing").get<bool>(), j.at("shift").get<int>()};
  s.limits = {j.at("max_diff_pixels").get<std::size_t>(), finite(j.at("max_diff_ratio"))};
  s.suite_location = j.at("suite_location").get<std::string>();
  s.order = j.at("order").get<std::size_t>();
  return s;
}

json diff_json(const ImageDiff& d) {
  return {{"same_size", d.same_size},
          {"width", d.width},
          {"height", d.height},
          {"reference_width", d.reference_width},
          {"reference_height", d.reference_height},
          {"differing_pixels", d.differing_pixels},
          {"changed_pixels", d.changed_pixels},
          {"differing_share", d.differing_share},
          {"max_distance", d.max_distance},
          {"mean_distance", d.mean_distance},
          {"antialiased_pixels", d.antialiased_pixels},
          {"shifted_pixels", d.shifted_pixels},
          {"threshold", d.threshold}};
}

ImageDiff diff_from(const json& j) {
  ImageDiff d;
  d.same_size = j.at("same_size").get<bool>();
  d.width = side_from(j.at("width"), 0);
  d.height = side_from(j.at("height"), 0);
  d.reference_width = side_from(j.at("reference_width"), 0);
  d.reference_height = side_from(j.at("reference_height"), 0);
  d.differing_pixels = j.at("differing_pixels").get<std::size_t>();
  d.changed_pixels = j.at("changed_pixels").get<std::size_t>();
  d.differing_share = finite(j.at("differing_share"));
  d.max_distance = finite(j.at("max_distance"));
  d.mean_distance = finite(j.at("mean_distance"));
  d.antialiased_pixels = j.at("antialiased_pixels").get<std::size_t>();
  d.shifted_pixels = j.at("shifted_pixels").get<std::size_t>();
  d.threshold = finite(j.at("threshold"));
  return d;
}

json case_json(const CaseResult& r) {
  json accepted = json::array();
  for (const AcceptedReference& a : r.accepted) accepted.push_back({{"file", a.file}, {"renderer", a.renderer}});
  json changes = json::array();
  for (const ObjectChange& c : r.changes) {
    changes.push_back({{"object", c.object}, {"text", c.text}, {"changed", c.changed}});
  }
  return {{"spec", spec_json(r.spec)},
          {"status", name_of(r.status)},
          {"message", r.message},
          {"diff", r.diff ? diff_json(*r.diff) : json(nullptr)},
          {"matched_reference", r.matched_reference},
          {"accepted", accepted},
          {"other_renderer", r.other_renderer},
          {"renderer_difference", r.renderer_difference},
          {"renderer", r.renderer},
          {"changes", changes},
          {"reference_image", r.reference_image},
          {"actual_image", r.actual_image},
          {"diff_image", r.diff_image},
          {"seconds", r.seconds},
          {"render_seconds", r.render_seconds}};
}

CaseResult case_from(const json& j) {
  CaseResult r;
  r.spec = spec_from(j.at("spec"));
  r.status = enum_from(j.at("status"), kStatuses, "status");
  r.message = j.at("message").get<std::string>();
  if (!j.at("diff").is_null()) r.diff = diff_from(j.at("diff"));
  r.matched_reference = j.at("matched_reference").get<std::string>();
  for (const json& a : j.at("accepted")) {
    r.accepted.push_back({a.at("file").get<std::string>(), a.at("renderer").get<std::string>()});
  }
  r.other_renderer = j.at("other_renderer").get<bool>();
  r.renderer_difference = j.at("renderer_difference").get<bool>();
  r.renderer = j.at("renderer").get<std::string>();
  for (const json& c : j.at("changes")) {
    r.changes.push_back(
        {c.at("object").get<std::string>(), c.at("text").get<std::string>(), c.at("changed").get<bool>()});
  }
  r.reference_image = j.at("reference_image").get<std::string>();
  r.actual_image = j.at("actual_image").get<std::string>();
  r.diff_image = j.at("diff_image").get<std::string>();
  r.seconds = finite(j.at("seconds"));
  r.render_seconds = finite(j.at("render_seconds"));
  return r;
}

json summary_json(const RunSummary& s) {
  return {{"title", s.title},
          {"renderer", s.renderer},
          {"seconds", s.seconds},
          {"workers", s.workers},
          {"new_fails", s.new_fails},
          {"shard", {s.shard_k, s.shard_n}},
          {"suite_cases", s.suite_cases}};
}

RunSummary summary_from(const json& j) {
  RunSummary s;
  s.title = j.at("title").get<std::string>();
  s.renderer = j.at("renderer").get<std::string>();
  s.seconds = finite(j.at("seconds"));
  s.workers = j.at("workers").get<int>();
  s.new_fails = j.at("new_fails").get<bool>();
  s.shard_k = j.at("shard").at(0).get<int>();
  s.shard_n = j.at("shard").at(1).get<int>();
  s.suite_cases = j.at("suite_cases").get<std::size_t>();
  if (s.shard_n < 1 || s.shard_k < 1 || s.shard_k > s.shard_n)
    throw ResultsError("expected shard K/N with 1 <= K <= N");
  return s;
}

}  // namespace

std::string results_json(const std::vector<CaseResult>& results, const RunSummary& summary) {
  json cases = json::array();
  for (const CaseResult& r : results) cases.push_back(case_json(r));
  const json j = {{"format", kResultsFormat}, {"summary", summary_json(summary)}, {"cases", cases}};
  return j.dump(1) + "\n";
}

void write_results_file(const std::filesystem::path& report_dir, const std::vector<CaseResult>& results,
                        const RunSummary& summary) {
  std::error_code ec;
  std::filesystem::create_directories(report_dir, ec);
  io::write_file_atomically(report_dir / "results.json", results_json(results, summary));
}

RunResults read_results_file(const std::filesystem::path& file) {
  std::string text;
  try {
    text = read_capped(file, kMaxResultsBytes, "a results file");
  } catch (const std::runtime_error& e) {
    throw ResultsError(e.what());
  }
  return parse_results(text, file.string());
}

RunResults parse_results(const std::string& text, const std::string& name) {
  const std::string& file = name;
  try {
    const json j = json::parse(text);
    if (j.at("format").get<int>() != kResultsFormat) {
      throw ResultsError("format " + j.at("format").dump() + ", this sweep reads format " +
                         std::to_string(kResultsFormat));
    }
    RunResults out;
    out.summary = summary_from(j.at("summary"));
    for (const json& c : j.at("cases")) out.cases.push_back(case_from(c));
    return out;
  } catch (const ResultsError& e) {
    throw ResultsError(file + ": " + e.what());
  } catch (const json::exception& e) {
    throw ResultsError(file + ": not a results file of sweep snapshot: " + e.what());
  }
}

}  // namespace sweep::snapshot
