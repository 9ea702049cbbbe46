// The reports of `sweep snapshot`: the HTML page (order, escaping, images, counts, numbers, no
// network), read as text and, when chromium is installed, loaded in a real headless browser whose
// self-test (#selftest) says whether every image loaded and the slider and flicker work; and the
// JUnit XML, read back with tinyxml2.
#include "snapshot/report.hpp"

#include "support/file_support.hpp"

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <tinyxml2.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 80;
constexpr int kHeight = 60;

fs::path output_folder(const std::string& name) {
  const fs::path folder = fs::absolute(fs::path(SWEEP_TEST_OUTPUT_DIR) / "report" / name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

using Shade = std::function<std::array<std::uint8_t, 3>(int x, int y)>;

void write_png(const fs::path& file, const Shade& shade) {
  fs::create_directories(file.parent_path());
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto pixel = shade(x, y);
      rgb.insert(rgb.end(), pixel.begin(), pixel.end());
    }
  }
  ASSERT_NE(stbi_write_png(file.c_str(), kWidth, kHeight, 3, rgb.data(), kWidth * 3), 0) << file;
}

// A dark render background with a grey disc; the actual image's disc sits 6 pixels lower.
Shade render_shade(int disc_y) {
  return [disc_y](int x, int y) -> std::array<std::uint8_t, 3> {
    const int dx = x - kWidth / 2;
    const int dy = y - disc_y;
    if (dx * dx + dy * dy < 18 * 18) return {170, 176, 186};
    return {28, 31, 36};
  };
}

Shade heat_shade() {
  return [](int x, int y) -> std::array<std::uint8_t, 3> {
    if (y > 20 && y < 44 && x > 20 && x < 60) return {230, 60, 40};
    return {60, 60, 60};
  };
}

void write_images(const fs::path& report_dir, const CaseResult& result) {
  if (!result.reference_image.empty()) write_png(report_dir / result.reference_image, render_shade(26));
  if (!result.actual_image.empty()) write_png(report_dir / result.actual_image, render_shade(32));
  if (!result.diff_image.empty()) write_png(report_dir / result.diff_image, heat_shade());
}

CaseResult make_case(const std::string& name, const std::string& file, Status status, const std::string& message) {
  CaseResult result;
  result.spec.name = name;
  result.spec.file = fs::path("/models") / file;
  result.spec.relative = file;
  result.spec.size = {kWidth, kHeight};
  result.status = status;
  result.message = message;
  result.seconds = 0.25;
  return result;
}

ImageDiff make_diff(std::size_t differing) {
  ImageDiff diff;
  diff.same_size = true;
  diff.width = kWidth;
  diff.height = kHeight;
  diff.differing_pixels = differing;
  diff.changed_pixels = differing + 2000;
  diff.differing_share = static_cast<double>(differing) / (kWidth * kHeight);
  diff.max_distance = 0.82;
  diff.mean_distance = 0.41;
  diff.antialiased_pixels = 312;
  diff.shifted_pixels = 45;
  return diff;
}

const char* const kScriptName = "<script>alert(1)</script>-smooth";

// One case of each status (passes first, to see the page reorder them), their images written.
std::vector<CaseResult> example_results(const fs::path& report_dir) {
  std::vector<CaseResult> results;
  results.push_back(make_case("cup-smooth", "cup.swp", Status::Pass, "matches cup-smooth.png"));
  results.push_back(make_case(kScriptName, "odd/<b>.swp", Status::Pass, "matches \"it\" & more"));

  CaseResult fail =
      make_case("bowl-smooth", "kitchen/bowl.swp", Status::Fail, "1,204 pixels differ (25.08%) & only 8 <allowed>");
  fail.diff = make_diff(1204);
  fail.matched_reference = "bowl-smooth_1.png";
  fail.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  fail.accepted = {{"bowl-smooth.png", "softpipe"}, {"bowl-smooth_1.png", "llvmpipe (LLVM 15.0.6, 256 bits)"}};
  fail.changes = {{"bowl", "bowl: 1,204 pixels differ; its mesh moved up to 0.031 (bounding box +0.03 in y)", true},
                  {"table", "table: unchanged", false},
                  {"odd", "<img src=x onerror=alert(2)>: 3 pixels differ", true}};
  fail.reference_image = "fail/bowl-smooth.reference.png";
  fail.actual_image = "fail/bowl-smooth.actual.png";
  fail.diff_image = "fail/bowl-smooth.diff.png";
  results.push_back(fail);

  results.push_back(make_case("lamp-frames", "lamp.swp", Status::New, "new: wrote lamp-frames.png"));
  results.back().actual_image = "new/lamp-frames.png";

  results.push_back(make_case("broken-smooth", "broken.swp", Status::Error, "broken.swp:3: expected a number"));

  CaseResult warning = make_case("vase-wire", "vase.swp", Status::Warning, "passes by thresholds: 3 pixels differ");
  warning.diff = make_diff(3);
  warning.other_renderer = true;
  warning.matched_reference = "vase-wire.png";
  warning.accepted = {{"vase-wire.png", "softpipe"}};
  warning.changes = {{"vase", "vase: 3 pixels differ", true}};
  warning.reference_image = "warn ings/vase-wire #1.reference.png";  // needs URL escaping
  warning.actual_image = "warn ings/vase-wire #1.actual.png";
  warning.diff_image = "warn ings/vase-wire #1.diff.png";
  results.push_back(warning);

  results.push_back(make_case("cup-wire", "cup.swp", Status::Updated, "updated cup-wire.png"));
  results.back().reference_image = "updated/cup-wire.old.png";
  results.back().actual_image = "updated/cup-wire.png";

  for (const CaseResult& result : results) write_images(report_dir, result);
  return results;
}

