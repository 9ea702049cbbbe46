// The desktop's file dialog: which one is chosen, the command lines of zenity and kdialog, how
// their exit is read, and a real dialog program (a script standing in for zenity) run on
// FileChoice's thread: chosen, cancelled, failed, and closed when the viewer goes away.
#include "desktop/file_chooser.hpp"
#include "desktop/settings.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <map>
#include <string>
#include <thread>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;
using Outcome = ChooserResult::Outcome;

Environment fake_environment(std::map<std::string, std::string> variables) {
  return [variables = std::move(variables)](const char* name) -> const char* {
    const auto found = variables.find(name);
    return found == variables.end() ? nullptr : found->second.c_str();
  };
}

/// An executable shell script named `name` in `folder`.
fs::path write_program(const fs::path& folder, const std::string& name, const std::string& body) {
  const fs::path path = folder / name;
  test::write_text(path, "#!/bin/sh\n" + body);
  ::chmod(path.c_str(), 0755);
  return path;
}

/// Waits for `choice` (a dialog program that answers at once) and returns its result.
ChooserResult wait_for(FileChoice& choice) {
  for (int i = 0; i < 1000 && !choice.finished(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_TRUE(choice.finished()) << "the dialog program did not finish within 10 s";
  return choice.finished() ? choice.take() : ChooserResult{};
}

TEST(ChooseChooser, ThePortalFirstThenKdialogOnKdeThenZenityThenKdialogThenTheInAppBrowser) {
  ChooserSystem everything{true, "/usr/bin/zenity", "/usr/bin/kdialog", false};
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, everything), ChooserKind::Portal);
  EXPECT_EQ(choose_chooser(ChooserPreference::InApp, everything), ChooserKind::InApp) << "the setting forces it";
  ChooserSystem no_portal = everything;
  no_portal.portal = false;
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, no_portal), ChooserKind::Zenity);
  no_portal.kde = true;
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, no_portal), ChooserKind::Kdialog);
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, ChooserSystem{false, "", "/usr/bin/kdialog", false}),
            ChooserKind::Kdialog);
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, ChooserSystem{false, "/usr/bin/zenity", "", true}),
            ChooserKind::Zenity)
      << "KDE without kdialog";
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, ChooserSystem{}), ChooserKind::InApp) << "nothing: in-app";
}

TEST(ProbeChooserSystem, FindsExecutableDialogProgramsOnThePathAndKdeInTheDesktopName) {
  test::ScratchFolder bin;
  test::ScratchFolder other;
  const fs::path zenity = write_program(other.path(), "zenity", "exit 0\n");
  test::write_text(bin.path() / "kdialog", "not executable\n");
  const ChooserSystem found = probe_chooser_system(fake_environment(
      {{"PATH", bin.path().string() + "::" + other.path().string()}, {"XDG_CURRENT_DESKTOP", "ubuntu:KDE"}}));
  EXPECT_EQ(found.zenity, zenity.string());
  EXPECT_EQ(found.kdialog, "") << "a file that is not executable is not a program";
  EXPECT_TRUE(found.kde);
  EXPECT_FALSE(found.portal) << "no session bus address: the bus is not asked";
  const ChooserSystem none = probe_chooser_system(fake_environment({}));
  EXPECT_EQ(none.zenity, "");
  EXPECT_FALSE(none.kde);
}

TEST(ProbeChooserSystem, ABusAddressWhereNoBusAnswersMeansNoPortal) {
  test::ScratchFolder folder;
  const std::string address = "unix:path=" + (folder.path() / "no-bus").string();
  EXPECT_FALSE(probe_chooser_system(fake_environment({{"DBUS_SESSION_BUS_ADDRESS", address}})).portal);
}

TEST(ChooserCommand, ZenityOpensInTheFolderWithSwpFilesFirst) {
  ChooserRequest open{ChooserRequest::Purpose::Open, "/home/ann/models", {}};
  EXPECT_EQ(chooser_command(ChooserKind::Zenity, "/usr/bin/zenity", open),
            (std::vector<std::string>{"/usr/bin/zenity", "--file-selection", "--title=Open a file",
                                      "--filename=/home/ann/models/", "--file-filter=SWP files | *.swp *.SWP",
                                      "--file-filter=All files | *"}));
}

