// Puts the CLI's heap on transparent huge pages before anything allocates much.
//
// A short offsetgen run (generate, density, list) touches a few MiB of fresh heap, and on the virtual
// machines it runs on the first touch of each 4 KiB page costs 15-17 us: about 260 faults, 4-5 ms, of a
// 21 ms gyroid order 4 generation. A 2 MiB page costs about 150 us once (BENCHMARKS.md, start-up).
// Only address space is reserved here; pages that are never touched cost nothing. Where the kernel
// offers no transparent huge pages, madvise fails and the heap behaves as before.
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr int kReserve = 64 << 20;
constexpr std::size_t kProbe = 256 << 10;

// Held for the life of the process, so that the heap's next block starts on a huge page.
void* volatile skipped = nullptr;

// Priority 101: before the static initialisers of everything linked into this executable (GiNaC's and
// CLN's among them), which allocate from the same heap.
__attribute__((constructor(101))) void put_heap_on_huge_pages() {
  // One contiguous heap: large blocks from it too (not from mmap, 4 KiB pages each), and it is not
  // given back while the process runs.
  mallopt(M_MMAP_THRESHOLD, kReserve);
  mallopt(M_TRIM_THRESHOLD, 2 * kReserve);
  mallopt(M_TOP_PAD, kReserve);
  // Grow the heap now, by the reserve, and mark its aligned part.
  void* probe = std::malloc(kProbe);
  if (probe == nullptr) {
    return;
  }
  const auto at = reinterpret_cast<std::uintptr_t>(probe);
  char* const heap_end = static_cast<char*>(sbrk(0));
  const auto heap_end_at = reinterpret_cast<std::uintptr_t>(heap_end);
  // At least the probe's size past it, so that the skipping block is too large for any free chunk
  // and comes from the heap's top.
  const auto begin = (at + kProbe + kHugePage - 1) & ~(kHugePage - 1);
  const auto end = heap_end_at & ~(kHugePage - 1);
  std::free(probe);
  if (begin >= end || madvise(heap_end - (heap_end_at - begin), end - begin, MADV_HUGEPAGE) != 0) {
    return;
  }
  // Skip to the aligned start, so that what comes next lies on huge pages: a run allocates about 1 MiB,
  // which would otherwise fit before it. The skipped block's pages are never touched.
  skipped = std::malloc(begin - at);
}

}  // namespace