RunSummary example_summary() {
  return {"sweep snapshot models/", "llvmpipe (LLVM 15.0.6, 256 bits)", 12.5, 2};
}

std::string write_example_page(const fs::path& report_dir) {
  write_html_report(report_dir, example_results(report_dir), example_summary());
  return test::read_file(report_dir / "index.html");
}

// Where the case's card (or pass entry) starts: its escaped name's first place in the page.
std::size_t place_of(const std::string& page, const std::string& escaped_name) {
  const std::size_t at = page.find(">" + escaped_name + "<");
  EXPECT_NE(at, std::string::npos) << escaped_name;
  return at;
}

/// "%20" and "%23" (what the report encodes in image names) as a space and '#'.
std::string url_decoded(const std::string& url) {
  std::string out;
  for (std::size_t i = 0; i < url.size(); ++i) {
    if (url.compare(i, 3, "%20") == 0 || url.compare(i, 3, "%23") == 0) {
      out.push_back(url[i + 2] == '0' ? ' ' : '#');
      i += 2;
    } else {
      out.push_back(url[i]);
    }
  }
  return out;
}

TEST(HtmlReport, ListsWhatNeedsLookingAtFirstAndPassesLast) {
  const std::string page = write_example_page(output_folder("order"));
  const std::vector<std::string> order = {"bowl-smooth", "broken-smooth", "vase-wire",
                                          "lamp-frames", "cup-wire",      "cup-smooth"};
  for (std::size_t i = 1; i < order.size(); ++i) {
    EXPECT_LT(place_of(page, order[i - 1]), place_of(page, order[i])) << order[i - 1] << " before " << order[i];
  }
  // The passes are a compact list, not cards.
  EXPECT_EQ(page.find("data-status=\"pass\"", page.find("<details class=\"passes\"")),
            page.find("data-status=\"pass\""));
  EXPECT_EQ(page.find("<article class=\"case s-pass"), std::string::npos);
}

TEST(HtmlReport, EscapesTextFromUserFiles) {
  const std::string page = write_example_page(output_folder("escape"));
  EXPECT_NE(page.find("&lt;script&gt;alert(1)&lt;/script&gt;-smooth"), std::string::npos);
  EXPECT_EQ(page.find("<script>alert"), std::string::npos);
  EXPECT_NE(page.find("&lt;img src=x onerror=alert(2)&gt;: 3 pixels differ"), std::string::npos);
  EXPECT_EQ(page.find("<img src=x"), std::string::npos);
  EXPECT_NE(page.find("1,204 pixels differ (25.08%) &amp; only 8 &lt;allowed&gt;"), std::string::npos);
  EXPECT_NE(page.find("odd/&lt;b&gt;.swp"), std::string::npos);
  EXPECT_NE(page.find("&quot;it&quot; &amp; more"), std::string::npos);  // in the pass entry's title
  // The page's own script is the only one.
  std::size_t scripts = 0;
  for (std::size_t at = page.find("<script"); at != std::string::npos; at = page.find("<script", at + 1)) ++scripts;
  EXPECT_EQ(scripts, 1u);
}

