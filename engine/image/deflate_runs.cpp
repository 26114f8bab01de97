#include "engine/image/deflate_runs.h"

#include <libdeflate.h>  // adler32

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <memory>

#include "engine/image/deflate_find_runs.h"
#include "engine/util/cpu.h"

namespace p3d::image {

using deflate::kLengthCodes;
using deflate::kMaxRun;
using deflate::kShortestMatch;
using deflate::LengthCode;
using deflate::Run;

namespace {

constexpr int kLiteralLengthSymbols = 286, kEndOfBlock = 256, kMaxCodeBits = 15;
// The literal/length codes are kept to 14 bits (deflate allows 15) so that four
// literals fit one put of the bit writer; a frame's rarest bytes lose a bit at most.
constexpr int kMaxLiteralBits = 14;
static_assert(4 * kMaxLiteralBits + 7 <= 64, "four literals and the bits of a partial byte fit 64 bits");
constexpr int kCodeLengthSymbols = 19, kMaxCodeLengthBits = 7;
// The order in which a block's header gives the code length code's lengths.
constexpr uint8_t kCodeLengthOrder[kCodeLengthSymbols] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

// Code lengths of at most max_bits for symbols of the given frequencies: a Huffman
// code (two queues over the leaves in order of frequency), its lengths' histogram then
// made to fit max_bits (by moving leaves up the tree until Kraft's sum is 1 again), the
// shortest lengths given to the most frequent symbols. Always a complete code of two
// symbols or more (decoders may refuse a lone code), so an unused symbol may get one.
void huffman_lengths(const uint32_t* frequency, int symbols, int max_bits, uint8_t* lengths) {
  std::fill(lengths, lengths + symbols, uint8_t(0));
  // Symbols by frequency, then by symbol: sorted as one key each, frequency above symbol.
  std::array<uint64_t, kLiteralLengthSymbols> by_frequency{};
  int used = 0;
  for (int s = 0; s < symbols; ++s)
    if (frequency[s]) by_frequency[size_t(used++)] = uint64_t(frequency[s]) << 16 | uint64_t(s);
  for (int s = 0; used < 2; ++s)
    if (!frequency[s]) by_frequency[size_t(used++)] = uint64_t(s);  // its frequency counts as 0
  std::sort(by_frequency.begin(), by_frequency.begin() + used);
  std::array<uint16_t, kLiteralLengthSymbols> leaf{};
  for (int i = 0; i < used; ++i) leaf[size_t(i)] = uint16_t(by_frequency[size_t(i)]);
  // Nodes 0..used-1 are the leaves, then each merge; a node's parent comes after it.
  std::array<uint64_t, 2 * kLiteralLengthSymbols> weight{};
  std::array<uint16_t, 2 * kLiteralLengthSymbols> parent{}, depth{};
  for (int i = 0; i < used; ++i) weight[size_t(i)] = frequency[leaf[size_t(i)]];
  int next_leaf = 0, next_inner = used;
  auto smallest = [&](int made) {
    return next_leaf < used && (next_inner >= made || weight[size_t(next_leaf)] <= weight[size_t(next_inner)])
               ? next_leaf++
               : next_inner++;
  };
  for (int made = used; made < 2 * used - 1; ++made) {
    const int a = smallest(made), b = smallest(made);
    weight[size_t(made)] = weight[size_t(a)] + weight[size_t(b)];
    parent[size_t(a)] = parent[size_t(b)] = uint16_t(made);
  }
  std::array<int, kLiteralLengthSymbols + 1> count{};  // leaves by depth, the deepest clamped to max_bits
  depth[size_t(2 * used - 2)] = 0;
  for (int i = 2 * used - 3; i >= 0; --i) {
    depth[size_t(i)] = uint16_t(depth[parent[size_t(i)]] + 1);
    if (i < used) ++count[size_t(std::min<int>(depth[size_t(i)], max_bits))];
  }
  uint32_t kraft = 0;  // the sum of 2^(max_bits - length)
  for (int bits = 1; bits <= max_bits; ++bits) kraft += uint32_t(count[size_t(bits)]) << (max_bits - bits);
  while (kraft > (1u << max_bits)) {  // a leaf at max_bits moves under a shorter one, split in two
    --count[size_t(max_bits)];
    for (int bits = max_bits - 1; bits > 0; --bits)
      if (count[size_t(bits)]) {
        --count[size_t(bits)];
        count[size_t(bits + 1)] += 2;
        break;
      }
    --kraft;
  }
  int k = 0;  // the least frequent take the longest
  for (int bits = max_bits; bits >= 1; --bits)
    for (int c = 0; c < count[size_t(bits)]; ++c) lengths[leaf[size_t(k++)]] = uint8_t(bits);
}

// Canonical codes for the lengths (RFC 1951, 3.2.2), bit-reversed: deflate sends a
// code's first bit first, and the bit writer fills bytes from their low bits.
void canonical_codes(const uint8_t* lengths, int symbols, uint16_t* codes) {
  auto reversed = [](uint32_t code, int n) {
    uint32_t r = 0;
    for (int i = 0; i < n; ++i, code >>= 1) r = r << 1 | (code & 1);
    return r;
  };
  std::array<uint32_t, kMaxCodeBits + 2> count{}, next{};
  for (int s = 0; s < symbols; ++s) ++count[lengths[s]];
  count[0] = 0;
  for (int bits = 1, code = 0; bits <= kMaxCodeBits; ++bits) next[size_t(bits)] = uint32_t(code = (code + int(count[size_t(bits) - 1])) << 1);
  for (int s = 0; s < symbols; ++s) {
    const int n = lengths[s];
    if (!n) continue;
    const uint32_t code = next[size_t(n)]++;
    codes[s] = uint16_t(reversed(code, n));
  }
}

// Bits into bytes, low bits first, without a branch: the buffer's eight bytes are
// stored at each put and the whole bytes among them kept (a put adds at most 56 bits
// to fewer than 8). The output needs 8 bytes of room past its end.
class BitWriter {
 public:
  // Writing at `out`, after `count` bits (fewer than 8) not yet whole bytes.
  BitWriter(uint8_t* out, uint64_t bits = 0, int count = 0) : out_(out), bits_(bits), count_(count) {}
  uint64_t pending_bits() const { return bits_; }
  int pending_count() const { return count_; }
  void put(uint64_t value, int n) {
    bits_ |= value << count_;
    count_ += n;
    std::memcpy(out_, &bits_, 8);  // little-endian
    const int bytes = count_ >> 3;
    out_ += bytes;
    bits_ >>= 8 * bytes;
    count_ &= 7;
  }
  // Starts again at `out`, the whole bytes so far behind; returns where they ended.
  uint8_t* rewind(uint8_t* out) {
    uint8_t* end = out_;
    out_ = out;
    return end;
  }
  // The last bits, to the next byte, into out (room for one); returns where they ended.
  uint8_t* finish_into(uint8_t* out) {
    if (count_ > 0) *out++ = uint8_t(bits_);
    return out;
  }

