#include "engine/front/back_screen.h"

#include "engine/play/screen.h"

namespace p3d::front {

namespace {
constexpr int kFlatSide = 64;
constexpr const char* kBorderNames[8] = {"BRDR_TL", "BRDR_T", "BRDR_TR", "BRDR_L", "BRDR_R", "BRDR_BL", "BRDR_B", "BRDR_BR"};
}  // namespace

ViewWindow view_window(int width, int area_height, int screen_blocks, int scale) {
  if (screen_blocks >= 10) return {0, 0, width, area_height};
  scale = std::max(scale, 1);
  const int w = width * screen_blocks / 10;
  const int h = ((area_height / scale * screen_blocks / 10) & ~7) * scale;
  return {(width - w) / 2, (area_height - h) / 2, w, h};
}

std::optional<BackScreen> BackScreen::load(const wad::Stack& wads, bool commercial) {
  const wad::Lump* flat = wads.find(commercial ? "GRNROCK" : "FLOOR7_2");
  if (!flat || flat->bytes.size() < size_t(kFlatSide * kFlatSide)) return std::nullopt;
  BackScreen b;
  b.flat_.assign(flat->bytes.begin(), flat->bytes.begin() + kFlatSide * kFlatSide);
  for (size_t i = 0; i < 8; ++i) b.border_[i] = wad::find_picture(wads, kBorderNames[i]);  // broken: left out
  return b;
}

void BackScreen::draw(image::Image& frame, int area_height, const ViewWindow& v, int scale,
                      const std::vector<uint32_t>& palette) const {
  scale = std::max(scale, 1);
  for (int y = 0; y < std::min(area_height, frame.height); ++y)
    for (int x = 0; x < frame.width; ++x)
      frame.at(x, y) = palette[flat_[size_t((y / scale) % kFlatSide * kFlatSide + (x / scale) % kFlatSide)]];
  // Each picture at a pixel of the frame, its texels scale x scale.
  auto put = [&](size_t piece, int px, int py) {
    if (border_[piece]) play::draw_picture(frame, *border_[piece], 0, 0, {scale, px, py}, palette);
  };
  const int step = 8 * scale;
  for (int x = 0; x < v.width; x += step) {
    put(1, v.x + x, v.y - step);
    put(6, v.x + x, v.y + v.height);
  }
  for (int y = 0; y < v.height; y += step) {
    put(3, v.x - step, v.y + y);
    put(4, v.x + v.width, v.y + y);
  }
  put(0, v.x - step, v.y - step);
  put(2, v.x + v.width, v.y - step);
  put(5, v.x - step, v.y + v.height);
  put(7, v.x + v.width, v.y + v.height);
}

}  // namespace p3d::front
