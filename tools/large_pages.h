// The tools' memory in 2 MB pages (large_pages.cpp, where mimalloc is linked).
#pragma once

namespace p3d {

#ifdef P3D_MIMALLOC
// Moves the calling thread's allocations into the arena of 2 MB pages, as the main
// thread's are from the start; false where there is no arena.
bool large_pages_for_this_thread();
#else
inline bool large_pages_for_this_thread() { return false; }
#endif

}  // namespace p3d