 private:
  uint8_t* out_;
  uint64_t bits_ = 0;
  int count_ = 0;
};

// A code length sequence (the literal/length lengths, then the distance lengths) as
// the code length alphabet's symbols: 16 repeats the last length 3-6 times, 17 and 18
// give 3-10 and 11-138 zeros.
struct CodeLength {
  uint8_t symbol, extra;
};
std::vector<CodeLength> code_length_symbols(const std::vector<uint8_t>& lengths) {
  std::vector<CodeLength> out;
  for (size_t k = 0; k < lengths.size();) {
    const uint8_t length = lengths[k];
    size_t run = 1;
    while (k + run < lengths.size() && lengths[k + run] == length) ++run;
    k += run;
    if (length == 0) {
      for (; run >= 11; run -= std::min<size_t>(run, 138)) out.push_back({18, uint8_t(std::min<size_t>(run, 138) - 11)});
      if (run >= 3) out.push_back({17, uint8_t(run - 3)}), run = 0;
    } else {
      out.push_back({length, 0}), --run;
      for (; run >= 3; run -= std::min<size_t>(run, 6)) out.push_back({16, uint8_t(std::min<size_t>(run, 6) - 3)});
    }
    for (; run > 0; --run) out.push_back({length, 0});
  }
  return out;
}

// One block of dynamic Huffman codes: its header (the codes' lengths, themselves
// Huffman coded), its literals and runs, and its end.
void write_block(const uint8_t* bytes, size_t begin, size_t end, size_t readable, const Run* runs, size_t run_count,
                 std::array<uint32_t, kLiteralLengthSymbols>& frequency, bool last, BitWriter& writer) {
  BitWriter bits = writer;  // a local copy, kept in registers: `writer` may be memory the compiler must update
  frequency[kEndOfBlock] = 1;
  std::array<uint8_t, kLiteralLengthSymbols> lengths{};
  std::array<uint16_t, kLiteralLengthSymbols> codes{};
  huffman_lengths(frequency.data(), kLiteralLengthSymbols, kMaxLiteralBits, lengths.data());
  canonical_codes(lengths.data(), kLiteralLengthSymbols, codes.data());
  int literal_symbols = kLiteralLengthSymbols;
  while (literal_symbols > 257 && lengths[size_t(literal_symbols - 1)] == 0) --literal_symbols;
  // Distance codes 0 (distance 1) and 1 (unused), one bit each: a complete code.
  std::vector<uint8_t> sequence(lengths.begin(), lengths.begin() + literal_symbols);
  sequence.insert(sequence.end(), {1, 1});
  const std::vector<CodeLength> header = code_length_symbols(sequence);
  std::array<uint32_t, kCodeLengthSymbols> header_frequency{};
  for (const CodeLength& c : header) ++header_frequency[c.symbol];
  std::array<uint8_t, kCodeLengthSymbols> header_lengths{};
  std::array<uint16_t, kCodeLengthSymbols> header_codes{};
  huffman_lengths(header_frequency.data(), kCodeLengthSymbols, kMaxCodeLengthBits, header_lengths.data());
  canonical_codes(header_lengths.data(), kCodeLengthSymbols, header_codes.data());
  int header_symbols = kCodeLengthSymbols;
  while (header_symbols > 4 && header_lengths[kCodeLengthOrder[header_symbols - 1]] == 0) --header_symbols;

  // A run's bits at once: its length's code and extra bits, and distance 1's code (0).
  std::array<uint32_t, kMaxRun + 1> run_bits{};
  std::array<uint8_t, kMaxRun + 1> run_bit_count{};
  for (size_t length = kShortestMatch; length <= kMaxRun; ++length) {
    const LengthCode& c = kLengthCodes[length];
    run_bits[length] = codes[c.symbol] | uint32_t(c.extra) << lengths[c.symbol];
    run_bit_count[length] = uint8_t(lengths[c.symbol] + c.extra_bits + 1);
  }

  bits.put(last, 1);
  bits.put(2, 2);  // dynamic Huffman codes
  bits.put(uint32_t(literal_symbols - 257), 5);
  bits.put(2 - 1, 5);
  bits.put(uint32_t(header_symbols - 4), 4);
  for (int k = 0; k < header_symbols; ++k) bits.put(header_lengths[kCodeLengthOrder[k]], 3);
  constexpr int kExtraBits[kCodeLengthSymbols] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 3, 7};
  for (const CodeLength& c : header) {
    bits.put(header_codes[c.symbol], header_lengths[c.symbol]);
    if (kExtraBits[c.symbol]) bits.put(c.extra, kExtraBits[c.symbol]);
  }
  // Literals four to a put (at most 56 bits): a quarter of the writer's chain of dependences.
  const auto literals = [&](size_t from, size_t to) {
    if (to + 3 > readable) {
      for (; from < to; ++from) bits.put(codes[bytes[from]], lengths[bytes[from]]);
      return;
    }
    for (; from < to; from += 4) {  // the last four masked to what is left, as find_runs counts them
      const uint8_t* b = bytes + from;
      uint32_t code[4], length[4];
      for (size_t k = 0; k < 4; ++k) {
        const bool literal = k < to - from;
        code[k] = literal ? codes[b[k]] : 0, length[k] = literal ? lengths[b[k]] : 0;
      }
      const uint64_t low = code[0] | uint64_t(code[1]) << length[0];
      const uint64_t high = code[2] | uint64_t(code[3]) << length[2];
      const uint32_t low_bits = length[0] + length[1];
      bits.put(low | high << low_bits, int(low_bits + length[2] + length[3]));
    }
  };
  size_t i = begin;
  for (size_t r = 0; r < run_count; ++r) {
    literals(i, runs[r].at);
    bits.put(run_bits[runs[r].length], run_bit_count[runs[r].length]);
    i = runs[r].at + runs[r].length;
  }
  literals(i, end);
  bits.put(codes[kEndOfBlock], lengths[kEndOfBlock]);
  writer = bits;
}

}  // namespace

