// `sweep check` and the print options `sweep export` shares with it (commands.hpp).
#include "app/commands.hpp"
#include "model/print/printability.hpp"

#include <cstdio>
#include <memory>

namespace sweep::app {
namespace {

struct CheckChoice {
  std::string file;
  io::PrintOptions print;
  EvaluationChoice evaluation;
};

int check_file(const CheckChoice& choice) {
  Document doc;
  Scene scene;
  if (!load_and_evaluate(choice.file, choice.evaluation.options(), doc, scene)) return 1;
  const PrintModel model = print_model(doc, scene, choice.print.height_mm);
  if (model.parts.empty()) {
    std::fprintf(stderr, "%s has no named surfaces; nothing to check\n", choice.file.c_str());
    return 0;
  }
  const std::vector<PrintFinding> findings = check_print(doc, model, choice.file, {choice.print.min_wall_mm});
  std::size_t failing = 0;
  for (const PrintFinding& finding : findings) {
    std::printf("%s\n", finding.message.c_str());
    failing += finding.fails;
  }
  std::printf("%s: %zu surface%s, %s: %s\n", choice.file.c_str(), model.parts.size(),
              model.parts.size() == 1 ? "" : "s",
              model_size_text(model.placement, choice.print.height_mm > 0.0).c_str(),
              failing == 0 ? "printable" : (std::to_string(failing) + " warning" + (failing == 1 ? "" : "s")).c_str());
  return failing == 0 ? 0 : 1;
}

}  // namespace

void add_print_options(CLI::App* command, io::PrintOptions& print, const std::string& scope) {
  command
      ->add_option("--height", print.height_mm,
                   scope +
                       "scale the model so it is MM millimetres tall (without it 1 model unit = 1 mm; the size "
                       "is printed)")
      ->check(CLI::Range(0.001, 100000.0))
      ->type_name("MM");
  command
      ->add_option("--min-wall", print.min_wall_mm,
                   scope +
                       "warn of walls thinner than MM millimetres as printed (default 0.8, about two lines of "
                       "a 0.4 mm nozzle)")
      ->check(CLI::Range(0.001, 1000.0))
      ->type_name("MM");
}

std::optional<std::string> option_for_another_format(const CLI::App& export_command, const std::string& format) {
  struct Owner {
    const char* option;
    const char* formats;  // as the message says them
    bool (*fits)(const std::string&);
  };
  static constexpr Owner owners[] = {
      {"--quantize", "glb", [](const std::string& f) { return f == "glb"; }},
      {"--height", "3mf or stl", [](const std::string& f) { return f == "3mf" || f == "stl"; }},
      {"--min-wall", "3mf or stl", [](const std::string& f) { return f == "3mf" || f == "stl"; }},
      {"--merge", "stl", [](const std::string& f) { return f == "stl"; }}};
  for (const Owner& owner : owners) {
    if (export_command.count(owner.option) == 0 || owner.fits(format)) continue;
    return std::string(owner.option) + ": expected --format " + owner.formats + ", found --format " + format;
  }
  return std::nullopt;
}

void add_check_command(CLI::App& app, Action& action) {
  auto choice = std::make_shared<CheckChoice>();
  CLI::App* command = app.add_subcommand(
      "check",
      "Check FILE's printable surfaces as a 3MF or STL export would, writing nothing: open surfaces, non-manifold "
      "edges, orientation, surfaces crossing themselves or each other, thin walls and floating parts, each named "
      "with its line; exit 1 when a check fails");
  command->add_option("file", choice->file, "SWP file to read")->required()->check(CLI::ExistingFile);
  add_print_options(command, choice->print, "");
  add_evaluation_options(command, choice->evaluation);
  command->callback([choice, &action] { action = [choice] { return check_file(*choice); }; });
}

}  // namespace sweep::app
