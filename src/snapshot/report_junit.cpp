#include "snapshot/report.hpp"

#include <tinyxml2.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

// JUnit XML for CI systems (GitLab, Jenkins, GitHub test reporters): one <testsuite>, a
// <testcase> per case in run order. tinyxml2 escapes markup; what it does not do is keep the
// file well-formed when a message carries bytes XML 1.0 forbids (control characters, broken
// UTF-8 from a user's file), so those become U+FFFD first.

namespace sweep::snapshot {
namespace {

std::string seconds_text(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", seconds < 0.0 ? 0.0 : seconds);
  return text;
}

// Valid UTF-8 without the control characters XML 1.0 forbids; anything else becomes U+FFFD.
std::string xml_text(std::string_view text) {
  static constexpr std::string_view kReplacement = "\xef\xbf\xbd";
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<unsigned char>(text[i]);
    if (lead < 0x80) {
      const bool allowed = lead >= 0x20 || lead == '\t' || lead == '\n' || lead == '\r';
      if (allowed && lead != 0x7f) {
        out += static_cast<char>(lead);
      } else {
        out += kReplacement;
      }
      ++i;
      continue;
    }
    std::size_t length = 0;
    unsigned int code = 0;
    if (lead >= 0xc2 && lead <= 0xdf) {
      length = 2;
      code = lead & 0x1fu;
    } else if (lead >= 0xe0 && lead <= 0xef) {
      length = 3;
      code = lead & 0x0fu;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
      length = 4;
      code = lead & 0x07u;
    }
    bool valid = length > 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      valid = (next & 0xc0u) == 0x80u;
      code = (code << 6) | (next & 0x3fu);
    }
    // Overlong forms, surrogates, beyond U+10FFFF and the non-characters U+FFFE/U+FFFF.
    valid = valid && !(length == 3 && code < 0x800) && !(length == 4 && (code < 0x10000 || code > 0x10ffff)) &&
            !(code >= 0xd800 && code <= 0xdfff) && code != 0xfffe && code != 0xffff;
    if (valid) {
      out.append(text.substr(i, length));
      i += length;
    } else {
      out += kReplacement;
      ++i;
    }
  }
  return out;
}

// The failure body: the attribution (a changed object marked with '*'), then the numbers.
std::string failure_body(const CaseResult& result) {
  std::string body;
  for (const ObjectChange& change : result.changes) body += (change.changed ? "* " : "  ") + change.text + "\n";
  if (result.diff) body += result.diff->summary() + "\n";
  if (!result.matched_reference.empty()) {
    body += "compared with " + result.matched_reference + " (" + std::to_string(result.accepted.size()) +
            (result.accepted.size() == 1 ? " accepted reference)\n" : " accepted references)\n");
  }
  for (const AcceptedReference& a : result.accepted) {
    body += "reference " + a.file + ": " + (a.renderer.empty() ? "renderer unknown" : a.renderer) + "\n";
  }
  if (result.other_renderer) body += "reference from another renderer: compared with thresholds\n";
  if (!result.diff_image.empty()) body += "heat map: " + result.diff_image + "\n";
  return body;
}

}  // namespace

void write_junit(const std::filesystem::path& file, const std::vector<CaseResult>& results, const RunSummary& summary) {
  int failures = 0;
  int errors = 0;
  for (const CaseResult& result : results) {
    const bool fails = fails_run(result, summary);
    errors += fails && result.status == Status::Error ? 1 : 0;
    failures += fails && result.status != Status::Error ? 1 : 0;
  }

  tinyxml2::XMLDocument document;
  document.InsertEndChild(document.NewDeclaration());
  tinyxml2::XMLElement* suite = document.NewElement("testsuite");
  document.InsertEndChild(suite);
  suite->SetAttribute("name", "sweep snapshot");
  suite->SetAttribute("tests", static_cast<int>(results.size()));
  suite->SetAttribute("failures", failures);
  suite->SetAttribute("errors", errors);
  suite->SetAttribute("skipped", 0);
  suite->SetAttribute("time", seconds_text(summary.seconds).c_str());

  tinyxml2::XMLElement* properties = suite->InsertNewChildElement("properties");
  const auto property = [&](const char* name, const std::string& value) {
    tinyxml2::XMLElement* element = properties->InsertNewChildElement("property");
    element->SetAttribute("name", name);
    element->SetAttribute("value", xml_text(value).c_str());
  };
  property("title", summary.title);
  property("renderer", summary.renderer);
  property("workers", std::to_string(summary.workers));

  for (const CaseResult& result : results) {
    tinyxml2::XMLElement* test = suite->InsertNewChildElement("testcase");
    const std::filesystem::path& swp = result.spec.relative.empty() ? result.spec.file : result.spec.relative;
    test->SetAttribute("classname", xml_text(swp.generic_string()).c_str());
    test->SetAttribute("name", xml_text(result.spec.name).c_str());
    test->SetAttribute("time", seconds_text(result.seconds).c_str());
    if (result.status == Status::New && fails_run(result, summary)) {
      tinyxml2::XMLElement* failure = test->InsertNewChildElement("failure");
      failure->SetAttribute("message", xml_text(result.message + " (not accepted: run with --update)").c_str());
      failure->SetAttribute("type", "new-reference");
      failure->SetText(xml_text(result.message + "\n").c_str());
      continue;
    }
    switch (result.status) {
      case Status::Fail: {
        tinyxml2::XMLElement* failure = test->InsertNewChildElement("failure");
        failure->SetAttribute("message", xml_text(result.message).c_str());
        failure->SetAttribute("type", result.renderer_difference ? "renderer-difference" : "snapshot");
        failure->SetText(xml_text(failure_body(result)).c_str());
        break;
      }
      case Status::Error: {
        tinyxml2::XMLElement* error = test->InsertNewChildElement("error");
        error->SetAttribute("message", xml_text(result.message).c_str());
        error->SetAttribute("type", "error");
        error->SetText(xml_text(result.message).c_str());
        break;
      }
      case Status::Warning:
        test->InsertNewChildElement("system-out")
            ->SetText(xml_text("warning: " + result.message + "\n" + failure_body(result)).c_str());
        break;
      case Status::New:
      case Status::Updated:
        test->InsertNewChildElement("system-out")->SetText(xml_text(result.message).c_str());
        break;
      case Status::Pass:
        break;
    }
  }

  std::error_code ignored;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ignored);
  if (document.SaveFile(file.c_str()) != tinyxml2::XML_SUCCESS) {
    throw std::runtime_error("cannot write the JUnit XML " + file.string());
  }
}

}  // namespace sweep::snapshot