// A block's literals may read up to kLookahead bytes past it (find_runs), so it goes
// out once they are in too.
constexpr size_t kBlockBytes = kDeflateBlockBytes, kLookahead = 3;

void deflate_runs(std::span<const uint8_t> in, std::vector<uint8_t>& out) {
  DeflateRuns deflater(out);
  for (size_t at = 0; at < in.size();) {
    const size_t n = std::min(kBlockBytes, in.size() - at);
    std::memcpy(deflater.room(n), in.data() + at, n);
    deflater.wrote(n);
    at += n;
  }
  deflater.finish();
}

DeflateRuns::DeflateRuns(std::vector<uint8_t>& out) : out_(out) {
  out_.insert(out_.end(), {0x78, 0x01});  // deflate with a 32 KB window, the fastest level; a multiple of 31
}

uint8_t* DeflateRuns::room(size_t n) {
  if (size_ + n > input_.size()) {  // the blocks gone out make room: keep the byte before the next
    const size_t keep = begin_ > 0 ? begin_ - 1 : 0;
    if (size_ > keep) std::memmove(input_.data(), input_.data() + keep, size_ - keep);  // none yet: no buffer
    begin_ -= keep, size_ -= keep;
    if (size_ + n > input_.size()) input_.resize(std::max(size_ + n, 2 * kBlockBytes));
  }
  return input_.data() + size_;
}

