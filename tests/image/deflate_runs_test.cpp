// The run-length deflater against libdeflate's decompressor (an independent inflater
// that refuses what RFC 1950/1951 do not allow): every input back exactly, runs of
// every length, skewed frequencies, and codes cut to 14 bits whose longest literals go
// four to a put of the bit writer.
#include <libdeflate.h>

#include <gtest/gtest.h>

#include <array>

#include "engine/image/deflate_find_runs.h"
#include "engine/image/deflate_runs.h"
#include "engine/util/rng.h"

namespace p3d::image {
namespace {

std::vector<uint8_t> inflate(const std::vector<uint8_t>& stream, size_t size) {
  libdeflate_decompressor* d = libdeflate_alloc_decompressor();
  std::vector<uint8_t> out(size + 1);
  size_t got = 0;
  const libdeflate_result r = libdeflate_zlib_decompress(d, stream.data(), stream.size(), out.data(), out.size(), &got);
  libdeflate_free_decompressor(d);
  EXPECT_EQ(r, LIBDEFLATE_SUCCESS);
  out.resize(r == LIBDEFLATE_SUCCESS ? got : 0);
  return out;
}

void expect_round_trip(const std::vector<uint8_t>& in, const std::string& what) {
  std::vector<uint8_t> stream = {0xAB};  // appended after what is there
  deflate_runs(in, stream);
  ASSERT_EQ(stream[0], 0xAB) << what;
  stream.erase(stream.begin());
  EXPECT_EQ(inflate(stream, in.size()), in) << what;
  std::vector<uint8_t> again;
  deflate_runs(in, again);
  EXPECT_EQ(again, stream) << what << ": the same bytes give the same stream";
}

TEST(DeflateRuns, EveryInputComesBackExactly) {
  expect_round_trip({}, "empty");
  expect_round_trip({7}, "one byte");
  expect_round_trip({7, 7}, "two equal bytes");
  expect_round_trip(std::vector<uint8_t>(100000, 0), "zeros");
  Rng rng(11);
  std::vector<uint8_t> noise(70000);
  for (uint8_t& b : noise) b = uint8_t(rng.next());
  expect_round_trip(noise, "noise");
  std::vector<uint8_t> runs;  // a run of every length from 1 to 600, byte values alternating
  for (size_t n = 1; n <= 600; ++n) runs.insert(runs.end(), n, uint8_t(n % 2 ? 3 : 200));
  expect_round_trip(runs, "runs of every length");
  std::vector<uint8_t> mixed;  // runs short and long (from 16) among literals, every byte value
  for (int i = 0; i < 50000; ++i) mixed.insert(mixed.end(), size_t(1 + rng.below(24)), uint8_t(rng.below(256)));
  expect_round_trip(mixed, "mixed");
}

// Fed a piece at a time, as a PNG's rows are filtered, the deflater writes the very
// stream of the whole input at once: inputs of whole blocks and one to four bytes more
// or fewer (a block waits for the three bytes after it), in pieces of every size.
TEST(DeflateRuns, PiecesMakeTheSameStreamAsTheWhole) {
  Rng rng(12);
  for (const size_t blocks : {0, 1, 2, 3})
    for (int extra = -4; extra <= 4; ++extra) {
      if (blocks == 0 && extra < 0) continue;
      std::vector<uint8_t> in(blocks * kDeflateBlockBytes + size_t(extra));
      for (size_t i = 0; i < in.size(); i += 1 + rng.below(30)) in[i] = uint8_t(rng.below(4));  // runs among literals
      std::vector<uint8_t> whole;
      deflate_runs(in, whole);
      for (const size_t largest : {1, 3, 641, 4000, 100000}) {
        std::vector<uint8_t> pieces = {0xAB};  // appended after what is there
        {
          DeflateRuns deflater(pieces);
          for (size_t at = 0; at < in.size();) {
            const size_t n = std::min(in.size() - at, size_t(1 + rng.below(largest)));
            std::copy_n(in.data() + at, n, deflater.room(n));
            deflater.wrote(n);
            at += n;
          }
          deflater.finish();
        }
        const std::string what = std::to_string(in.size()) + " bytes in pieces of up to " + std::to_string(largest);
        ASSERT_EQ(pieces[0], 0xAB) << what;
        pieces.erase(pieces.begin());
        EXPECT_EQ(pieces, whole) << what;
        EXPECT_EQ(inflate(pieces, in.size()), in) << what;
      }
    }
}

TEST(DeflateRuns, SkewedFrequenciesComeBack) {
  // Symbol k appearing Fibonacci(k) times, shuffled: three blocks, each with codes from
  // 1 to 14 bits long.
  std::vector<uint8_t> skewed;
  uint64_t a = 1, b = 1;
  for (int symbol = 0; symbol < 25; ++symbol, std::swap(a, b), b += a)
    for (uint64_t i = 0; i < a; ++i) skewed.push_back(uint8_t(symbol * 10));
  Rng rng(3);
  for (size_t i = skewed.size(); i > 1; --i) std::swap(skewed[i - 1], skewed[rng.below(i)]);  // no runs to speak of
  expect_round_trip(skewed, "Fibonacci frequencies");
}

TEST(DeflateRuns, LiteralsOfTheLongestCodesComeBackFourToAPut) {
  // Symbol k (k = 0..15) appearing 2^k times, 64 KB in all (one block): unlimited, the
  // rarest codes would be 16 bits long; cut to 14, the four rarest symbols take 14 bits
  // each. They come first, fifteen in a row with no two alike (no runs): the bit writer
  // puts four such literals at once, 56 bits.
  std::vector<uint8_t> bytes;
  for (int k : {3, 2, 3, 1, 3, 2, 3, 0, 3, 2, 3, 1, 3, 2, 3}) bytes.push_back(uint8_t(k * 16));
  std::vector<uint8_t> others;
  for (int k = 4; k < 15; ++k) others.insert(others.end(), size_t(1) << k, uint8_t(k * 16));
  Rng rng(5);
  for (size_t i = others.size(); i > 1; --i) std::swap(others[i - 1], others[rng.below(i)]);
  size_t most = size_t(1) << 15;  // the commonest symbol between the others: no runs
  for (const uint8_t o : others) {
    bytes.push_back(o);
    if (most) bytes.push_back(15 * 16), --most;
  }
  bytes.insert(bytes.end(), most, uint8_t(15 * 16));
  ASSERT_EQ(bytes.size(), size_t(65535));
  expect_round_trip(bytes, "powers of two, the rarest first");
}

// The scans for runs 64 bytes at a time (AVX-512BW) find the SSE2 scans' very runs and
// count the same literals, so the stream is the same on any processor: runs of every
// length from 1 to 300 among literals, blocks starting and ending anywhere.
TEST(DeflateRuns, WideScansFindTheSameRuns) {
#if defined(__x86_64__)
  if (!__builtin_cpu_supports("avx512f") || !__builtin_cpu_supports("avx512bw"))
    GTEST_SKIP() << "no AVX-512BW on this processor";
  Rng rng(13);
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<uint8_t> in;
    const size_t size = size_t(rng.range(1, trial < 200 ? 300 : 6000));
    while (in.size() < size) {  // short stretches and long runs, of few byte values (so runs meet)
      const size_t length = size_t(rng.below(4) == 0 ? rng.range(1, 300) : rng.range(1, 24));
      in.insert(in.end(), length, uint8_t(rng.below(3) == 0 ? rng.next() : rng.below(3)));
    }
    const size_t begin = size_t(rng.below(in.size())), end = begin + size_t(rng.below(in.size() - begin + 1));
    const size_t readable = end + size_t(rng.below(in.size() - end + 1));
    const size_t room = (end - begin) / deflate::kShortestMatch + 1;
    std::vector<deflate::Run> narrow(room), wide(room);
    std::array<uint32_t, 286> narrow_counts{}, wide_counts{};
    const size_t n = deflate::find_runs<deflate::Sse2Scan>(in.data(), begin, end, readable, narrow.data(),
                                                            narrow_counts.data());
    const size_t w = deflate::find_runs_avx512(in.data(), begin, end, readable, wide.data(), wide_counts.data());
    const std::string what = "trial " + std::to_string(trial) + ", bytes [" + std::to_string(begin) + ", " +
                             std::to_string(end) + ") of " + std::to_string(in.size());
    ASSERT_EQ(w, n) << what;
    for (size_t r = 0; r < n; ++r) {
      ASSERT_EQ(wide[r].at, narrow[r].at) << what << ", run " << r;
      ASSERT_EQ(wide[r].length, narrow[r].length) << what << ", run " << r;
    }
    ASSERT_EQ(wide_counts, narrow_counts) << what;
  }
#else
  GTEST_SKIP() << "the AVX-512 scans are built on x86-64 only";
#endif
}

TEST(DeflateRuns, RunsCompress) {
  std::vector<uint8_t> stream;
  deflate_runs(std::vector<uint8_t>(1 << 20, 9), stream);
  EXPECT_LT(stream.size(), size_t(2000));  // about a bit per 258 bytes
}

}  // namespace
}  // namespace p3d::image