TEST(ChooserCommand, ZenitySavesTheCurrentFileAndConfirmsOverwriting) {
  ChooserRequest save{ChooserRequest::Purpose::Save, "/home/ann/models", "/home/ann/models/vase.swp"};
  EXPECT_EQ(chooser_command(ChooserKind::Zenity, "zenity", save),
            (std::vector<std::string>{"zenity", "--file-selection", "--save", "--confirm-overwrite",
                                      "--title=Save the document as", "--filename=/home/ann/models/vase.swp",
                                      "--file-filter=SWP files | *.swp *.SWP", "--file-filter=All files | *"}));
  ChooserRequest untitled{ChooserRequest::Purpose::Save, "/tmp/work", "untitled.swp"};
  EXPECT_EQ(chooser_command(ChooserKind::Zenity, "zenity", untitled)[5], "--filename=/tmp/work/untitled.swp");
}

TEST(ChooserCommand, KdialogOpensAndSavesWithItsOwnFilterSyntax) {
  ChooserRequest open{ChooserRequest::Purpose::Open, "/m", {}};
  EXPECT_EQ(chooser_command(ChooserKind::Kdialog, "kdialog", open),
            (std::vector<std::string>{"kdialog", "--title", "Open a file", "--getopenfilename", "/m/",
                                      "SWP files (*.swp *.SWP)"}));
  ChooserRequest save{ChooserRequest::Purpose::Save, "/m", "a.swp"};
  EXPECT_EQ(chooser_command(ChooserKind::Kdialog, "kdialog", save),
            (std::vector<std::string>{"kdialog", "--title", "Save the document as", "--getsavefilename", "/m/a.swp",
                                      "SWP files (*.swp *.SWP)"}));
}

TEST(CommandResult, StatusZeroWithAPathIsChosenOneIsCancelledAnythingElseFails) {
  const ChooserResult chosen = command_result("/usr/bin/zenity", 0, "/home/ann/a b.swp\n", "");
  EXPECT_EQ(chosen.outcome, Outcome::Chosen);
  EXPECT_EQ(chosen.path, "/home/ann/a b.swp");
  EXPECT_EQ(command_result("zenity", 0, "/x/y.swp\r\nmore\n", "").path, "/x/y.swp") << "the first line only";
  EXPECT_EQ(command_result("zenity", 0, "", "").outcome, Outcome::Cancelled);
  EXPECT_EQ(command_result("zenity", 1, "", "").outcome, Outcome::Cancelled);
  const ChooserResult failed = command_result("/usr/bin/zenity", 5, "", "Gtk-WARNING: cannot open display\nmore");
  EXPECT_EQ(failed.outcome, Outcome::Failed);
  EXPECT_EQ(failed.problem, "zenity exited with status 5: Gtk-WARNING: cannot open display");
  EXPECT_EQ(command_result("/opt/kdialog", -1, "", "No such file or directory").problem,
            "kdialog did not run: No such file or directory");
}

TEST(FileChoice, RunsTheDialogProgramOnItsThreadAndWakesTheCallerWithThePath) {
  test::ScratchFolder folder;
  const fs::path args = folder.path() / "args";
  const fs::path zenity = write_program(folder.path(), "zenity",
                                        "printf '%s\\n' \"$@\" > '" + args.string() + "'\necho /models/vase.swp\n");
  std::atomic<int> woken{0};
  FileChoice choice(ChooserKind::Zenity, zenity.string(), {ChooserRequest::Purpose::Open, folder.path(), {}},
                    [&woken] { ++woken; });
  const ChooserResult result = wait_for(choice);
  EXPECT_EQ(result.outcome, Outcome::Chosen);
  EXPECT_EQ(result.path, "/models/vase.swp");
  EXPECT_EQ(woken.load(), 1);
  EXPECT_EQ(test::read_file(args), "--file-selection\n--title=Open a file\n--filename=" + folder.path().string() +
                                       "/\n--file-filter=SWP files | *.swp *.SWP\n--file-filter=All files | *\n");
}