TEST(HtmlReport, ShowsEveryImageTheResultsNameAndNoOther) {
  const fs::path dir = output_folder("images");
  const std::string page = write_example_page(dir);
  for (const char* name : {"fail/bowl-smooth.reference.png", "fail/bowl-smooth.actual.png", "fail/bowl-smooth.diff.png",
                           "new/lamp-frames.png", "updated/cup-wire.old.png", "updated/cup-wire.png"}) {
    EXPECT_NE(page.find(std::string("src=\"") + name + "\""), std::string::npos) << name;
  }
  for (const char* name : {"reference", "actual", "diff"}) {
    const std::string url = std::string("warn%20ings/vase-wire%20%231.") + name + ".png";
    EXPECT_NE(page.find("src=\"" + url + "\""), std::string::npos) << url;
  }
  // Every image the page shows is a file beside it (the URL decoded).
  // (No std::regex: GCC 12 warns maybe-uninitialized inside it in the sanitizer build.)
  std::set<std::string> shown;
  for (std::size_t at = page.find("src=\""); at != std::string::npos; at = page.find("src=\"", at + 1)) {
    const std::size_t begin = at + 5;
    std::string file = page.substr(begin, page.find('"', begin) - begin);
    file = url_decoded(file);
    EXPECT_TRUE(fs::is_regular_file(dir / file)) << file;
    shown.insert(file);
  }
  EXPECT_EQ(shown.size(), 9u);
  // The failure's reference and actual are shown twice more in its slider and flicker widget.
  EXPECT_NE(page.find("<input type=\"range\""), std::string::npos);
  EXPECT_NE(page.find("class=\"flicker\""), std::string::npos);
  EXPECT_NE(page.find("image-rendering:pixelated"), std::string::npos);
  EXPECT_NE(page.find("width=\"160\" height=\"120\""), std::string::npos);  // 80x60 shown 2x
}

TEST(HtmlReport, HeaderCountsTheStatusesAndNamesTheRun) {
  const std::string page = write_example_page(output_folder("header"));
  EXPECT_NE(page.find("<p class=\"counts\">3 passed, 3 failed (1 new, 1 updated, 1 warnings, 1 errors)</p>"),
            std::string::npos);
  EXPECT_NE(page.find("<h1>sweep snapshot models/</h1>"), std::string::npos);
  EXPECT_NE(page.find("llvmpipe (LLVM 15.0.6, 256 bits)"), std::string::npos);
  EXPECT_NE(page.find("12.5 s"), std::string::npos);
  EXPECT_NE(page.find("2 workers"), std::string::npos);
  EXPECT_NE(page.find("data-filter=\"fail\""), std::string::npos);
}

TEST(HtmlReport, ShowsTheAttributionAndTheNumbers) {
  const std::string page = write_example_page(output_folder("numbers"));
  EXPECT_NE(page.find("<li class=\"changed\">bowl: 1,204 pixels differ; its mesh moved up to 0.031"),
            std::string::npos);
  EXPECT_NE(page.find("<li>table: unchanged</li>"), std::string::npos);
  EXPECT_NE(page.find("<b>1,204</b> of 4,800 (25.08&#8201;%)"), std::string::npos);
  EXPECT_NE(page.find("largest 0.820, mean 0.410"), std::string::npos);
  EXPECT_NE(page.find("312 anti-aliased, 45 shifted"), std::string::npos);
  // The two counts of pixels in the terminal's words, and the heat map's colours named.
  EXPECT_NE(page.find("<dt>changed pixels</dt><dd>3,204<span class=\"limit\">the colour changed at all"),
            std::string::npos);
  EXPECT_NE(page.find("changed pixels: the colour changed, not past the threshold"), std::string::npos);
  EXPECT_NE(page.find("differing pixels: over the threshold (yellow) to the farthest colour (red)"), std::string::npos);
  // Which renderers have a reference, this run's marked.
  EXPECT_NE(page.find("<li class=\"this\"><code>bowl-smooth_1.png</code> llvmpipe (LLVM 15.0.6, 256 bits) &#8212; "
                      "this run's renderer</li>"),
            std::string::npos);
  EXPECT_NE(page.find("<code>bowl-smooth_1.png</code><span class=\"limit\">2 accepted references"), std::string::npos);
  EXPECT_NE(page.find("reference from another renderer: compared with thresholds"), std::string::npos);
  EXPECT_NE(page.find(">broken.swp:3: expected a number<"), std::string::npos);
}

TEST(HtmlReport, NeedsNoNetwork) {
  const std::string page = write_example_page(output_folder("offline"));
  for (const char* reference : {"http:", "https:", "<link", "@import", "url(", "src=\"//"}) {
    EXPECT_EQ(page.find(reference), std::string::npos) << reference;
  }
}

