// What the processor offers beyond x86-64's baseline, each asked once. Only the files
// built with a vector loop for it ask (their CMake definitions say they were).
#pragma once

namespace p3d {

#if defined(__x86_64__) || defined(__i386__)
#define P3D_CPU_HAS(...) __VA_ARGS__
#else
#define P3D_CPU_HAS(...) false
#endif

// AVX2: the PNG filters' 32 bytes at a time.
inline bool has_avx2() {
  static const bool yes = P3D_CPU_HAS(__builtin_cpu_supports("avx2"));
  return yes;
}

// AVX-512 with BW's byte compares: the deflater's scans for runs.
inline bool has_avx512_bw() {
  static const bool yes = P3D_CPU_HAS(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw"));
  return yes;
}

// AVX-512 with VL and DQ's doubles and 64-bit integers: the projection of a wall's ends.
inline bool has_avx512_vl_dq() {
  static const bool yes = P3D_CPU_HAS(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                                      __builtin_cpu_supports("avx512dq"));
  return yes;
}

// AVX-512 with VBMI's byte permutes (and BW's byte compares): the column, flat and
// palette loops.
inline bool has_avx512_vbmi() {
  static const bool yes = has_avx512_bw() && P3D_CPU_HAS(__builtin_cpu_supports("avx512vbmi"));
  return yes;
}

#undef P3D_CPU_HAS

}  // namespace p3d
