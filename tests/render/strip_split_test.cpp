// The strips' edges: well formed for any width and count, and moved by the strips'
// times toward equal shares of the work.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "engine/render/strip_split.h"
#include "engine/util/rng.h"

namespace p3d::render {
namespace {

constexpr int kAlign = 16;

// From 0 to the width, every inner edge aligned and every strip at least kAlign wide.
void expect_well_formed(const std::vector<int>& edges, int width, const std::string& what) {
  ASSERT_GE(edges.size(), 2u) << what;
  EXPECT_EQ(edges.front(), 0) << what;
  EXPECT_EQ(edges.back(), width) << what;
  for (size_t k = 1; k < edges.size(); ++k) {
    EXPECT_GE(edges[k] - edges[k - 1], std::min(width, kAlign)) << what << " strip " << k - 1;
    if (k + 1 < edges.size()) {
      EXPECT_EQ(edges[k] % kAlign, 0) << what << " edge " << k;
    }
  }
}

TEST(StripSplit, EvenEdgesFitAnyWidthAndCount) {
  for (int width : {1, 15, 16, 40, 100, 160, 320, 640, 1919, 3840})
    for (int count : {1, 2, 3, 8, 64}) {
      const std::vector<int> edges = even_edges(width, count, kAlign);
      const std::string what = std::to_string(width) + " columns, " + std::to_string(count) + " strips";
      expect_well_formed(edges, width, what);
      EXPECT_EQ(int(edges.size()) - 1, std::max(1, std::min(count, width / kAlign))) << what;
      const int widest = width / (int(edges.size()) - 1) + kAlign;
      for (size_t k = 1; k < edges.size(); ++k) EXPECT_LE(edges[k] - edges[k - 1], widest) << what;
    }
}

// Columns whose costs differ (a busy left, a cheap right, random steps): strips timed
// by those costs, frame after frame, end up sharing the total within a column or two.
TEST(StripSplit, BalancedEdgesShareTheTimeEvenly) {
  Rng rng(11);
  for (int round = 0; round < 30; ++round) {
    const int width = 64 + int(rng.below(1900)), count = 2 + int(rng.below(4));
    std::vector<double> cost(static_cast<size_t>(width));
    double level = 1;
    for (double& c : cost) {
      if (rng.below(40) == 0) level = 0.2 + double(rng.below(100)) / 10;
      c = level;
    }
    std::vector<int> edges = even_edges(width, count, kAlign);
    const size_t strips = edges.size() - 1;
    std::vector<double> seconds(strips);
    auto time_strips = [&] {
      for (size_t i = 0; i < strips; ++i) {
        seconds[i] = 0;
        for (int x = edges[i]; x < edges[i + 1]; ++x) seconds[i] += cost[size_t(x)];
      }
    };
    for (int frame = 0; frame < 40; ++frame) {
      time_strips();
      balance_edges(edges, seconds, kAlign);
      expect_well_formed(edges, width, "round " + std::to_string(round));
    }
    time_strips();
    double total = 0, most = 0, densest = 0;
    for (size_t i = 0; i < strips; ++i) total += seconds[i], most = std::max(most, seconds[i]);
    for (const double c : cost) densest = std::max(densest, c);
    // Edges fall on multiples of kAlign: a strip may be off by half that many columns each side.
    EXPECT_LE(most, total / double(strips) + kAlign * densest) << "round " << round << ": " << width << " columns";
  }
}

// Times that say nothing (none yet, zero, not a number) leave the edges where they were.
TEST(StripSplit, MeaninglessTimesLeaveTheEdges) {
  const std::vector<int> even = even_edges(640, 4, kAlign);
  for (const std::vector<double>& seconds :
       {std::vector<double>{0, 0, 0, 0}, {std::nan(""), 1, 1, 1}, {std::numeric_limits<double>::infinity(), 1, 1, 1}}) {
    std::vector<int> edges = even;
    balance_edges(edges, seconds, kAlign);
    EXPECT_EQ(edges, even);
  }
  std::vector<int> edges = even;
  balance_edges(edges, std::vector<double>{1, 1, 1}, kAlign);  // not this split's
  EXPECT_EQ(edges, even);
}

}  // namespace
}  // namespace p3d::render
