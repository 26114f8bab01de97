// The row filters' vector loops, written once over an instruction set's operations
// (png_filters.cpp's SSE2, png_filters_avx2.cpp's AVX2); included by those two files
// only. Each instantiation is compiled in one of them alone, so no code built for
// AVX2 is shared with the SSE2 path.
#pragma once

#include <cstddef>
#include <cstdint>

#include "engine/image/png_filters.h"

namespace p3d::image::lanes {

// Ops::kBytes bytes of a row with their neighbours: left (a), up (b) and up-left (c).
// Paeth's distances stay in bytes: pa = |b - c| and pb = |a - c| as unsigned
// differences, and pc = |(a - c) + (b - c)| their sum (saturated: 255 still orders
// after both) where a and b lie on one side of c, else the difference of the two.
template <typename Ops>
struct Pixels {
  using V = typename Ops::V;
  V r, a, b, c;
  // Ops::kBytes bytes from x, or (spread) the sixteen from x and from every 32 after it.
  template <bool kSpread = false>
  static Pixels at(const uint8_t* row, const uint8_t* up, size_t channels, size_t x) {
    const auto load = [](const uint8_t* p) { return kSpread ? Ops::load_spread(p) : Ops::load(p); };
    return {load(row + x), load(row + x - channels), load(up + x), load(up + x - channels)};
  }

  V filtered(int type) const {
    switch (type) {
      case 0: return r;
      case 1: return Ops::sub(r, a);
      case 2: return Ops::sub(r, b);
      case 3: return Ops::sub(r, average());
      default: return Ops::sub(r, paeth_predictor());
    }
  }
  // (a + b) >> 1 without overflow: avg rounds up, so take off the carry of a ^ b.
  V average() const { return Ops::sub(Ops::avg(a, b), Ops::bit_and(Ops::bit_xor(a, b), Ops::set1(1))); }
  V paeth_predictor() const {
    const auto distance = [](V x, V y) { return Ops::bit_or(Ops::subs(x, y), Ops::subs(y, x)); };
    const auto at_most = [](V x, V y) { return Ops::eq(Ops::min(x, y), x); };  // unsigned x <= y
    const V pa = distance(b, c), pb = distance(a, c);
    const V one_side = Ops::eq(at_most(c, a), at_most(c, b));
    const V pc = Ops::select(one_side, Ops::adds(pa, pb), distance(pa, pb));
    return Ops::select(Ops::bit_and(at_most(pa, pb), at_most(pa, pc)), a, Ops::select(at_most(pb, pc), b, c));
  }
};

// The five filters' magnitudes summed (|v ^ 128 - 128| is the magnitude of v as a
// signed byte: psadbw against 128), and Paeth's bytes written on the way.
template <typename Ops>
struct Costs {
  using V = typename Ops::V;
  V sums[5] = {Ops::zero(), Ops::zero(), Ops::zero(), Ops::zero(), Ops::zero()};

  V add(const Pixels<Ops>& p) {
    const V bias = Ops::set1(0x80);
    const V f[5] = {p.filtered(0), p.filtered(1), p.filtered(2), p.filtered(3), p.filtered(kPaethFilter)};
    for (int i = 0; i < 5; ++i) sums[i] = Ops::add64(sums[i], Ops::sad(Ops::bit_xor(f[i], bias), bias));
    return f[kPaethFilter];
  }
  void add_into(uint32_t* cost) const {
    for (int i = 0; i < 5; ++i) cost[i] += Ops::total(sums[i]);
  }
};

// A row's bytes from x, in steps of 32 while 32 remain: the first sixteen of each step
// costed (the sample), Paeth's bytes of all 32 written to out. Ops::kBytes / 16 steps
// at a time (their sampled sixteens in one vector, their other sixteens in another).
// Returns where it stopped.
template <typename Ops>
size_t cost_steps(const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, size_t x, uint32_t* cost,
                  uint8_t* out) {
  constexpr size_t kStep = 2 * Ops::kBytes;
  Costs<Ops> costs;
  for (; x + kStep <= stride; x += kStep) {
    Ops::store_spread(out + x, costs.add(Pixels<Ops>::template at<true>(row, up, channels, x)));
    Ops::store_spread(out + x + 16, Pixels<Ops>::template at<true>(row, up, channels, x + 16).filtered(kPaethFilter));
  }
  costs.add_into(cost);
  return x;
}

// Bytes [channels, stride) of a row filtered by `type` into out (stride >= channels +
// Ops::kBytes); the last step overlaps the one before it.
template <typename Ops>
void apply(int type, const uint8_t* row, const uint8_t* up, size_t channels, size_t stride, uint8_t* out) {
  const auto store = [&](size_t x) { Ops::store(out + x, Pixels<Ops>::at(row, up, channels, x).filtered(type)); };
  size_t x = channels;
  for (; x + Ops::kBytes <= stride; x += Ops::kBytes) store(x);
  if (x < stride) store(stride - Ops::kBytes);
}

}  // namespace p3d::image::lanes