TEST(FileChoice, CancelledAndFailedDialogsSaySo) {
  test::ScratchFolder folder;
  const fs::path cancel = write_program(folder.path(), "cancel", "exit 1\n");
  FileChoice cancelled(ChooserKind::Zenity, cancel.string(), {}, {});
  EXPECT_EQ(wait_for(cancelled).outcome, Outcome::Cancelled);
  const fs::path broken = write_program(folder.path(), "broken", "echo 'cannot open display' >&2\nexit 255\n");
  FileChoice failed(ChooserKind::Kdialog, broken.string(), {}, {});
  const ChooserResult result = wait_for(failed);
  EXPECT_EQ(result.outcome, Outcome::Failed);
  EXPECT_EQ(result.problem, "broken exited with status 255: cannot open display");
  FileChoice missing(ChooserKind::Zenity, (folder.path() / "nowhere").string(), {}, {});
  EXPECT_EQ(wait_for(missing).problem, "nowhere did not run: No such file or directory");
}

TEST(FileChoice, GoingAwayWhileTheDialogIsOpenClosesIt) {
  test::ScratchFolder folder;
  const fs::path pid_file = folder.path() / "pid";
  const fs::path slow =
      write_program(folder.path(), "zenity", "echo $$ > '" + pid_file.string() + "'\nexec sleep 60\n");
  const auto start = std::chrono::steady_clock::now();
  {
    FileChoice choice(ChooserKind::Zenity, slow.string(), {}, {});
    for (int i = 0; i < 500 && !fs::exists(pid_file); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(fs::exists(pid_file));
    EXPECT_FALSE(choice.finished());
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30)) << "the dialog was not closed";
  const int pid = std::stoi(test::read_file(pid_file));
  EXPECT_NE(::kill(pid, 0), 0) << "the dialog program still runs";
}

TEST(Settings, KeepTheFileChooserPreferenceAndSkipWhatTheyDoNotKnow) {
  test::ScratchFolder folder;
  const fs::path file = folder.path() / "sweep" / "settings.txt";
  EXPECT_EQ(load_settings(file), Settings{}) << "no file: the defaults";
  EXPECT_EQ(load_settings(file).file_chooser, ChooserPreference::Auto);
  ASSERT_EQ(save_settings(file, Settings{ChooserPreference::InApp}), "");
  EXPECT_EQ(test::read_file(file), "file-chooser in-app\n");
  EXPECT_EQ(load_settings(file).file_chooser, ChooserPreference::InApp);
  test::write_text(file, "colour blue\nfile-chooser sometimes\r\n\nfile-chooser in-app\r\n");
  EXPECT_EQ(load_settings(file).file_chooser, ChooserPreference::InApp) << "CRLF, unknown keys and values skipped";
  test::write_text(file, "file-chooser sometimes\n");
  EXPECT_EQ(load_settings(file).file_chooser, ChooserPreference::Auto);
}

TEST(Settings, SweepFileChooserOverridesThePreferenceForARun) {
  EXPECT_EQ(chooser_preference_override(fake_environment({{"SWEEP_FILE_CHOOSER", "in-app"}})),
            ChooserPreference::InApp);
  EXPECT_EQ(chooser_preference_override(fake_environment({{"SWEEP_FILE_CHOOSER", "auto"}})), ChooserPreference::Auto);
  EXPECT_EQ(chooser_preference_override(fake_environment({{"SWEEP_FILE_CHOOSER", "yes"}})), std::nullopt);
  EXPECT_EQ(chooser_preference_override(fake_environment({})), std::nullopt);
}

TEST(Settings, AFolderThatCannotBeMadeIsOneMessage) {
  test::ScratchFolder folder;
  test::write_text(folder.path() / "file", "x");
  const fs::path file = folder.path() / "file" / "settings.txt";
  EXPECT_EQ(save_settings(file, Settings{}), "cannot save the settings to " + file.string() + ": " +
                                                 std::make_error_code(std::errc::not_a_directory).message());
}

}  // namespace
}  // namespace sweep::editor
