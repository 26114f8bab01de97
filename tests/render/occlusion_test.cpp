#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "engine/render/occlusion.h"
#include "engine/util/rng.h"

namespace p3d::render {
namespace {

// The word-based mask against a plain vector<bool> model, over random operations.
TEST(ColumnMask, AgreesWithABitPerBoolModel) {
  for (int width : {1, 63, 64, 65, 130, 640}) {
    ColumnMask mask;
    mask.reset(width);
    std::vector<bool> model(width, false);
    Rng rng(width);
    for (int step = 0; step < 2000; ++step) {
      const int x0 = int(rng.below(width)), x1 = x0 + int(rng.below(width - x0));
      bool all = true;
      std::vector<int> open;
      for (int x = x0; x <= x1; ++x) {
        all = all && model[x];
        if (!model[x]) open.push_back(x);
      }
      ASSERT_EQ(mask.all_closed(x0, x1), all) << width << " [" << x0 << "," << x1 << "]";
      std::vector<int> seen;
      mask.for_each_open(x0, x1, [&](int x) { seen.push_back(x); });
      ASSERT_EQ(seen, open);
      const int c = int(rng.below(width));
      mask.close(c);
      model[c] = true;
      ASSERT_TRUE(mask.is_closed(c));
      ASSERT_EQ(mask.full(), std::find(model.begin(), model.end(), false) == model.end());
    }
  }
}

// A strip's mask: every column outside [x0, x1) closed, each counted once, whatever
// was closed before; the strip's own columns untouched.
TEST(ColumnMask, ClosesOutsideAStrip) {
  for (int width : {1, 63, 64, 65, 130, 640}) {
    Rng rng(width + 7);
    for (int step = 0; step < 300; ++step) {
      const int x0 = int(rng.below(width + 1)), x1 = x0 + int(rng.below(width + 1 - x0));  // [x0, x1) may be empty
      ColumnMask mask;
      mask.reset(width);
      std::vector<bool> model(width, false);
      for (int k = int(rng.below(4)); k > 0; --k) {
        const int c = int(rng.below(width));
        mask.close(c);
        model[c] = true;
      }
      mask.close_outside(x0, x1);
      for (int x = 0; x < width; ++x) model[x] = model[x] || x < x0 || x >= x1;
      for (int x = 0; x < width; ++x) ASSERT_EQ(mask.is_closed(x), model[x]) << width << " [" << x0 << "," << x1 << ") " << x;
      ASSERT_EQ(mask.closed_count(), int(std::count(model.begin(), model.end(), true))) << width;
    }
  }
}

TEST(ColumnMask, CountsEachColumnOnce) {
  ColumnMask mask;
  mask.reset(100);
  for (int i = 0; i < 3; ++i)
    for (int x = 0; x < 100; x += 2) mask.close(x);
  EXPECT_EQ(mask.closed_count(), 50);
  EXPECT_FALSE(mask.full());
  for (int x = 1; x < 100; x += 2) mask.close(x);
  EXPECT_TRUE(mask.full());
}

}  // namespace
}  // namespace p3d::render
