// Where Sweep keeps what outlives a run: the XDG variables and the HOME fallback read from a
// fake environment, and creating the folder (with the reasons it can fail).
#include "desktop/user_folders.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <map>
#include <string>

namespace sweep::editor {
namespace {

using test::joined;

/// An environment holding exactly `variables`.
Environment fake_environment(std::map<std::string, std::string> variables) {
  return [variables = std::move(variables)](const char* name) -> const char* {
    const auto found = variables.find(name);
    return found == variables.end() ? nullptr : found->second.c_str();
  };
}

TEST(UserFolders, XdgVariablesAreHonoured) {
  const Environment env =
      fake_environment({{"XDG_STATE_HOME", "/xdg/state"}, {"XDG_CONFIG_HOME", "/xdg/config"}, {"HOME", "/home/ann"}});
  const UserFolder state = state_folder(env);
  ASSERT_TRUE(state.ok()) << state.problem;
  EXPECT_EQ(state.path, std::filesystem::path("/xdg/state/sweep"));
  const UserFolder config = config_folder(env);
  ASSERT_TRUE(config.ok()) << config.problem;
  EXPECT_EQ(config.path, std::filesystem::path("/xdg/config/sweep"));
}

TEST(UserFolders, HomeIsTheFallbackWithoutXdgVariables) {
  const Environment env = fake_environment({{"HOME", "/home/ann"}});
  EXPECT_EQ(state_folder(env).path, std::filesystem::path("/home/ann/.local/state/sweep"));
  EXPECT_TRUE(state_folder(env).ok());
  EXPECT_EQ(config_folder(env).path, std::filesystem::path("/home/ann/.config/sweep"));
  EXPECT_TRUE(config_folder(env).ok());
}

TEST(UserFolders, RelativeOrEmptyXdgVariablesAreIgnored) {
  const Environment relative =
      fake_environment({{"XDG_STATE_HOME", "state"}, {"XDG_CONFIG_HOME", "./config"}, {"HOME", "/home/ann"}});
  EXPECT_EQ(state_folder(relative).path, std::filesystem::path("/home/ann/.local/state/sweep"));
  EXPECT_EQ(config_folder(relative).path, std::filesystem::path("/home/ann/.config/sweep"));
  const Environment empty = fake_environment({{"XDG_STATE_HOME", ""}, {"XDG_CONFIG_HOME", ""}, {"HOME", "/home/ann"}});
  EXPECT_EQ(state_folder(empty).path, std::filesystem::path("/home/ann/.local/state/sweep"));
  EXPECT_EQ(config_folder(empty).path, std::filesystem::path("/home/ann/.config/sweep"));
}

TEST(UserFolders, NoHomeAndNoXdgIsAProblemNamingBothVariables) {
  const Environment env = fake_environment({{"XDG_STATE_HOME", "relative"}});
  const UserFolder state = state_folder(env);
  EXPECT_FALSE(state.ok());
  EXPECT_EQ(state.problem, "neither XDG_STATE_HOME nor HOME is set: nowhere to keep recovery copies");
  const UserFolder config = config_folder(env);
  EXPECT_FALSE(config.ok());
  EXPECT_EQ(config.problem,
            "neither XDG_CONFIG_HOME nor HOME is set: nowhere to keep recent files and the window layout");
  EXPECT_EQ(ensure_folder(state), state.problem) << "ensure_folder passes the problem on";
  const Environment empty_home = fake_environment({{"HOME", ""}});
  EXPECT_FALSE(state_folder(empty_home).ok());
}

TEST(UserFolders, NothingIsCreatedUntilEnsured) {
  test::ScratchFolder scratch("sweep-user-folders");
  const Environment env = fake_environment({{"HOME", scratch.path().string()}});
  const UserFolder state = state_folder(env);
  EXPECT_FALSE(std::filesystem::exists(state.path));
  EXPECT_EQ(ensure_folder(state), "");
  EXPECT_TRUE(std::filesystem::is_directory(state.path));
  EXPECT_EQ(ensure_folder(state), "") << "an existing folder is fine";
}

TEST(UserFolders, EnsureFolderNamesTheFolderItCannotCreate) {
  test::ScratchFolder scratch("sweep-user-folders");
  if (::geteuid() == 0) {
    // Root ignores permissions: put a file where a parent folder should be instead.
    test::write_text(scratch.path() / "blocker", "x");
    UserFolder folder;
    folder.path = scratch.path() / "blocker" / "sweep";
    EXPECT_EQ(ensure_folder(folder), joined({"cannot create ", folder.path.string(), ": Not a directory"}));
  } else {
    const std::filesystem::path locked = scratch.path() / "locked";
    std::filesystem::create_directory(locked);
    std::filesystem::permissions(locked, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    UserFolder folder;
    folder.path = locked / "sweep";
    EXPECT_EQ(ensure_folder(folder), joined({"cannot create ", folder.path.string(), ": Permission denied"}));
    std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
  }
}

TEST(UserFolders, EnsureFolderRefusesAFileInTheWay) {
  test::ScratchFolder scratch("sweep-user-folders");
  UserFolder folder;
  folder.path = scratch.path() / "sweep";
  test::write_text(folder.path, "not a folder");
  EXPECT_EQ(ensure_folder(folder), joined({"cannot use ", folder.path.string(), ": it is not a folder"}));
}

TEST(UserFolders, ProcessEnvironmentReadsTheRealEnvironment) {
  ::setenv("SWEEP_USER_FOLDERS_TEST", "value", 1);
  const Environment env = process_environment();
  ASSERT_NE(env("SWEEP_USER_FOLDERS_TEST"), nullptr);
  EXPECT_STREQ(env("SWEEP_USER_FOLDERS_TEST"), "value");
  ::unsetenv("SWEEP_USER_FOLDERS_TEST");
  EXPECT_EQ(env("SWEEP_USER_FOLDERS_TEST"), nullptr);
}

}  // namespace
}  // namespace sweep::editor
