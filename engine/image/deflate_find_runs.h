// How deflate_runs.cpp finds a block's runs, shared with deflate_runs_avx512.cpp (built
// for AVX-512BW, called only where the processor has it). Its functions are in an
// unnamed namespace, so each file keeps its own build of them: nothing built for
// AVX-512 stands in for the SSE2 code.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace p3d::image::deflate {

// A run of a block: `length` bytes from `at` repeating the byte before them.
struct Run {
  size_t at, length;
};

// find_runs for processors with AVX-512BW (deflate_runs_avx512.cpp): the same runs,
// each scan 64 bytes to a compare.
size_t find_runs_avx512(const uint8_t* bytes, size_t begin, size_t end, size_t readable, Run* runs,
                        uint32_t* frequency);

namespace {

constexpr size_t kMinRun = 3, kMaxRun = 258;
// The shortest run sent as a match. A filtered frame's short runs are mostly zeros,
// whose literal codes are a bit or two: as literals they take few more bits than a
// match's length and distance codes. And each run costs the branches that end the
// stretches of literals around it, which the processor mispredicts: from sixteen
// rather than eight, a Doom frame's PNG takes a sixth less time and is 0.5-2% bigger.
// (From three it was 7% bigger than from eight; from thirty-two, 4% bigger than from
// sixteen for a further 7%.)
constexpr size_t kShortestMatch = 16;

// A match length's symbol (257..285) with its extra bits (RFC 1951, 3.2.5).
struct LengthCode {
  uint16_t symbol = 0;
  uint8_t extra_bits = 0;
  uint16_t extra = 0;
};
constexpr std::array<LengthCode, kMaxRun + 1> kLengthCodes = [] {
  constexpr uint16_t base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  constexpr uint8_t extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  std::array<LengthCode, kMaxRun + 1> codes{};
  for (size_t length = kMinRun; length <= kMaxRun; ++length) {
    int k = 28;
    while (base[k] > length) --k;
    codes[length] = {uint16_t(257 + k), extra[k], uint16_t(length - base[k])};
  }
  return codes;
}();

// The bytes from `at` equal to the one before it, up to `limit`: sixteen at a time.
inline size_t sse2_run_length(const uint8_t* at, size_t limit) {
  size_t n = 0;
#ifdef __SSE2__
  const __m128i repeated = _mm_set1_epi8(char(at[-1]));
  for (; n + 16 <= limit; n += 16) {
    const __m128i sixteen = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at + n));
    const uint32_t same = uint32_t(_mm_movemask_epi8(_mm_cmpeq_epi8(sixteen, repeated)));
    if (same != 0xFFFF) return n + size_t(std::countr_one(same));
  }
#endif
  while (n < limit && at[n] == at[-1]) ++n;
  return n;
}

// The first j >= i where a run of kShortestMatch or more starts (bytes j to j + 15 equal
// to byte j - 1), or n: sixteen places at a time with SSE2.
inline size_t sse2_next_run(const uint8_t* bytes, size_t i, size_t n) {
  static_assert(kShortestMatch == 16, "the runs of equal bytes are found by doubling to sixteen");
  size_t j = std::max<size_t>(i, 1);
#ifdef __SSE2__
  const auto load = [&](size_t at) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes + at)); };
  for (; j + 32 <= n; j += 16) {  // bit k of `same`: byte j + k equals the one before it
    const uint32_t same = uint32_t(_mm_movemask_epi8(_mm_cmpeq_epi8(load(j), load(j - 1)))) |
                          uint32_t(_mm_movemask_epi8(_mm_cmpeq_epi8(load(j + 16), load(j + 15)))) << 16;
    uint32_t runs = same & same >> 1;  // bit k: bytes j + k to j + k + 15 each equal the one before
    runs &= runs >> 2;
    runs &= runs >> 4;
    runs &= runs >> 8;
    if (runs & 0xFFFF) return j + size_t(std::countr_zero(runs));
  }
#endif
  for (; j + kShortestMatch <= n; ++j) {
    size_t k = 0;
    while (k < kShortestMatch && bytes[j + k] == bytes[j - 1]) ++k;
    if (k == kShortestMatch) return j;
  }
  return n;
}

// The two scans sixteen bytes at a time (SSE2), as find_runs takes them.
struct Sse2Scan {
  static size_t next_run(const uint8_t* bytes, size_t i, size_t n) { return sse2_next_run(bytes, i, n); }
  static size_t run_length(const uint8_t* at, size_t limit) { return sse2_run_length(at, limit); }
};

// The runs of bytes [begin, end) (a run may repeat the byte before `begin`), found by
// Scan's next_run and run_length, and the frequencies of the block's symbols: its
// literals (every byte outside a run) and its runs' length codes. `runs` has room for
// (end - begin) / kShortestMatch + 1. Returns how many runs.
// The literals between two runs are counted (and written, write_block) four at a time,
// the last four masked to what is left: they may read three bytes past the stretch,
// so they do where that is inside the input (bytes [0, readable)). A loop for the last
// zero to three is a branch the processor mispredicts at most stretches' ends (4-5% of
// a frame's encoding at 1920x1080, with run_length's sixteen at a time).
template <typename Scan>
size_t find_runs(const uint8_t* bytes, size_t begin, size_t end, size_t readable, Run* runs, uint32_t* frequency) {
  // The literals counted four at a time, a table for each (a repeated byte waits on no
  // one counter).
  std::array<std::array<uint32_t, 256>, 4> literal_counts{};
  const auto count_literals = [&](size_t from, size_t to) {
    if (to + 3 > readable) {
      for (; from < to; ++from) ++literal_counts[0][bytes[from]];
      return;
    }
    for (; from < to; from += 4)  // the last four masked to what is left
      for (size_t k = 0; k < 4; ++k) literal_counts[k][bytes[from + k]] += uint32_t(k < to - from);
  };
  size_t count = 0, i = begin;
  for (;;) {
    const size_t at = Scan::next_run(bytes, i, end);
    count_literals(i, at);
    if (at == end) break;
    const size_t length = Scan::run_length(bytes + at, std::min(kMaxRun, end - at));
    runs[count++] = {at, length};
    ++frequency[kLengthCodes[length].symbol];
    i = at + length;
  }
  for (size_t b = 0; b < 256; ++b)
    frequency[b] = literal_counts[0][b] + literal_counts[1][b] + literal_counts[2][b] + literal_counts[3][b];
  return count;
}

}  // namespace

}  // namespace p3d::image::deflate
