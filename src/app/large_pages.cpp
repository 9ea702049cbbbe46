// Memory paid once: the global operator new and delete of the `sweep` executable (and of the
// benchmarks and a test of their own, which measure what it does). A large block (mesh positions,
// normals, indices, an export's bytes: 4 MB and more) is mapped by glibc on its own, on a 2 MB
// boundary, and the kernel is asked for 2 MB pages over it (madvise MADV_HUGEPAGE, honoured where
// transparent huge pages are `madvise` or `always`, as on Debian): filling it then faults once per
// 2 MB instead of once per 4 KB. On this project's VM a 4 KB page costs about 8 us to fault in, a
// 2 MB page about 0.12 ms: fresh memory was 90 % of a fresh evaluation of weird.swp at ten times its
// STEPS (BM_EvaluateWeirdTenTimesSteps 121 ms against 13 ms re-evaluating into kept buffers; now
// 18-20 ms, docs/performance.md). Small blocks are plain malloc. glibc's own
// `GLIBC_TUNABLES=glibc.malloc.hugetlb=1` does much the same, but no user sets it.
//
// Not compiled into sanitizer builds: ASan and UBSan's allocators replace these operators there.
#include <malloc.h>
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
/// From this size on an allocation holds at least one whole aligned 2 MB page.
constexpr std::size_t kLarge = 2 * kHugePage;

/// glibc's bytes before an mmapped chunk's memory: the chunk header (two size_t).
constexpr std::size_t kChunkHeader = 2 * sizeof(std::size_t);

/// glibc maps every large block by itself, always (a fixed threshold: by default it moves blocks
/// the size of one freed into the heap, where no advice reaches them), and keeps up to 8 MB of
/// freed heap at its top rather than trimming it page by page (its own rule for a 4 MB threshold).
const bool kMallocTuned =
    mallopt(M_MMAP_THRESHOLD, static_cast<int>(kLarge)) == 1 && mallopt(M_TRIM_THRESHOLD, 8 << 20) == 1;

/// The size to ask malloc for `size` bytes so that glibc maps a whole number of 2 MB pages (the
/// kernel places such a mapping on a 2 MB boundary): the block's memory then starts 16 bytes
/// into a 2 MB page and every page of it can be a huge one.
std::size_t whole_huge_pages(std::size_t size) {
  const std::size_t mapped = (size + 2 * kChunkHeader + kHugePage - 1) & ~(kHugePage - 1);
  return mapped - 2 * kChunkHeader;
}

#ifndef MADV_COLLAPSE
#define MADV_COLLAPSE 25  // Linux 6.1; older kernels refuse it, and the first 2 MB keep 4 KB pages
#endif
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14; older kernels refuse it, and the tail faults as used
#endif

/// Asks for 2 MB pages on the mapping holding the large block `p` of `size` bytes, over the 2 MB
/// pages its bytes cover, the last one only when they fill at least 3/4 of it (so a block holds
/// at most 512 KB that only the rounding made: peak memory does not grow). A shorter tail keeps
/// 4 KB pages but gets them all now, in one call (MADV_POPULATE_WRITE: half the cost of faulting
/// them one by one); a block filled only in part (a vector grown by doubling) pays that tail
/// early. glibc wrote the block's header into its first page before the advice, so that 2 MB
/// already has a table of 4 KB pages: MADV_COLLAPSE makes it one huge page now rather than 511
/// faults later. Errors are ignored (a kernel without transparent huge pages or these calls
/// simply faults 4 KB pages as they are used).
void advise_huge_pages(void* p, std::size_t size) {
  const std::uintptr_t start = (reinterpret_cast<std::uintptr_t>(p) - kChunkHeader) & ~std::uintptr_t{4095};
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(p) + size;
  const std::uintptr_t huge = (end - start + kHugePage / 4) & ~(kHugePage - 1);
  auto* mapping = reinterpret_cast<void*>(start);
  if (madvise(mapping, huge, MADV_HUGEPAGE) != 0) return;
  madvise(mapping, kHugePage, MADV_COLLAPSE);
  if (start + huge < end) madvise(reinterpret_cast<void*>(start + huge), end - start - huge, MADV_POPULATE_WRITE);
}

/// malloc with operator new's contract: the new-handler until it succeeds, else bad_alloc.
void* allocate(std::size_t size) {
  if (size == 0) size = 1;
  const std::size_t asked = size >= kLarge && kMallocTuned ? whole_huge_pages(size) : size;
  for (;;) {
    if (void* p = std::malloc(asked)) {
      if (asked != size) advise_huge_pages(p, size);
      return p;
    }
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t size) {
  return allocate(size);
}
void* operator new[](std::size_t size) {
  return allocate(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
