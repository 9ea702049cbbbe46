// The `sweep` executable's operator new (src/app/large_pages.cpp): a large block is 2 MB pages
// from its first byte, so filling it costs a few page faults rather than one per 4 KB, and blocks
// of every size work as operator new and delete promise. Skipped where the kernel has no
// transparent huge pages ([never] or no sysfs file).
#include <sys/resource.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace {

bool kernel_has_huge_pages() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string setting;
  std::getline(in, setting);
  return in && setting.find("[never]") == std::string::npos;
}

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

TEST(LargePages, FillingALargeBlockFaultsOncePerTwoMegabytes) {
  if (!kernel_has_huge_pages()) GTEST_SKIP() << "no transparent huge pages in this kernel";
  constexpr std::size_t kBytes = std::size_t{24} << 20;  // 6144 pages of 4 KB, 12 of 2 MB
  for (int round = 0; round < 3; ++round) {              // fresh memory each time, as in a run
    const long before = minor_faults();
    std::unique_ptr<char[]> block(new char[kBytes]);
    std::memset(block.get(), round + 1, kBytes);
    const long faults = minor_faults() - before;
    EXPECT_LE(faults, 64) << "round " << round << ": 4 KB pages would fault 6144 times";
    EXPECT_EQ(block[kBytes - 1], round + 1);
  }
}

TEST(LargePages, BlocksOfEverySizeKeepTheirBytesAndAlignment) {
  std::vector<std::unique_ptr<std::uint64_t[]>> blocks;
  for (std::size_t words : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{1} << 19,
                            std::size_t{1} << 21, (std::size_t{3} << 20) + 7}) {
    blocks.emplace_back(new std::uint64_t[words + 1]);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(blocks.back().get()) % alignof(std::max_align_t), 0u);
    for (std::size_t k = 0; k <= words; k += 997) blocks.back()[k] = words ^ k;
  }
  std::size_t b = 0;
  for (std::size_t words : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{1} << 19,
                            std::size_t{1} << 21, (std::size_t{3} << 20) + 7}) {
    for (std::size_t k = 0; k <= words; k += 997) ASSERT_EQ(blocks[b][k], words ^ k);
    ++b;
  }
  std::unique_ptr<char> one(new (std::nothrow) char('x'));
  ASSERT_NE(one, nullptr);
  EXPECT_EQ(*one, 'x');
}

TEST(LargePages, AnImpossibleSizeThrowsBadAlloc) {
  volatile std::size_t huge = ~std::size_t{0} / 2;
  EXPECT_THROW(static_cast<void>(std::make_unique<char[]>(huge)), std::bad_alloc);
  EXPECT_EQ(new (std::nothrow) char[huge], nullptr);
}

}  // namespace
