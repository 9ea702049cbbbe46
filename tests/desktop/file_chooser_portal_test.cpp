// The desktop portal's dialog through libportal, against a private session bus (dbus-daemon)
// where sweep_fake_portal answers for org.freedesktop.portal.Desktop as xdg-desktop-portal does.
#include "desktop/file_chooser.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;
using Outcome = ChooserResult::Outcome;

/// A program started with its stdout on a pipe; stopped (SIGTERM) when destroyed.
class Child {
 public:
  explicit Child(std::vector<std::string> argv) {
    int ends[2];
    if (::pipe(ends) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, ends[0]);
    std::vector<char*> args;
    for (std::string& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    if (::posix_spawnp(&pid_, args[0], &actions, nullptr, args.data(), environ) != 0) pid_ = 0;
    posix_spawn_file_actions_destroy(&actions);
    ::close(ends[1]);
    out_ = ::fdopen(ends[0], "r");
  }
  ~Child() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
    if (out_ != nullptr) std::fclose(out_);
  }
  /// The next line it prints, without its line end ("" at the end).
  std::string line() {
    char buffer[4096];
    if (out_ == nullptr || std::fgets(buffer, sizeof buffer, out_) == nullptr) return {};
    std::string text = buffer;
    if (!text.empty() && text.back() == '\n') text.pop_back();
    return text;
  }
  bool started() const { return pid_ > 0; }

 private:
  pid_t pid_ = 0;
  std::FILE* out_ = nullptr;
};

class PortalChooser : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    folder_ = std::make_unique<test::ScratchFolder>("sweep-portal");
    bus_ =
        std::make_unique<Child>(std::vector<std::string>{"dbus-daemon", "--session", "--nofork", "--print-address=1"});
    const std::string address = bus_->line();
    if (address.empty()) return;
    ::setenv("DBUS_SESSION_BUS_ADDRESS", address.c_str(), 1);  // libportal's session bus, and the probe's
    test::write_text(answer(), "cancel\n");
    portal_ = std::make_unique<Child>(std::vector<std::string>{SWEEP_FAKE_PORTAL, answer().string(), log().string()});
    ready_ = portal_->line() == "ready";
  }
  static void TearDownTestSuite() {
    portal_.reset();
    bus_.reset();
    folder_.reset();
  }
  void SetUp() override {
    ASSERT_TRUE(ready_) << "no private session bus with the fake portal (is dbus-daemon installed?)";
  }

  static fs::path answer() { return folder_->path() / "answer"; }
  static fs::path log() { return folder_->path() / "log"; }

  static ChooserResult choose(ChooserRequest request) {
    FileChoice choice(ChooserKind::Portal, "", std::move(request), {});
    for (int i = 0; i < 1000 && !choice.finished(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_TRUE(choice.finished()) << "the portal did not answer within 10 s";
    return choice.finished() ? choice.take() : ChooserResult{};
  }

  static inline std::unique_ptr<test::ScratchFolder> folder_;
  static inline std::unique_ptr<Child> bus_;
  static inline std::unique_ptr<Child> portal_;
  static inline bool ready_ = false;
};

TEST_F(PortalChooser, IsFoundOnTheSessionBusAndChosenFirst) {
  const ChooserSystem system = probe_chooser_system(process_environment());
  EXPECT_TRUE(system.portal);
  EXPECT_EQ(choose_chooser(ChooserPreference::Auto, system), ChooserKind::Portal);
}

TEST_F(PortalChooser, OpenGivesTheFileTheUserChose) {
  test::write_text(answer(), "/models/a vase.swp\n");
  fs::remove(log());
  const ChooserResult result = choose({ChooserRequest::Purpose::Open, "/models", {}});
  EXPECT_EQ(result.outcome, Outcome::Chosen) << result.problem;
  EXPECT_EQ(result.path, "/models/a vase.swp") << "the file:// URI read back as a path";
  EXPECT_EQ(test::read_file(log()), "OpenFile Open a file\n");
}

TEST_F(PortalChooser, SaveSuggestsTheFileAndItsFolderAndCancelIsNothingChosen) {
  test::write_text(answer(), "cancel\n");
  fs::remove(log());
  const ChooserResult result = choose({ChooserRequest::Purpose::Save, "/elsewhere", "/models/vase.swp"});
  EXPECT_EQ(result.outcome, Outcome::Cancelled) << result.problem;
  EXPECT_EQ(test::read_file(log()), "SaveFile Save the document as vase.swp /models\n");
  test::write_text(answer(), "/models/copy.swp\n");
  EXPECT_EQ(choose({ChooserRequest::Purpose::Save, "/models", "untitled.swp"}).path, "/models/copy.swp");
}

}  // namespace
}  // namespace sweep::editor
