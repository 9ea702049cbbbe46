// The Open and Save As browser without a window: what a folder lists (sub-folders, then .swp
// files, hidden entries left out, case-insensitive order and filter), moving the highlight,
// entering folders and going up, typed paths, and folders that cannot be read.
#include "desktop/file_browser.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace sweep::editor {
namespace {

using test::joined;

void touch(const std::filesystem::path& path) {
  test::write_text(path, "circ a 8 1\n");
}

/// A tree with folders, .swp files, other files, hidden entries and links:
///   alpha/ (inner.swp)  Beta/  folder.swp/  link-to-alpha -> alpha  .hidden/
///   Apple.SWP  model.swp  zeta.swp  notes.txt  readme  .secret.swp  broken.swp -> nowhere
class FileBrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto& root = scratch_.path();
    std::filesystem::create_directory(root / "alpha");
    touch(root / "alpha" / "inner.swp");
    std::filesystem::create_directory(root / "Beta");
    std::filesystem::create_directory(root / "folder.swp");
    std::filesystem::create_directory(root / ".hidden");
    std::filesystem::create_directory_symlink(root / "alpha", root / "link-to-alpha");
    std::filesystem::create_symlink(root / "nowhere.swp", root / "broken.swp");
    for (const char* name : {"Apple.SWP", "model.swp", "zeta.swp", "notes.txt", "readme", ".secret.swp"})
      touch(root / name);
  }

  static std::vector<std::string> names(const std::vector<BrowserEntry>& entries) {
    std::vector<std::string> result;
    for (const BrowserEntry& e : entries) result.push_back(e.folder ? joined({e.name, "/"}) : e.name);
    return result;
  }

  const std::filesystem::path& root() const { return scratch_.path(); }

  test::ScratchFolder scratch_{"sweep-browser"};
};

TEST_F(FileBrowserTest, ListsFoldersThenSwpFilesCaseInsensitivelyWithoutHiddenOnes) {
  std::vector<BrowserEntry> entries{{"stale", false}};
  EXPECT_EQ(list_folder(root(), "", entries), "");
  EXPECT_EQ(names(entries), (std::vector<std::string>{"alpha/", "Beta/", "folder.swp/", "link-to-alpha/", "Apple.SWP",
                                                      "model.swp", "zeta.swp"}));
}

TEST_F(FileBrowserTest, TheFilterKeepsNamesContainingItInAnyCase) {
  std::vector<BrowserEntry> entries;
  EXPECT_EQ(list_folder(root(), "A", entries), "");
  EXPECT_EQ(names(entries), (std::vector<std::string>{"alpha/", "Beta/", "link-to-alpha/", "Apple.SWP", "zeta.swp"}));
  EXPECT_EQ(list_folder(root(), "swp", entries), "");
  EXPECT_EQ(names(entries), (std::vector<std::string>{"folder.swp/", "Apple.SWP", "model.swp", "zeta.swp"}));
  EXPECT_EQ(list_folder(root(), "secret", entries), "") << "hidden entries stay hidden";
  EXPECT_TRUE(entries.empty());
}

TEST_F(FileBrowserTest, AFolderThatCannotBeReadSaysWhy) {
  std::vector<BrowserEntry> entries{{"stale", false}};
  const auto missing = root() / "missing";
  EXPECT_EQ(list_folder(missing, "", entries),
            joined({"cannot read ", missing.string(), ": No such file or directory"}));
  EXPECT_TRUE(entries.empty());
  EXPECT_EQ(list_folder(root() / "readme", "", entries),
            joined({"cannot read ", (root() / "readme").string(), ": Not a directory"}));
  EXPECT_TRUE(entries.empty());
}

TEST_F(FileBrowserTest, AnUnreadableFolderSaysPermissionDenied) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads every folder";
  const auto locked = root() / "Beta";
  std::filesystem::permissions(locked, std::filesystem::perms::none);
  std::vector<BrowserEntry> entries;
  EXPECT_EQ(list_folder(locked, "", entries), joined({"cannot read ", locked.string(), ": Permission denied"}));
  FileBrowser browser;
  browser.open_at(locked);
  EXPECT_EQ(browser.folder(), locked);
  EXPECT_EQ(browser.error(), joined({"cannot read ", locked.string(), ": Permission denied"}));
  EXPECT_TRUE(browser.entries().empty());
  EXPECT_EQ(browser.highlighted(), -1);
  std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
}

TEST_F(FileBrowserTest, OpenAtShowsAFolderOrAFilesFolder) {
  FileBrowser browser;
  browser.open_at(root());
  EXPECT_EQ(browser.folder(), root());
  EXPECT_EQ(browser.error(), "");
  EXPECT_EQ(browser.filter(), "");
  EXPECT_EQ(browser.entries().size(), 7u);
  EXPECT_EQ(browser.highlighted(), 0);

  browser.open_at(root() / "alpha" / "inner.swp");
  EXPECT_EQ(browser.folder(), root() / "alpha");
  browser.open_at(root() / "not-yet-saved.swp");
  EXPECT_EQ(browser.folder(), root()) << "a .swp path that does not exist yet (Save As)";
  browser.open_at(root() / "folder.swp");
  EXPECT_EQ(browser.folder(), root() / "folder.swp") << "a folder, whatever its name";
  EXPECT_EQ(browser.highlighted(), -1) << "nothing to highlight";
  browser.open_at(root() / "alpha" / "." / ".." / "Beta" / "");
  EXPECT_EQ(browser.folder(), root() / "Beta") << "normalized, without a trailing separator";
  browser.open_at(root() / "missing-folder");
  EXPECT_EQ(browser.folder(), std::filesystem::current_path());
}