TEST(HtmlReport, WithoutCasesSaysSo) {
  const fs::path dir = output_folder("empty");
  write_html_report(dir, {}, example_summary());
  const std::string page = test::read_file(dir / "index.html");
  EXPECT_NE(page.find("0 passed, 0 failed (0 new, 0 updated, 0 warnings, 0 errors)"), std::string::npos);
  EXPECT_NE(page.find("No cases ran."), std::string::npos);
}

TEST(HtmlReport, ThrowsWhenItCannotBeWritten) {
  const fs::path blocker = output_folder("unwritable") / "a-file";
  test::write_text(blocker, "not a folder");
  EXPECT_THROW(write_html_report(blocker / "report", {}, example_summary()), std::runtime_error);
}

struct JunitCase {
  std::string classname, name, time, outcome, message, body;
};

std::vector<JunitCase> read_junit(const fs::path& file, tinyxml2::XMLDocument& document) {
  std::vector<JunitCase> cases;
  EXPECT_EQ(document.LoadFile(file.c_str()), tinyxml2::XML_SUCCESS) << document.ErrorStr();
  const tinyxml2::XMLElement* suite = document.FirstChildElement("testsuite");
  if (suite == nullptr) return cases;
  for (const tinyxml2::XMLElement* test = suite->FirstChildElement("testcase"); test != nullptr;
       test = test->NextSiblingElement("testcase")) {
    JunitCase read{test->Attribute("classname"), test->Attribute("name"), test->Attribute("time"), "", "", ""};
    if (const tinyxml2::XMLElement* outcome = test->FirstChildElement()) {
      read.outcome = outcome->Name();
      if (outcome->Attribute("message")) read.message = outcome->Attribute("message");
      if (outcome->GetText()) read.body = outcome->GetText();
    }
    cases.push_back(read);
  }
  return cases;
}

TEST(JunitReport, CountsAndNamesEveryCase) {
  const fs::path dir = output_folder("junit");
  write_junit(dir / "junit.xml", example_results(dir), example_summary());
  tinyxml2::XMLDocument document;
  const std::vector<JunitCase> cases = read_junit(dir / "junit.xml", document);
  const tinyxml2::XMLElement* suite = document.FirstChildElement("testsuite");
  ASSERT_NE(suite, nullptr);
  EXPECT_STREQ(suite->Attribute("name"), "sweep snapshot");
  EXPECT_EQ(suite->IntAttribute("tests"), 7);
  EXPECT_EQ(suite->IntAttribute("failures"), 2);  // the failure and the new reference nothing accepted
  EXPECT_EQ(suite->IntAttribute("errors"), 1);
  EXPECT_EQ(suite->IntAttribute("skipped"), 0);
  EXPECT_STREQ(suite->Attribute("time"), "12.500");
  ASSERT_EQ(cases.size(), 7u);
  // Run order, classname the SWP file, name the case, an outcome element only for failures and
  // errors, a line of output for the others that are not plain passes.
  const std::vector<std::array<std::string, 3>> expected = {{"cup.swp", "cup-smooth", ""},
                                                            {"odd/<b>.swp", kScriptName, ""},
                                                            {"kitchen/bowl.swp", "bowl-smooth", "failure"},
                                                            {"lamp.swp", "lamp-frames", "failure"},
                                                            {"broken.swp", "broken-smooth", "error"},
                                                            {"vase.swp", "vase-wire", "system-out"},
                                                            {"cup.swp", "cup-wire", "system-out"}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(cases[i].classname, expected[i][0]);
    EXPECT_EQ(cases[i].name, expected[i][1]);
    EXPECT_EQ(cases[i].outcome, expected[i][2]) << cases[i].name;
    EXPECT_EQ(cases[i].time, "0.250");
  }
  EXPECT_EQ(cases[3].message, "new: wrote lamp-frames.png (not accepted: run with --update)");
  EXPECT_NE(cases[5].body.find("reference from another renderer: compared with thresholds"), std::string::npos);
  EXPECT_NE(cases[5].body.find("reference vase-wire.png: softpipe\n"), std::string::npos);
}

TEST(JunitReport, ANewReferenceAcceptedByUpdatePassesWithItsLine) {
  const fs::path dir = output_folder("junit-accepted");
  RunSummary summary = example_summary();
  summary.new_fails = false;  // --update or --update=missing
  write_junit(dir / "junit.xml", example_results(dir), summary);
  tinyxml2::XMLDocument document;
  const std::vector<JunitCase> cases = read_junit(dir / "junit.xml", document);
  EXPECT_EQ(document.FirstChildElement("testsuite")->IntAttribute("failures"), 1);
  ASSERT_EQ(cases.size(), 7u);
  EXPECT_EQ(cases[3].outcome, "system-out");
  EXPECT_EQ(cases[3].body, "new: wrote lamp-frames.png");
}

