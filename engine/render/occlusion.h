// The W-bit column occlusion array of the survey's Algorithm 13, stored as 64-bit
// words: bit x is set once screen column x is closed.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace p3d::render {

class ColumnMask {
 public:
  void reset(int width) {
    width_ = width;
    closed_ = 0;
    words_.assign((width + 63) / 64, 0);
  }

  // Closes every column outside [x0, x1): a strip of the screen walks the tree alone.
  // A word at a time: each strip of a frame does it, over the whole width.
  void close_outside(int x0, int x1) {
    for (int w = 0; w < int(words_.size()); ++w) {
      const uint64_t outside = columns_below(w, width_) & ~(columns_below(w, x1) & ~columns_below(w, x0));
      closed_ += std::popcount(outside & ~words_[w]);
      words_[w] |= outside;
    }
  }

  bool full() const { return closed_ == width_; }
  int closed_count() const { return closed_; }
  bool is_closed(int x) const { return words_[x >> 6] >> (x & 63) & 1; }
  const uint64_t* words() const { return words_.data(); }  // bit x of word x / 64: column x closed

  void close(int x) {
    uint64_t& w = words_[x >> 6];
    const uint64_t bit = uint64_t{1} << (x & 63);
    closed_ += (w & bit) == 0;
    w |= bit;
  }

  // True when every column in [x0, x1] is closed (x0 <= x1, both on screen).
  bool all_closed(int x0, int x1) const {
    for (int w = x0 >> 6; w <= x1 >> 6; ++w)
      if (~words_[w] & range_bits(w, x0, x1)) return false;
    return true;
  }

  // Calls f(x) for every column in [x0, x1] that is open when the call reaches it.
  template <typename F>
  void for_each_open(int x0, int x1, F&& f) const {
    for (int w = x0 >> 6; w <= x1 >> 6; ++w) {
      uint64_t open = ~words_[w] & range_bits(w, x0, x1);
      while (open) {
        f((w << 6) + std::countr_zero(open));
        open &= open - 1;
      }
    }
  }

 private:
  // The bits of word w for the columns left of x.
  static uint64_t columns_below(int w, int x) {
    const int n = std::clamp(x - (w << 6), 0, 64);
    return n == 64 ? ~uint64_t{0} : (uint64_t{1} << n) - 1;
  }
  // The bits of word w that lie in [x0, x1].
  static uint64_t range_bits(int w, int x0, int x1) {
    const int lo = std::max(x0 - (w << 6), 0), hi = std::min(x1 - (w << 6), 63);
    return (~uint64_t{0} >> (63 - hi)) & (~uint64_t{0} << lo);
  }

  int width_ = 0, closed_ = 0;
  std::vector<uint64_t> words_;
};

}  // namespace p3d::render
