#include "snapshot/report.hpp"

#include "io/files/xml_text.hpp"
#include "snapshot/report_assets.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

// The HTML report: one self-contained page (its style and script inline, so it can be opened from
// a CI artifact without a server or network), the images beside it. Cases that need looking at
// come first with everything known about them; passes close the page as a compact list, so a
// suite of hundreds stays readable. Every text from the run (names, paths, messages, the renderer
// string) is escaped: names and messages come from users' files.

namespace sweep::snapshot {
namespace {

// What the page lists first: what needs looking at.
constexpr std::array<Status, kStatusCount> kPageOrder = {Status::Fail, Status::Error,   Status::Warning,
                                                         Status::New,  Status::Updated, Status::Pass};

std::size_t page_rank(Status status) {
  return static_cast<std::size_t>(std::find(kPageOrder.begin(), kPageOrder.end(), status) - kPageOrder.begin());
}

// The status as a CSS class and filter key: its name in lower case (name_of spells a failure "FAIL").
std::string key_of(Status status) {
  std::string key = name_of(status);
  for (char& c : key) c = char(std::tolower(static_cast<unsigned char>(c)));
  return key;
}

// An image's relative path as a URL: a name with a space, '#', '?' or '%' still finds its file.
std::string url_of(std::string_view path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : path) {
    const auto byte = static_cast<unsigned char>(c);
    const bool plain = (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z') || (byte >= '0' && byte <= '9') ||
                       c == '-' || c == '_' || c == '.' || c == '~' || c == '/';
    if (plain) {
      out += c;
    } else {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string html_percent(double share) {
  return percent(share, {"&lt; ", "&#8201;"});
}

std::string duration(double seconds) {
  if (seconds < 10.0) return fixed(seconds, 2) + " s";
  if (seconds < 60.0) return fixed(seconds, 1) + " s";
  const auto whole = static_cast<long>(seconds + 0.5);
  char text[64];
  std::snprintf(text, sizeof text, "%ld min %02ld s", whole / 60, whole % 60);
  return text;
}

std::string count_of(int n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string local_time_now() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &local);
  return text;
}

struct ImageSize {
  int width = 320;
  int height = 240;
  int scale = 2;  // small renders are enlarged so single pixels can be seen
};

ImageSize display_size(const CaseResult& result) {
  ImageSize size;
  if (result.diff && result.diff->same_size && result.diff->width > 0) {
    size.width = result.diff->width;
    size.height = result.diff->height;
  } else if (result.spec.size.x > 0 && result.spec.size.y > 0) {
    size.width = result.spec.size.x;
    size.height = result.spec.size.y;
  }
  size.scale = size.width <= 400 ? 2 : 1;
  return size;
}

std::string file_of(const CaseResult& result) {
  return (result.spec.relative.empty() ? result.spec.file : result.spec.relative).generic_string();
}

void append_where(std::string& html, const CaseResult& result) {
  const CaseSpec& spec = result.spec;
  html += "<p class=\"where\"><span class=\"mono\">" + io::xml_escaped(file_of(result)) + "</span><span>" +
          name_of(spec.mode) + "</span><span>view " + name_of(spec.view.name) + "</span>";
  if (spec.color != render::ColorMode::Material) html += "<span>colour " + std::string(name_of(spec.color)) + "</span>";
  html += "<span>" + std::to_string(spec.size.x) + "&#215;" + std::to_string(spec.size.y) + "</span>";
  if (!spec.suite_location.empty()) html += "<span class=\"mono\">" + io::xml_escaped(spec.suite_location) + "</span>";
  html += "</p>\n";
}

std::string img_tag(const std::string& file, const char* alt, const ImageSize& size) {
  return "<img src=\"" + io::xml_escaped(url_of(file)) + "\" alt=\"" + alt + "\" width=\"" +
         std::to_string(size.width * size.scale) + "\" height=\"" + std::to_string(size.height * size.scale) + "\">";
}

// Reference over actual: the slider sets how much of the reference (from the left) covers the
// actual; flicker alternates the two whole.
void append_comparison(std::string& html, const CaseResult& result, const ImageSize& size) {
  const int width = size.width * size.scale;
  html +=
      "<div class=\"compare\">\n<div class=\"stage\" data-show=\"reference\" style=\"width:" + std::to_string(width) +
      "px;aspect-ratio:" + std::to_string(size.width) + "/" + std::to_string(size.height) + "\">" +
      img_tag(result.actual_image, "actual", size) + "<div class=\"wipe-top\" style=\"width:50%\">" +
      img_tag(result.reference_image, "reference", size) +
      "</div><span class=\"tag tag-left\">reference</span><span class=\"tag tag-right\">actual</span></div>\n"
      "<div class=\"controls\"><input type=\"range\" class=\"wipe\" min=\"0\" max=\"100\" value=\"50\" "
      "aria-label=\"wipe between reference (left) and actual (right)\"><button type=\"button\" class=\"flicker\" "
      "aria-pressed=\"false\" title=\"alternate reference and actual every 500 ms (f)\">flicker</button></div>\n"
      "</div>\n";
}

// Which renderers have a reference for the case, this run's marked.
void append_renderers(std::string& html, const CaseResult& result) {
  if (result.accepted.empty()) return;
  html += "<h3>Renderers with a reference</h3>\n<ul class=\"renderers\">\n";
  for (const AcceptedReference& a : result.accepted) {
    const bool mine = a.renderer == result.renderer;
    html += std::string("<li") + (mine ? " class=\"this\"" : "") + "><code>" + io::xml_escaped(a.file) + "</code> " +
            io::xml_escaped(a.renderer.empty() ? "(renderer unknown: no sidecar)" : a.renderer) +
            (mine ? " &#8212; this run's renderer" : "") + "</li>\n";
  }
  if (std::none_of(result.accepted.begin(), result.accepted.end(),
                   [&](const AcceptedReference& a) { return a.renderer == result.renderer; })) {
    html += "<li class=\"this\">none from this run's renderer, " + io::xml_escaped(result.renderer) + "</li>\n";
  }
  html += "</ul>\n";
}

// What each colour of the heat map means (image_diff.hpp, heat_map).
void append_legend(std::string& html) {
  static constexpr const char* kKeys[][2] = {
      {"rgb(72,72,72)", "same colour (the reference, dimmed)"},
      {"rgb(106,36,146)", "changed pixels: the colour changed, not past the threshold"},
      {"linear-gradient(90deg,rgb(255,255,0),rgb(255,0,0))",
       "differing pixels: over the threshold (yellow) to the farthest colour (red)"},
      {"rgb(36,36,160)", "forgiven: an anti-aliased edge"},
      {"rgb(36,160,36)", "forgiven: a one-pixel shift"}};
  html += "<ul class=\"legend\" aria-label=\"heat map colours\">";
  for (const auto& [colour, meaning] : kKeys) {
    html += std::string("<li><span class=\"swatch\" style=\"background:") + colour + "\"></span>" + meaning + "</li>";
  }
  html += "</ul>\n";
}

void append_numbers(std::string& html, const CaseResult& result) {
  const bool has_reference = !result.matched_reference.empty();
  if (!result.diff && !has_reference && !result.other_renderer) return;
  html += "<h3>Comparison</h3>\n<dl class=\"numbers\">\n";
  if (result.diff) {
    const ImageDiff& diff = *result.diff;
    const DiffLimits& limits = result.spec.limits;
    if (!diff.same_size) {
      html += "<dt>size</dt><dd>" + io::xml_escaped(diff.summary()) + "</dd>\n";
    } else {
      const auto pixels = static_cast<std::size_t>(diff.width) * static_cast<std::size_t>(diff.height);
      html += "<dt>differing pixels</dt><dd><b>" + grouped_count(diff.differing_pixels) + "</b> of " +
              grouped_count(pixels) + " (" + html_percent(diff.differing_share) + ")<span class=\"limit\">allowed " +
              grouped_count(limits.max_diff_pixels) + " pixels";
      if (limits.max_diff_ratio < 1.0) html += ", " + html_percent(limits.max_diff_ratio);
      html += "</span></dd>\n<dt>changed pixels</dt><dd>" + grouped_count(diff.changed_pixels) +
              "<span class=\"limit\">the colour changed at all</span></dd>\n<dt>colour distance</dt><dd>largest " +
              fixed(diff.max_distance, 3) + ", mean " + fixed(diff.mean_distance, 3) +
              "<span class=\"limit\">threshold " + fixed(result.spec.diff.threshold, 3) +
              "</span></dd>\n<dt>forgiven</dt><dd>" + grouped_count(diff.antialiased_pixels) + " anti-aliased, " +
              grouped_count(diff.shifted_pixels) + " shifted</dd>\n";
    }
  }
  if (has_reference) {
    html += std::string("<dt>") + (result.status == Status::Fail ? "closest reference" : "matched reference") +
            "</dt><dd><code>" + io::xml_escaped(result.matched_reference) + "</code><span class=\"limit\">" +
            count_of(int(result.accepted.size()), "accepted reference", "accepted references") + "</span></dd>\n";
  }
  if (result.other_renderer) {
    html += "<dd class=\"note\">reference from another renderer: compared with thresholds</dd>\n";
  }
  html += "</dl>\n";
  append_renderers(html, result);
}

void append_figure(std::string& html, const std::string& file, const char* what, const ImageSize& size) {
  if (file.empty()) return;
  html += "<figure><a href=\"" + io::xml_escaped(url_of(file)) + "\">" + img_tag(file, what, size) +
          "</a><figcaption><span>" + what + "</span><code title=\"" + io::xml_escaped(file) + "\">" +
          io::xml_escaped(file) + "</code></figcaption></figure>\n";
}

void append_case(std::string& html, const CaseResult& result, std::size_t index) {
  const std::string key = key_of(result.status);
  const bool attention =
      result.status == Status::Fail || result.status == Status::Error || result.status == Status::Warning;
  const std::string id = "case-" + std::to_string(index + 1);
  html += "<article class=\"case s-" + key + (attention ? " attention" : "") + "\" id=\"" + id + "\" data-status=\"" +
          key + "\">\n<div class=\"case-head\"><span class=\"badge\">" + io::xml_escaped(name_of(result.status)) +
          "</span><h2 class=\"case-name\"><a href=\"#" + id + "\">" + io::xml_escaped(result.spec.name) +
          "</a></h2><span class=\"case-time\">" + duration(result.seconds) + "</span></div>\n";
  append_where(html, result);
  if (!result.message.empty()) html += "<p class=\"message\">" + io::xml_escaped(result.message) + "</p>\n";

  const ImageSize size = display_size(result);
  const bool comparable = !result.reference_image.empty() && !result.actual_image.empty();
  std::string facts;
  if (!result.changes.empty()) {
    facts += "<h3>Objects</h3>\n<ul class=\"changes\">\n";
    for (const ObjectChange& change : result.changes) {
      facts += std::string("<li") + (change.changed ? " class=\"changed\"" : "") + ">" + io::xml_escaped(change.text) +
               "</li>\n";
    }
    facts += "</ul>\n";
  }
  append_numbers(facts, result);
  if (comparable || !facts.empty()) {
    html += "<div class=\"case-body\">\n";
    if (comparable) append_comparison(html, result, size);
    if (!facts.empty()) html += "<div class=\"facts\">\n" + facts + "</div>\n";
    html += "</div>\n";
  }
  const int figures = (result.reference_image.empty() ? 0 : 1) + (result.actual_image.empty() ? 0 : 1) +
                      (result.diff_image.empty() ? 0 : 1);
  if (figures > 0) {
    // Each at most the enlarged size, all in one row: three side by side share the width.
    html += "<div class=\"trio\" style=\"grid-template-columns:repeat(" + std::to_string(figures) + ",minmax(0," +
            std::to_string(size.width * size.scale) + "px))\">\n";
    append_figure(html, result.reference_image, "reference", size);
    append_figure(html, result.actual_image, "actual", size);
    append_figure(html, result.diff_image, "diff heat map", size);
    html += "</div>\n";
    if (!result.diff_image.empty()) append_legend(html);
  }
  html += "</article>\n";
}

// Open, but one line per case in columns: a few hundred passes stay a short block at the end.
void append_passes(std::string& html, const std::vector<const CaseResult*>& passes) {
  if (passes.empty()) return;
  html += "<details class=\"passes\" open><summary>" +
          count_of(static_cast<int>(passes.size()), "case passed", "cases passed") +
          "<span class=\"hint\">matched an accepted reference</span></summary>\n<ul class=\"pass-grid\">\n";
  for (const CaseResult* result : passes) {
    std::string title = file_of(*result);
    if (!result->message.empty()) title += " \xc2\xb7 " + result->message;
    for (const AcceptedReference& a : result->accepted) title += " \xc2\xb7 " + a.file + ": " + a.renderer;
    html += "<li data-status=\"pass\" title=\"" + io::xml_escaped(title) + "\"><span class=\"pname\">" +
            io::xml_escaped(result->spec.name) + "</span><span class=\"ptime\">" + duration(result->seconds) +
            "</span></li>\n";
  }
  html += "</ul>\n</details>\n";
}

void append_header(std::string& html, const RunSummary& summary, const Totals& totals, std::size_t total) {
  const int failed = totals.failed;
  const std::string verdict = failed > 0
                                  ? "<span class=\"verdict s-fail\">" + std::to_string(failed) + " to look at</span>"
                                  : "<span class=\"verdict s-pass\">all good</span>";
  html += "<header class=\"top\">\n<div class=\"top-row\"><h1>" + io::xml_escaped(summary.title) + "</h1>" + verdict +
          "</div>\n<p class=\"counts\">" + totals_line(totals) + "</p>\n<p class=\"meta\"><span>renderer <code>" +
          io::xml_escaped(summary.renderer) + "</code></span><span>" + duration(summary.seconds) + "</span><span>" +
          count_of(summary.workers, "worker", "workers") + "</span><span>" + local_time_now() +
          "</span></p>\n<div class=\"bar\"><nav class=\"filters\">";
  html += "<button type=\"button\" class=\"s-all\" data-filter=\"all\" aria-pressed=\"true\">all<span class=\"n\">" +
          std::to_string(total) + "</span></button> ";
  for (const Status status : kPageOrder) {
    const int n = totals.of(status);
    html += std::string("<button type=\"button\" class=\"s-") + key_of(status) + "\" data-filter=\"" + key_of(status) +
            "\" aria-pressed=\"false\"" + (n == 0 ? " disabled" : "") + ">" + io::xml_escaped(name_of(status)) +
            "<span class=\"n\">" + std::to_string(n) + "</span></button> ";
  }
  html +=
      "</nav><span class=\"keys\"><kbd>j</kbd> <kbd>k</kbd> next / previous failure &#160; <kbd>f</kbd> "
      "flicker</span></div>\n</header>\n";
}

}  // namespace

void write_html_report(const std::filesystem::path& report_dir, const std::vector<CaseResult>& results,
                       const RunSummary& summary) {
  std::vector<const CaseResult*> ordered;
  ordered.reserve(results.size());
  for (const CaseResult& result : results) ordered.push_back(&result);
  std::stable_sort(ordered.begin(), ordered.end(), [](const CaseResult* a, const CaseResult* b) {
    return page_rank(a->status) < page_rank(b->status);
  });
  const Totals totals = count_results(results, summary);

  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self' file: data:; "
      "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n<title>" +
      io::xml_escaped(summary.title) + " \xe2\x80\x94 " + totals_line(totals) + "</title>\n<style>\n" +
      std::string(report_style()) + "</style>\n</head>\n<body>\n";
  append_header(html, summary, totals, results.size());
  html += "<main>\n";
  if (results.empty()) html += "<p class=\"empty\">No cases ran.</p>\n";
  std::vector<const CaseResult*> passes;
  for (std::size_t i = 0; i < ordered.size(); ++i) {
    if (ordered[i]->status == Status::Pass) {
      passes.push_back(ordered[i]);
    } else {
      append_case(html, *ordered[i], i);
    }
  }
  append_passes(html, passes);
  html += "</main>\n<script>\n" + std::string(report_script()) + "</script>\n</body>\n</html>\n";

  std::error_code error;
  std::filesystem::create_directories(report_dir, error);
  const std::filesystem::path file = report_dir / "index.html";
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(html.data(), static_cast<std::streamsize>(html.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write the HTML report " + file.string());
}

}  // namespace sweep::snapshot
