// The map compiler's core: source walls -> BSP auto-partition -> level::Level.
// Splitters are lines of input walls (auto-partitions, de Berg ch. 12), or, where every
// wall's line would peel a few walls off a big cell, a free line through two of its
// vertices that halves it; a cell whose walls bound a convex region of one sector is a
// leaf (Doom's subsector).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "engine/level/level.h"
#include "engine/map/source.h"

namespace p3d::bsp {

enum class Strategy {
  kFirst,      // 2DBSP: the first fragment of each cell, in input order
  kRandom,     // 2DRANDOMBSP: the first fragment after a random permutation
  kFreeSplit,  // random, but take a free split (a fragment spanning its cell) whenever one exists
  kGreedy,     // score k sampled candidates by splits, balance and slivers; take the best
  // (first, random and freesplit take the first fragment that divides its cell)
};

std::optional<Strategy> parse_strategy(const std::string& name);
const char* strategy_name(Strategy s);

struct Options {
  Strategy strategy = Strategy::kGreedy;
  uint64_t seed = 1;
  // The defaults: on the 68 Freedoom maps, beside ZDBSP's trees, these gave 0.91 of its
  // segs, 1.04 times its subsectors as leaves and 0.998 of its mean leaf depth (geomeans;
  // every map's depth within 1.04), with fewer fragments and shallower trees than the
  // previous defaults on generated rooms, soups and grids too (docs/benchmarks.md).
  int greedy_candidates = 32;    // k: candidate splitters sampled per cell
  int greedy_sample = 128;       // fragments scored per candidate (all of them in smaller cells)
  double split_weight = 12;      // cost of one split
  double balance_weight = 2.25;  // cost of one barrier (a wall between two sectors) of imbalance between the sides
  double plain_weight = 2.0 / 9; // a wall that is no barrier, in barriers, for the balance
  double line_weight = 2;        // gain per fragment on the splitter's line (the node takes it from the cell)
  double peel_weight = 4;        // cost of a splitter leaving no fragment on one side
  double sliver_weight = 64;     // cost of a split leaving a piece shorter than kSliverLength
  // Free splitters (lines through two vertices, or through the median vertex, that hold
  // no wall), greedy only: tried in a cell of at least free_min_fragments fragments when
  // the best wall's line leaves fewer than free_lopsided of the sample on one side (or
  // none divides it); taken when one leaves at least free_balance of it on either side.
  int free_min_fragments = 64;
  double free_lopsided = 1.0 / 16;
  double free_balance = 1.0 / 4;
  int free_candidates = 16;      // lines through two sampled vertices scored per cell
  std::function<void(double fraction_done)> progress;  // called now and then during the build
  bool player_must_be_inside = true;  // a hand-written map's start must lie in a sector (imports only warn)
};

constexpr double kSliverLength = 1.0 / 16;  // map units

struct Stats {
  size_t walls = 0, fragments = 0, splits = 0, nodes = 0, leaves = 0;
  size_t segs = 0;               // Doom's count: a two-sided fragment is two segs (one per side)
  size_t empty_leaves = 0;       // leaves holding no fragment (their cell's walls all lie on its edges)
  size_t free_splits = 0;        // nodes whose splitter cut nothing and spanned its cell
  size_t free_lines = 0;         // nodes splitting along a line that holds no wall (Level::free_lines)
  size_t max_depth = 0;
  double mean_depth = 0;         // over leaves
  double shortest_fragment = 0;  // map units
  size_t ray_cast_leaves = 0;    // leaves facing no sector (none, or plain segments only): found by a ray cast
  size_t warnings = 0;           // a WAD map's quirks warned about, each counted (listed or not)

  // de Berg's bound on the expected size of 2DRANDOMBSP: n + 2 n ln n.
  double random_bound() const;
};

// Throws Error (located at the player statement) if the player starts outside every
// sector and options.player_must_be_inside.
level::Level build(const map::Source& source, const Options& options, Stats* stats = nullptr);
// The same, freeing the source's walls, vertices and grid as soon as the level holds them
// (what is left of it is of no further use): a million-wall map's peak memory. Pictures
// already in columns (a WAD's art) move into the level.
level::Level build(map::Source&& source, const Options& options, Stats* stats = nullptr);

}  // namespace p3d::bsp
