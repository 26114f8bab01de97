// What the processor offers beyond x86-64's baseline, asked once. Only the files built
// with a vector loop for it ask (their CMake definitions say they were).
#pragma once

namespace p3d {

// AVX-512 with VBMI's byte permutes (and BW's byte compares): the column, flat and
// palette loops.
inline bool has_avx512_vbmi() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool vbmi = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                           __builtin_cpu_supports("avx512vbmi");
  return vbmi;
#else
  return false;
#endif
}

}  // namespace p3d