TEST_F(FileBrowserTest, OpenAtARelativePathMakesItAbsolute) {
  FileBrowser browser;
  browser.open_at("model.swp");
  EXPECT_EQ(browser.folder(), std::filesystem::current_path()) << "a bare file name: the current folder";
  EXPECT_TRUE(browser.folder().is_absolute());
}

TEST_F(FileBrowserTest, SetFilterListsAgainAndHighlightsTheFirstRow) {
  FileBrowser browser;
  browser.open_at(root());
  browser.move(3);
  browser.set_filter("swp");
  EXPECT_EQ(browser.filter(), "swp");
  EXPECT_EQ(names(browser.entries()), (std::vector<std::string>{"folder.swp/", "Apple.SWP", "model.swp", "zeta.swp"}));
  EXPECT_EQ(browser.highlighted(), 0);
  browser.set_filter("nothing matches");
  EXPECT_TRUE(browser.entries().empty());
  EXPECT_EQ(browser.highlighted(), -1);
  EXPECT_EQ(browser.activate(), "") << "no row";
  browser.set_filter("");
  EXPECT_EQ(browser.entries().size(), 7u);
  EXPECT_EQ(browser.highlighted(), 0);
}

TEST_F(FileBrowserTest, MoveAndHighlightStayInTheList) {
  FileBrowser browser;
  browser.open_at(root());
  browser.move(1);
  EXPECT_EQ(browser.highlighted(), 1);
  browser.move(2);
  EXPECT_EQ(browser.highlighted(), 3);
  browser.move(100);
  EXPECT_EQ(browser.highlighted(), 6);
  browser.move(-100);
  EXPECT_EQ(browser.highlighted(), 0);
  browser.highlight(4);
  EXPECT_EQ(browser.highlighted(), 4);
  browser.highlight(99);
  EXPECT_EQ(browser.highlighted(), 6);
  browser.highlight(-1);
  EXPECT_EQ(browser.highlighted(), -1);
  browser.move(1);
  EXPECT_EQ(browser.highlighted(), 0) << "down from no row: the first";
}

TEST_F(FileBrowserTest, ActivatingAFolderEntersItAndAFileReturnsItsPath) {
  FileBrowser browser;
  browser.open_at(root());
  browser.set_filter("alp");
  ASSERT_EQ(names(browser.entries()), (std::vector<std::string>{"alpha/", "link-to-alpha/"}));
  EXPECT_EQ(browser.activate(), "") << "a folder is entered";
  EXPECT_EQ(browser.folder(), root() / "alpha");
  EXPECT_EQ(browser.filter(), "") << "the filter is cleared";
  EXPECT_EQ(names(browser.entries()), (std::vector<std::string>{"inner.swp"}));
  EXPECT_EQ(browser.highlighted(), 0);
  EXPECT_EQ(browser.activate(), (root() / "alpha" / "inner.swp").string());
  EXPECT_EQ(browser.folder(), root() / "alpha") << "a file leaves the folder shown";
  EXPECT_EQ(browser.activate(1), "") << "out of range";
  EXPECT_EQ(browser.activate(-2), "");

  browser.open_at(root());
  EXPECT_EQ(browser.activate(5), (root() / "model.swp").string()) << "a given row, not the highlighted one";
  EXPECT_EQ(browser.activate(3), "") << "a link to a folder is a folder";
  EXPECT_EQ(browser.folder(), root() / "link-to-alpha");
  EXPECT_EQ(names(browser.entries()), (std::vector<std::string>{"inner.swp"}));
}

TEST_F(FileBrowserTest, GoUpShowsTheParentWithTheFolderLeftHighlighted) {
  FileBrowser browser;
  browser.open_at(root() / "Beta");
  browser.set_filter("x");
  browser.go_up();
  EXPECT_EQ(browser.folder(), root());
  EXPECT_EQ(browser.filter(), "");
  EXPECT_EQ(browser.entries().size(), 7u);
  EXPECT_EQ(browser.highlighted(), 1) << "Beta";

  browser.open_at("/");
  browser.go_up();
  EXPECT_EQ(browser.folder(), std::filesystem::path("/")) << "the root has no parent";
}

TEST_F(FileBrowserTest, GoToShowsFoldersAndReturnsAnythingElse) {
  FileBrowser browser;
  browser.open_at(root());
  EXPECT_EQ(browser.go_to(""), "");
  EXPECT_EQ(browser.folder(), root());

  EXPECT_EQ(browser.go_to("alpha"), "") << "a relative folder";
  EXPECT_EQ(browser.folder(), root() / "alpha");
  EXPECT_EQ(browser.filter(), "");
  EXPECT_EQ(names(browser.entries()), (std::vector<std::string>{"inner.swp"}));

  EXPECT_EQ(browser.go_to("../zeta.swp"), (root() / "zeta.swp").string()) << "a relative file, normalized";
  EXPECT_EQ(browser.go_to("new.swp"), (root() / "alpha" / "new.swp").string()) << "a file that does not exist yet";
  EXPECT_EQ(browser.folder(), root() / "alpha");

  EXPECT_EQ(browser.go_to((root() / "Beta").string()), "") << "an absolute folder";
  EXPECT_EQ(browser.folder(), root() / "Beta");
  EXPECT_EQ(browser.go_to((root() / "model.swp").string()), (root() / "model.swp").string()) << "an absolute file";
  EXPECT_EQ(browser.go_to("../folder.swp"), "") << "a folder named like a file is still a folder";
  EXPECT_EQ(browser.folder(), root() / "folder.swp");
}

}  // namespace
}  // namespace sweep::editor