void DeflateRuns::wrote(size_t n) {
  adler_ = libdeflate_adler32(adler_, input_.data() + size_, n);
  size_ += n;
  while (size_ - begin_ >= kBlockBytes + kLookahead) block(begin_ + kBlockBytes, false);
}

void DeflateRuns::finish() {
  for (;;) {  // at least one block, the last
    const size_t end = std::min(size_, begin_ + kBlockBytes);
    block(end, end == size_);
    if (begin_ == size_) break;
  }
  uint8_t tail[8];
  BitWriter bits(tail, bits_, bit_count_);
  out_.insert(out_.end(), tail, bits.finish_into(tail));
  for (int shift = 24; shift >= 0; shift -= 8) out_.push_back(uint8_t(adler_ >> shift));
}

// The block of input [begin_, end): its bytes out, but for the last bits of a byte.
void DeflateRuns::block(size_t end, bool last) {
  constexpr size_t kBlockRoom = 1100 + 2 * kBlockBytes;  // a literal is at most 14 bits; a header under 1 KB
  thread_local std::unique_ptr<Run[]> runs = std::make_unique_for_overwrite<Run[]>(kBlockBytes / kShortestMatch + 1);
  thread_local std::unique_ptr<uint8_t[]> buffer = std::make_unique_for_overwrite<uint8_t[]>(kBlockRoom);
  BitWriter bits(buffer.get(), bits_, bit_count_);
  std::array<uint32_t, kLiteralLengthSymbols> frequency{};
  auto find_runs = deflate::find_runs<deflate::Sse2Scan>;
#ifdef P3D_AVX512_RUNS
  if (has_avx512_bw()) find_runs = deflate::find_runs_avx512;
#endif
  const size_t run_count = find_runs(input_.data(), begin_, end, size_, runs.get(), frequency.data());
  write_block(input_.data(), begin_, end, size_, runs.get(), run_count, frequency, last, bits);
  out_.insert(out_.end(), buffer.get(), bits.rewind(buffer.get()));  // the whole bytes; the rest stay in bits
  bits_ = bits.pending_bits(), bit_count_ = bits.pending_count();
  begin_ = end;
}

}  // namespace p3d::image
