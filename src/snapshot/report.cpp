#include "snapshot/report.hpp"

#include "io/xml_text.hpp"

#include <algorithm>
#include <array>
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
constexpr std::array<Status, 6> kPageOrder = {Status::Fail, Status::Error,   Status::Warning,
                                              Status::New,  Status::Updated, Status::Pass};

std::size_t page_rank(Status status) {
  return static_cast<std::size_t>(std::find(kPageOrder.begin(), kPageOrder.end(), status) - kPageOrder.begin());
}

// The status as a CSS class and filter key (name_of spells a failure "FAIL").
const char* key_of(Status status) {
  switch (status) {
    case Status::Pass:
      return "pass";
    case Status::Warning:
      return "warning";
    case Status::Fail:
      return "fail";
    case Status::New:
      return "new";
    case Status::Updated:
      return "updated";
    case Status::Error:
      return "error";
  }
  return "error";
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

std::string percent(double share) {
  if (share > 0.0 && share < 0.0001) return "&lt; 0.01&#8201;%";
  return fixed(share * 100.0, 2) + "&#8201;%";
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

struct Counts {
  std::array<int, 6> by_status{};  // indexed by Status
  int of(Status status) const { return by_status[static_cast<std::size_t>(status)]; }
};

Counts count(const std::vector<CaseResult>& results) {
  Counts counts;
  for (const CaseResult& result : results) ++counts.by_status[static_cast<std::size_t>(result.status)];
  return counts;
}

std::string counts_line(const Counts& c) {
  return std::to_string(c.of(Status::Pass)) + " passed, " + std::to_string(c.of(Status::Fail)) + " failed, " +
         std::to_string(c.of(Status::New)) + " new, " + std::to_string(c.of(Status::Updated)) + " updated, " +
         count_of(c.of(Status::Warning), "warning", "warnings") + ", " +
         count_of(c.of(Status::Error), "error", "errors");
}

const char* const kStyle = R"CSS(
:root{color-scheme:dark;--bg:#121418;--panel:#1a1d22;--panel2:#20242a;--line:#2c3139;--text:#dadee4;--muted:#8b929d;
--render:rgb(28,31,36);--accent:#8ab4f8;--fail:#f0565b;--error:#c77dff;--warning:#e9b44c;--new:#58a6ff;
--updated:#3cc4b4;--pass:#4cb86b;--mono:ui-monospace,"SF Mono",Menlo,Consolas,"DejaVu Sans Mono","Liberation Mono",monospace}
*{box-sizing:border-box}
html{background:var(--bg)}
body{margin:0;color:var(--text);font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"Noto Sans","DejaVu Sans",sans-serif}
code,.mono{font-family:var(--mono);font-size:12.5px}
a{color:inherit}
.s-fail{--c:var(--fail)}.s-error{--c:var(--error)}.s-warning{--c:var(--warning)}.s-new{--c:var(--new)}
.s-updated{--c:var(--updated)}.s-pass{--c:var(--pass)}.s-all{--c:var(--text)}
.top{position:sticky;top:0;z-index:3;background:rgba(18,20,24,.95);border-bottom:1px solid var(--line);padding:14px 24px 12px}
.top-row{display:flex;align-items:baseline;gap:14px;flex-wrap:wrap}
h1{font-size:19px;margin:0;font-weight:600;letter-spacing:.01em}
.verdict{font-weight:600;color:var(--c)}
.counts{margin:4px 0 2px;font-size:15px}
.meta{margin:0;color:var(--muted);font-size:12.5px;display:flex;flex-wrap:wrap;gap:4px 18px}
.meta code{color:var(--text)}
.bar{display:flex;align-items:center;gap:8px;flex-wrap:wrap;margin-top:10px}
.filters button,.flicker{font:inherit;font-size:12.5px;color:var(--text);background:var(--panel2);border:1px solid var(--line);
border-radius:6px;padding:4px 10px;cursor:pointer}
.filters button .n{display:inline-block;min-width:1.4em;margin-left:6px;padding:0 5px;border-radius:9px;text-align:center;
background:color-mix(in srgb,var(--c) 22%,transparent);color:var(--c);font-weight:600}
.filters button[aria-pressed=true],.flicker[aria-pressed=true]{border-color:var(--accent);background:#27303d}
.filters button:disabled{opacity:.4;cursor:default}
.keys{margin-left:auto;color:var(--muted);font-size:12px}
kbd{font:11px var(--mono);border:1px solid var(--line);border-bottom-width:2px;border-radius:4px;padding:0 4px;background:var(--panel2)}
main{padding:20px 24px 56px;max-width:1500px;margin:0 auto}
.empty{color:var(--muted)}
.case{background:var(--panel);border:1px solid var(--line);border-left:4px solid var(--c);border-radius:8px;padding:14px 18px 16px;
margin:0 0 18px;scroll-margin-top:150px}
.case.current{box-shadow:0 0 0 2px var(--accent)}
.case-head{display:flex;align-items:center;gap:10px;flex-wrap:wrap}
.badge{font:700 11px/1 var(--mono);letter-spacing:.05em;padding:4px 7px;border-radius:4px;color:#101215;background:var(--c)}
.case-name{font:600 16px/1.3 var(--mono);margin:0;word-break:break-all}
.case-name a{text-decoration:none}
.case-name a:hover{text-decoration:underline}
.case-time{margin-left:auto;color:var(--muted);font-size:12.5px}
.where{margin:4px 0 0;color:var(--muted);font-size:12.5px}
.where span+span::before{content:"\00b7";margin:0 7px;color:#5b616b}
.message{margin:10px 0 0;padding:8px 12px;background:var(--panel2);border-radius:6px;border-left:2px solid var(--c);
white-space:pre-wrap;word-break:break-word}
.case-body{display:flex;gap:22px;align-items:flex-start;margin-top:14px;flex-wrap:wrap}
.facts{flex:1 1 300px;min-width:0}
.facts h3{margin:0 0 6px;font-size:11.5px;font-weight:600;letter-spacing:.08em;text-transform:uppercase;color:var(--muted)}
.facts h3+*{margin-top:0}
.changes{list-style:none;margin:0 0 16px;padding:0}
.changes li{padding:5px 10px;border-radius:5px;margin-bottom:3px;color:var(--muted);word-break:break-word}
.changes li::before{content:"\2022";display:inline-block;width:1.1em;color:#5b616b}
.changes li.changed{color:var(--text);background:color-mix(in srgb,var(--c) 13%,transparent)}
.changes li.changed::before{content:"\25b8";color:var(--c)}
.numbers{display:grid;grid-template-columns:max-content 1fr;gap:5px 16px;margin:0}
.numbers dt{color:var(--muted)}
.numbers dd{margin:0;font-variant-numeric:tabular-nums}
.numbers .limit{color:var(--muted);margin-left:8px;font-size:12.5px}
.numbers .note{grid-column:1/-1;color:var(--warning);font-size:13px}
.compare{flex:0 1 auto;max-width:100%}
.stage{position:relative;max-width:100%;background:var(--render);box-shadow:0 0 0 1px var(--line);border-radius:4px;overflow:hidden;
container-type:inline-size;user-select:none}
.stage img{display:block;width:100%;height:100%}
.wipe-top{position:absolute;top:0;bottom:0;left:0;overflow:hidden}
.wipe-top img{width:100cqw;max-width:none}
.wipe-top::after{content:"";position:absolute;top:0;bottom:0;right:0;width:2px;background:rgba(255,255,255,.9);
box-shadow:0 0 3px rgba(0,0,0,.8)}
.tag,.stage.flickering::after{position:absolute;top:8px;font:600 11px/1 var(--mono);padding:4px 6px;border-radius:4px;
background:rgba(10,12,15,.72);color:#e8ebef;pointer-events:none}
.tag-left{left:8px}.tag-right{right:8px}
.stage.flickering .wipe-top{width:100%!important}
.stage.flickering .wipe-top::after,.stage.flickering .tag{display:none}
.stage.flickering[data-show=actual] .wipe-top{visibility:hidden}
.stage.flickering::after{content:attr(data-show);left:8px}
.controls{display:flex;align-items:center;gap:10px;margin-top:8px;color:var(--muted);font-size:12.5px}
.controls input{flex:1;accent-color:var(--accent)}
img{image-rendering:pixelated}
.trio{display:grid;gap:14px;margin-top:16px}
.trio figure{margin:0;min-width:0}
.trio a{display:block;background:var(--render);box-shadow:0 0 0 1px var(--line);border-radius:4px;overflow:hidden}
.trio img{display:block;width:100%;height:auto}
figcaption{margin-top:5px;color:var(--muted);font-size:12.5px;display:flex;gap:8px;align-items:baseline}
figcaption span{white-space:nowrap}
figcaption code{color:var(--text);overflow:hidden;text-overflow:ellipsis;white-space:nowrap}
.passes{background:var(--panel);border:1px solid var(--line);border-left:4px solid var(--pass);border-radius:8px;padding:12px 18px}
.passes summary{cursor:pointer;font-weight:600}
.passes summary .hint{color:var(--muted);font-weight:400;margin-left:8px;font-size:12.5px}
.pass-grid{list-style:none;margin:12px 0 2px;padding:0;display:grid;grid-template-columns:repeat(auto-fill,minmax(250px,1fr));
gap:2px 18px}
.pass-grid li{display:flex;gap:8px;padding:3px 0;border-bottom:1px solid #23272e;font:12.5px/1.4 var(--mono);min-width:0}
.pass-grid .pname{overflow:hidden;text-overflow:ellipsis;white-space:nowrap}
.pass-grid .pname::before{content:"\2713";color:var(--pass);margin-right:7px}
.pass-grid .ptime{margin-left:auto;color:var(--muted)}
[hidden]{display:none!important}
)CSS";

// The widgets (wipe slider, flicker), the filters, j/k, and the self-test a headless browser runs
// at #selftest: it counts the images that loaded, drives the first slider to both ends and the
// first flicker toggle, and writes what it found into body[data-selftest] and the title.
const char* const kScript = R"JS(
(() => {
  'use strict';
  const wipe = (stage, value) => { stage.querySelector('.wipe-top').style.width = value + '%'; };
  const flicker = (compare, on) => {
    const stage = compare.querySelector('.stage');
    const button = compare.querySelector('.flicker');
    clearInterval(compare.flickerTimer);
    compare.flickerTimer = 0;
    stage.classList.toggle('flickering', on);
    stage.dataset.show = 'reference';
    button.setAttribute('aria-pressed', String(on));
    compare.querySelector('input.wipe').disabled = on;
    if (on) {
      compare.flickerTimer = setInterval(() => {
        stage.dataset.show = stage.dataset.show === 'reference' ? 'actual' : 'reference';
      }, 500);
    }
  };
  for (const compare of document.querySelectorAll('.compare')) {
    const slider = compare.querySelector('input.wipe');
    const stage = compare.querySelector('.stage');
    slider.addEventListener('input', () => wipe(stage, slider.value));
    wipe(stage, slider.value);
    compare.querySelector('.flicker').addEventListener('click', () => flicker(compare, !compare.flickerTimer));
  }

  const buttons = [...document.querySelectorAll('.filters button')];
  const passes = document.querySelector('.passes');
  const show = (status) => {
    for (const b of buttons) b.setAttribute('aria-pressed', String(b.dataset.filter === status));
    for (const el of document.querySelectorAll('[data-status]')) {
      el.hidden = status !== 'all' && el.dataset.status !== status;
    }
    if (passes) {
      passes.hidden = status !== 'all' && status !== 'pass';
      if (status === 'pass') passes.open = true;
    }
  };
  for (const b of buttons) b.addEventListener('click', () => show(b.dataset.filter));

  let current = null;
  document.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const cards = [...document.querySelectorAll('.case.attention')].filter((c) => !c.hidden);
    if ((e.key === 'j' || e.key === 'k') && cards.length) {
      const at = cards.indexOf(current);
      const next = e.key === 'j' ? Math.min(at + 1, cards.length - 1) : Math.max(at < 0 ? 0 : at - 1, 0);
      if (current) current.classList.remove('current');
      current = cards[next];
      current.classList.add('current');
      current.scrollIntoView({block: 'start'});
    } else if (e.key === 'f' && current) {
      const compare = current.querySelector('.compare');
      if (compare) flicker(compare, !compare.flickerTimer);
    }
  });

  const selftest = () => {
    const images = [...document.images];
    const loaded = images.filter((img) => img.complete && img.naturalWidth > 0).length;
    const found = ['images ' + loaded + '/' + images.length + ' loaded'];
    const compare = document.querySelector('.compare');
    const finish = () => {
      const result = found.join('; ');
      document.body.dataset.selftest = result;
      document.title = result;
    };
    if (!compare) {
      found.push('no slider');
      finish();
      return;
    }
    const slider = compare.querySelector('input.wipe');
    const stage = compare.querySelector('.stage');
    const top = compare.querySelector('.wipe-top');
    const shown = (value) => {
      slider.value = String(value);
      slider.dispatchEvent(new Event('input'));
      return top.getBoundingClientRect().width;
    };
    const full = stage.clientWidth;
    const atZero = shown(0);
    const atHundred = shown(100);
    const topImage = top.querySelector('img').getBoundingClientRect().width;
    shown(50);
    const sliderOk = full > 0 && atZero < 1 && Math.abs(atHundred - full) < 1.5 && Math.abs(topImage - full) < 1.5;
    found.push(sliderOk ? 'slider ok'
                        : 'slider failed (0: ' + atZero + ' px, 100: ' + atHundred + ' px, image ' + topImage +
                              ' px of ' + full + ' px)');
    compare.querySelector('.flicker').click();
    const first = getComputedStyle(top).visibility;
    setTimeout(() => {
      const second = getComputedStyle(top).visibility;
      compare.querySelector('.flicker').click();
      found.push(first === 'visible' && second === 'hidden' ? 'flicker ok'
                                                            : 'flicker failed (' + first + ', then ' + second + ')');
      finish();
    }, 600);
  };
  if (location.hash === '#selftest') {
    if (document.readyState === 'complete') selftest();
    else window.addEventListener('load', selftest);
  }
})();
)JS";

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
  html += "<p class=\"where\"><span class=\"mono\">" + xml_escaped(file_of(result)) + "</span><span>" +
          name_of(spec.mode) + "</span><span>view " + xml_escaped(spec.view.name) + "</span>";
  if (spec.color != "material") html += "<span>colour " + xml_escaped(spec.color) + "</span>";
  html += "<span>" + std::to_string(spec.size.x) + "&#215;" + std::to_string(spec.size.y) + "</span>";
  if (!spec.suite_location.empty()) html += "<span class=\"mono\">" + xml_escaped(spec.suite_location) + "</span>";
  html += "</p>\n";
}

std::string img_tag(const std::string& file, const char* alt, const ImageSize& size) {
  return "<img src=\"" + xml_escaped(url_of(file)) + "\" alt=\"" + alt + "\" width=\"" +
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

void append_numbers(std::string& html, const CaseResult& result) {
  const bool has_reference = !result.matched_reference.empty();
  if (!result.diff && !has_reference && !result.other_renderer) return;
  html += "<h3>Comparison</h3>\n<dl class=\"numbers\">\n";
  if (result.diff) {
    const ImageDiff& diff = *result.diff;
    const DiffLimits& limits = result.spec.limits;
    if (!diff.same_size) {
      html += "<dt>size</dt><dd>" + xml_escaped(diff.summary()) + "</dd>\n";
    } else {
      const auto pixels = static_cast<std::size_t>(diff.width) * static_cast<std::size_t>(diff.height);
      html += "<dt>differing pixels</dt><dd><b>" + grouped_count(diff.differing_pixels) + "</b> of " +
              grouped_count(pixels) + " (" + percent(diff.differing_share) + ")<span class=\"limit\">allowed " +
              grouped_count(limits.max_diff_pixels) + " px";
      if (limits.max_diff_ratio < 1.0) html += ", " + percent(limits.max_diff_ratio);
      html += "</span></dd>\n<dt>colour distance</dt><dd>largest " + fixed(diff.max_distance, 3) + ", mean " +
              fixed(diff.mean_distance, 3) + "<span class=\"limit\">threshold " + fixed(result.spec.diff.threshold, 3) +
              "</span></dd>\n<dt>forgiven</dt><dd>" + grouped_count(diff.antialiased_pixels) + " anti-aliased, " +
              grouped_count(diff.shifted_pixels) + " shifted</dd>\n";
    }
  }
  if (has_reference) {
    html += std::string("<dt>") + (result.status == Status::Fail ? "closest reference" : "matched reference") +
            "</dt><dd><code>" + xml_escaped(result.matched_reference) + "</code><span class=\"limit\">" +
            count_of(result.references, "accepted reference", "accepted references") + "</span></dd>\n";
  }
  if (result.other_renderer) {
    html += "<dd class=\"note\">reference from another renderer: compared with thresholds</dd>\n";
  }
  html += "</dl>\n";
}

void append_figure(std::string& html, const std::string& file, const char* what, const ImageSize& size) {
  if (file.empty()) return;
  html += "<figure><a href=\"" + xml_escaped(url_of(file)) + "\">" + img_tag(file, what, size) +
          "</a><figcaption><span>" + what + "</span><code title=\"" + xml_escaped(file) + "\">" + xml_escaped(file) +
          "</code></figcaption></figure>\n";
}

void append_case(std::string& html, const CaseResult& result, std::size_t index) {
  const std::string key = key_of(result.status);
  const bool attention =
      result.status == Status::Fail || result.status == Status::Error || result.status == Status::Warning;
  const std::string id = "case-" + std::to_string(index + 1);
  html += "<article class=\"case s-" + key + (attention ? " attention" : "") + "\" id=\"" + id + "\" data-status=\"" +
          key + "\">\n<div class=\"case-head\"><span class=\"badge\">" + xml_escaped(name_of(result.status)) +
          "</span><h2 class=\"case-name\"><a href=\"#" + id + "\">" + xml_escaped(result.spec.name) +
          "</a></h2><span class=\"case-time\">" + duration(result.seconds) + "</span></div>\n";
  append_where(html, result);
  if (!result.message.empty()) html += "<p class=\"message\">" + xml_escaped(result.message) + "</p>\n";

  const ImageSize size = display_size(result);
  const bool comparable = !result.reference_image.empty() && !result.actual_image.empty();
  std::string facts;
  if (!result.changes.empty()) {
    facts += "<h3>Objects</h3>\n<ul class=\"changes\">\n";
    for (const ObjectChange& change : result.changes) {
      facts += std::string("<li") + (change.changed ? " class=\"changed\"" : "") + ">" + xml_escaped(change.text) +
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
    html += "<li data-status=\"pass\" title=\"" + xml_escaped(title) + "\"><span class=\"pname\">" +
            xml_escaped(result->spec.name) + "</span><span class=\"ptime\">" + duration(result->seconds) +
            "</span></li>\n";
  }
  html += "</ul>\n</details>\n";
}

void append_header(std::string& html, const RunSummary& summary, const Counts& counts, std::size_t total) {
  const int failed = counts.of(Status::Fail) + counts.of(Status::Error);
  const std::string verdict = failed > 0
                                  ? "<span class=\"verdict s-fail\">" + std::to_string(failed) + " to look at</span>"
                                  : "<span class=\"verdict s-pass\">all good</span>";
  html += "<header class=\"top\">\n<div class=\"top-row\"><h1>" + xml_escaped(summary.title) + "</h1>" + verdict +
          "</div>\n<p class=\"counts\">" + counts_line(counts) + "</p>\n<p class=\"meta\"><span>renderer <code>" +
          xml_escaped(summary.renderer) + "</code></span><span>" + duration(summary.seconds) + "</span><span>" +
          count_of(summary.workers, "worker", "workers") + "</span><span>" + local_time_now() +
          "</span></p>\n<div class=\"bar\"><nav class=\"filters\">";
  html += "<button type=\"button\" class=\"s-all\" data-filter=\"all\" aria-pressed=\"true\">all<span class=\"n\">" +
          std::to_string(total) + "</span></button> ";
  for (const Status status : kPageOrder) {
    const int n = counts.of(status);
    html += std::string("<button type=\"button\" class=\"s-") + key_of(status) + "\" data-filter=\"" + key_of(status) +
            "\" aria-pressed=\"false\"" + (n == 0 ? " disabled" : "") + ">" + xml_escaped(name_of(status)) +
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
  const Counts counts = count(results);

  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src 'self' file: data:; "
      "style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n<title>" +
      xml_escaped(summary.title) + " \xe2\x80\x94 " + counts_line(counts) + "</title>\n<style>" + kStyle +
      "</style>\n</head>\n<body>\n";
  append_header(html, summary, counts, results.size());
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
  html += "</main>\n<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";

  std::error_code error;
  std::filesystem::create_directories(report_dir, error);
  const std::filesystem::path file = report_dir / "index.html";
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(html.data(), static_cast<std::streamsize>(html.size()));
  out.close();
  if (!out) throw std::runtime_error("cannot write the HTML report " + file.string());
}

}  // namespace sweep::snapshot