TEST(JunitReport, FailureCarriesTheMessageAndTheAttribution) {
  const fs::path dir = output_folder("junit-failure");
  write_junit(dir / "junit.xml", example_results(dir), example_summary());
  tinyxml2::XMLDocument document;
  const std::vector<JunitCase> cases = read_junit(dir / "junit.xml", document);
  ASSERT_EQ(cases.size(), 7u);
  EXPECT_EQ(cases[2].message, "1,204 pixels differ (25.08%) & only 8 <allowed>");
  EXPECT_NE(cases[2].body.find("* bowl: 1,204 pixels differ; its mesh moved up to 0.031 (bounding box +0.03 in y)\n"),
            std::string::npos);
  EXPECT_NE(cases[2].body.find("  table: unchanged\n"), std::string::npos);
  EXPECT_NE(cases[2].body.find("* <img src=x onerror=alert(2)>: 3 pixels differ\n"), std::string::npos);
  EXPECT_NE(cases[2].body.find("compared with bowl-smooth_1.png (2 accepted references)"), std::string::npos);
  EXPECT_EQ(cases[4].message, "broken.swp:3: expected a number");
}

TEST(JunitReport, StaysWellFormedWithBytesXmlForbids) {
  const fs::path dir = output_folder("junit-bytes");
  CaseResult result = make_case("bad\x01name", "caf\xc3\xa9.swp", Status::Error, "bad byte \xff and \x1b[31m");
  write_junit(dir / "junit.xml", {result}, example_summary());
  tinyxml2::XMLDocument document;
  const std::vector<JunitCase> cases = read_junit(dir / "junit.xml", document);
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].name, "bad\xef\xbf\xbdname");
  EXPECT_EQ(cases[0].classname, "caf\xc3\xa9.swp");
  EXPECT_EQ(cases[0].message, "bad byte \xef\xbf\xbd and \xef\xbf\xbd[31m");
}

TEST(JunitReport, ThrowsWhenItCannotBeWritten) {
  const fs::path blocker = output_folder("junit-unwritable") / "a-file";
  test::write_text(blocker, "not a folder");
  EXPECT_THROW(write_junit(blocker / "junit.xml", {}, example_summary()), std::runtime_error);
}

// A path for the shell, in single quotes.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A headless chromium run on `url` with its own profile in `dir`; `what` names its log file.
int run_chromium(const fs::path& dir, const std::string& url, const std::string& arguments, const std::string& what) {
  const std::string command =
      "timeout 60 /usr/bin/chromium --headless --no-sandbox --disable-gpu --no-first-run "
      "--user-data-dir=" +
      quoted((dir / ("profile-" + what)).string()) + " " + arguments + " " + quoted(url) + " 2>" +
      quoted((dir / (what + ".log")).string());
  return std::system(command.c_str());
}

TEST(HtmlReport, LoadsEveryImageAndItsWidgetsWorkInARealBrowser) {
  if (!fs::exists("/usr/bin/chromium")) GTEST_SKIP() << "/usr/bin/chromium is not installed";
  const fs::path dir = output_folder("browser");
  const std::string page = write_example_page(dir);
  std::size_t images = 0;
  for (std::size_t at = page.find("<img "); at != std::string::npos; at = page.find("<img ", at + 1)) ++images;
  ASSERT_EQ(images, 15u);  // nine in the figures, six in the three comparison widgets

  const std::string url = "file://" + (dir / "index.html").string();
  ASSERT_EQ(run_chromium(dir, url + "#selftest",
                         "--virtual-time-budget=5000 --dump-dom >" + quoted((dir / "dom.html").string()), "dom"),
            0)
      << test::read_file(dir / "dom.log");
  const std::string dom = test::read_file(dir / "dom.html");
  const std::size_t at = dom.find("data-selftest=\"");
  ASSERT_NE(at, std::string::npos) << dom.substr(0, 2000);
  const std::size_t begin = at + 15;
  EXPECT_EQ(dom.substr(begin, dom.find('"', begin) - begin), "images 15/15 loaded; slider ok; flicker ok");

  const fs::path screenshot = dir / "report.png";
  ASSERT_EQ(
      run_chromium(dir, url, "--hide-scrollbars --window-size=1280,1600 --screenshot=" + quoted(screenshot.string()),
                   "screenshot"),
      0)
      << test::read_file(dir / "screenshot.log");
  EXPECT_EQ(test::read_file(screenshot).substr(0, 8), "\x89PNG\r\n\x1a\n");
}

}  // namespace
}  // namespace sweep::snapshot
