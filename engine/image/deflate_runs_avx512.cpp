// find_runs' two scans 64 bytes to a compare: this file alone is built for AVX-512BW
// (engine/CMakeLists.txt), and deflate_runs.cpp calls it only where the processor has
// it. The same runs as the SSE2 scans', so the same stream.
#include <immintrin.h>

#include "engine/image/deflate_find_runs.h"

namespace p3d::image::deflate {

namespace {

struct Avx512Scan {
  // The first j >= i where bytes j to j + 15 each equal the one before, 49 places a
  // compare: bit k of `same` says byte j + k equals byte j + k - 1, and the shifts
  // bring in zeros, so only places whose sixteen lie within the 64 compared are found.
  static size_t next_run(const uint8_t* bytes, size_t i, size_t n) {
    static_assert(kShortestMatch == 16, "the runs of equal bytes are found by doubling to sixteen");
    size_t j = std::max<size_t>(i, 1);
    for (; j + 64 <= n; j += 49) {
      const uint64_t same = _mm512_cmpeq_epi8_mask(_mm512_loadu_si512(bytes + j), _mm512_loadu_si512(bytes + j - 1));
      uint64_t runs = same & same >> 1;  // bit k: bytes j + k to j + k + 15 each equal the one before
      runs &= runs >> 2;
      runs &= runs >> 4;
      runs &= runs >> 8;
      if (runs) return j + size_t(std::countr_zero(runs));
    }
    return sse2_next_run(bytes, j, n);
  }
  // The bytes from `at` equal to the one before it, up to `limit`.
  static size_t run_length(const uint8_t* at, size_t limit) {
    const __m512i repeated = _mm512_set1_epi8(char(at[-1]));
    size_t n = 0;
    for (; n + 64 <= limit; n += 64) {
      const uint64_t same = _mm512_cmpeq_epi8_mask(_mm512_loadu_si512(at + n), repeated);
      if (same != ~uint64_t(0)) return n + size_t(std::countr_one(same));
    }
    return n + sse2_run_length(at + n, limit - n);
  }
};

}  // namespace

size_t find_runs_avx512(const uint8_t* bytes, size_t begin, size_t end, size_t readable, Run* runs,
                        uint32_t* frequency) {
  return find_runs<Avx512Scan>(bytes, begin, end, readable, runs, frequency);
}

}  // namespace p3d::image::deflate
