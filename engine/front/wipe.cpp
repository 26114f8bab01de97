#include "engine/front/wipe.h"

#include <algorithm>

namespace p3d::front {

Melt::Melt(play::Random& m_random) {
  // Doom fills y[0..319] but melts only the first 160 (its columns go in pairs).
  std::array<int, 2 * kPairs> y{};
  y[0] = -(m_random.other() % 16);
  for (size_t i = 1; i < y.size(); ++i) {
    const int r = m_random.other() % 3 - 1;
    y[i] = std::clamp(y[i - 1] + r, -15, 0);
  }
  std::copy_n(y.begin(), kPairs, y_.begin());
}

bool Melt::tic() {
  bool done = true;
  for (int& y : y_) {
    if (y < 0) {
      ++y;
      done = false;
    } else if (y < kHeight) {
      const int dy = y < 16 ? y + 1 : 8;  // slow at first, then 8 rows a tic
      y = std::min(y + dy, kHeight);
      done = false;
    }
  }
  return done_ = done;
}

void Melt::draw(const image::Image& start, const image::Image& end, image::Image& out) const {
  for (int x = 0; x < out.width; ++x) {
    const int pair = std::min(x * kPairs / out.width, kPairs - 1);
    const int slid = std::max(y_[size_t(pair)], 0) * out.height / kHeight;  // rows of the frame
    for (int row = 0; row < out.height; ++row)
      out.at(x, row) = row < slid ? end.at(x, row) : start.at(x, row - slid);
  }
}

}  // namespace p3d::front
