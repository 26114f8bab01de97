// The tools allocate and touch hundreds of megabytes at a time (a level's records, its
// compiled bytes, a frame's PNG buffers), and a page fault on these virtual machines
// costs microseconds. Linked with mimalloc as their allocator, they take its memory from
// an arena of address space marked for transparent huge pages (where the kernel allows
// them): a fault per 2 MB rather than per 4 KB. mapc on a Freedoom map: 0.4 of the time
// and a twentieth of the faults; the sanitizer builds keep their own allocator.
#include <mimalloc-new-delete.h>  // new and delete straight to mimalloc (once per program: here)
#include <mimalloc.h>
#include <sys/mman.h>

#include <cstdint>

#include "tools/large_pages.h"

namespace {

// Address space only: a page is backed when first touched, as any allocation's.
constexpr size_t kArenaBytes = size_t(64) << 30;
constexpr size_t kArenaAlign = size_t(64) << 20;  // a multiple of mimalloc's segment alignment

// Before main, so that all but the C++ runtime's first allocations come from the arena;
// where the address space or the kernel's huge pages are not there, mimalloc maps its
// own memory as usual.
mi_arena_id_t arena_id;

const bool huge_page_arena = [] {
  void* space = mmap(nullptr, kArenaBytes + kArenaAlign, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (space == MAP_FAILED) return false;
  const uintptr_t start = (reinterpret_cast<uintptr_t>(space) + kArenaAlign - 1) & ~(kArenaAlign - 1);
  void* arena = reinterpret_cast<void*>(start);
  madvise(arena, kArenaBytes, MADV_HUGEPAGE);
  // The arena is the main thread's own: its default heap moves there from the segment
  // mimalloc mapped at start-up (in small pages, before this ran). Given as not
  // committed, mimalloc commits and decommits its ranges itself, so freed memory leaves
  // the process as it would under glibc (as committed, the hostile levels' peaks grew by
  // 40-150%).
  if (!mi_manage_os_memory_ex(arena, kArenaBytes, /*is_committed=*/false, /*is_large=*/false, /*is_zero=*/true,
                              /*numa_node=*/-1, /*exclusive=*/true, &arena_id))
    return false;
  return p3d::large_pages_for_this_thread();
}();

}  // namespace

namespace p3d {

// A thread's heap in the arena (mimalloc's heaps are each their thread's own).
bool large_pages_for_this_thread() {
  mi_heap_t* heap = mi_heap_new_in_arena(arena_id);
  if (heap) mi_heap_set_default(heap);
  return heap != nullptr;
}

}  // namespace p3d
