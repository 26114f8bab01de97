#include "engine/play/weapon_view.h"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "engine/play/fixed.h"
#include "engine/play/screen.h"
#include "engine/play/status_bar.h"
#include "engine/play/world.h"

namespace p3d::play {

namespace {

constexpr int kPaletteColours = 256;
constexpr int kDoomColormaps = 34;   // COLORMAP: 32 light levels, the inverse map, black
constexpr int kLevelLightMaps = 32;  // what a paletted level keeps of them
constexpr int kFuzzMap = 6;          // the shadow darkens what is behind it through this map

// Doom's psprite geometry (r_things.c, r_main.c).
constexpr int kBaseYCentre = 100;      // BASEYCENTER: the weapon hangs from row 100 of the screen
constexpr int kDoomBarViewRows = 168;  // Doom's view above its status bar
constexpr int kLightLevels = 16, kLightSegShift = 4, kColormapsLit = 32, kMaxLightScale = 48, kDistMap = 2;

// Doom's fuzz: the row above or below, in this order down the screen.
constexpr int kFuzzTable = 50;
constexpr int8_t kFuzzOffset[kFuzzTable] = {
    1, -1, 1, -1, 1,  1,  -1, 1, 1,  -1, 1,  1, 1, -1, 1, 1, 1,  -1, -1, -1, -1, 1, -1, -1, 1,
    1, 1,  1, -1, 1,  -1, 1,  1, -1, -1, 1,  1, -1, -1, -1, -1, 1, 1,  1,  1,  -1, 1, 1,  -1, 1};

// Where Doom's screen lies in the view: sprites scale by `scale` (16.16) about the
// centre column and row (Doom's centerx, centery; its pspritescale and pspriteiscale).
struct Place {
  Fixed scale = kFracUnit, inverse_scale = kFracUnit;
  int centre_x = kScreenWidth / 2, centre_y = kDoomBarViewRows / 2;
};

Place place_in(int width, int height, int status_bar_rows) {
  Place p;
  int k = 0, doom_rows = kScreenHeight;
  if (status_bar_rows > 0) {
    k = std::max(1, status_bar_rows / kStatusBarHeight);
    doom_rows = kDoomBarViewRows;
  } else if (width >= kScreenWidth && height >= kScreenHeight) {
    k = ScreenPlace::scale_for(width, height);
  }
  if (k == 0) {  // smaller than Doom's screen: Doom's own arithmetic for a view this wide
    p.scale = Fixed(int64_t(kFracUnit) * width / kScreenWidth);
    p.inverse_scale = Fixed(int64_t(kFracUnit) * kScreenWidth / std::max(width, 1));
    p.centre_x = width / 2;
    p.centre_y = height / 2;
    return p;
  }
  p.scale = k * kFracUnit;
  p.inverse_scale = kFracUnit / k;
  p.centre_x = (width - kScreenWidth * k) / 2 + kScreenWidth / 2 * k;
  p.centre_y = height - doom_rows / 2 * k;  // Doom's view's bottom on the frame's (or the bar's top)
  return p;
}

// One of COLORMAP's maps, as colours and (when known) palette indices.
struct Shade {
  std::array<uint32_t, kPaletteColours> colour{};
  std::array<uint8_t, kPaletteColours> index{};
  bool has_indices = false, ok = false;
};

const std::vector<uint32_t>& palette_of(const level::Level& level, const WeaponArt& art) {
  return level.paletted() ? level.palette : art.palette();
}

// The level's light maps where it has the map; the WADs' COLORMAP beyond them (the
// inverse map); full bright when neither has it.
Shade shade(int map, const level::Level& level, const WeaponArt& art) {
  Shade s;
  const size_t at = size_t(map) * kPaletteColours;
  if (level.paletted() && map < kLevelLightMaps && level.light_maps.size() >= at + kPaletteColours) {
    std::copy_n(level.light_maps.begin() + ptrdiff_t(at), kPaletteColours, s.colour.begin());
    s.has_indices = level.light_indices.size() >= at + kPaletteColours;
    if (s.has_indices) std::copy_n(level.light_indices.begin() + ptrdiff_t(at), kPaletteColours, s.index.begin());
    s.ok = true;
    return s;
  }
  const std::vector<uint32_t>& palette = palette_of(level, art);
  if (art.colormap().size() >= at + kPaletteColours && palette.size() >= size_t(kPaletteColours)) {
    for (int i = 0; i < kPaletteColours; ++i) {
      s.index[size_t(i)] = art.colormap()[at + size_t(i)];
      s.colour[size_t(i)] = palette[s.index[size_t(i)]];
    }
    s.has_indices = s.ok = true;
    return s;
  }
  return map != 0 ? shade(0, level, art) : s;
}

// Doom's R_DrawPlayerSprites light: the sector's level plus the gun's flash, at the
// nearest scale (MAXLIGHTSCALE-1) of a full-width view.
int sector_light_map(int sector_light, int extra_light) {
  const int light = std::clamp((sector_light >> kLightSegShift) + extra_light, 0, kLightLevels - 1);
  const int start = ((kLightLevels - 1 - light) * 2) * kColormapsLit / kLightLevels;
  const int level = start - (kMaxLightScale - 1) * kScreenWidth / kScreenWidth / kDistMap;
  return std::clamp(level, 0, kColormapsLit - 1);
}

bool is_shadow(const Player& player) {
  const int invisible = player.inv.powers[size_t(Power::kInvisibility)];
  return invisible > 4 * 32 || (invisible & 8);  // blinking as it runs out
}

// The pixels a sprite covers, column by column: the view's column, the picture's, and
// the rows the picture's opaque runs cover there (as R_DrawMaskedColumn clips them).
class SpriteColumns {
 public:
  SpriteColumns(const Psprite& psp, const WeaponArt::Picture& pic, const Place& place, int width, int height)
      : pic_(pic.picture), place_(place), height_(height) {
    const wad::IndexedImage& p = pic.picture;
    Fixed tx = psp.sx - kScreenWidth / 2 * kFracUnit - p.left_offset * kFracUnit;
    const Fixed centre_x = place.centre_x * kFracUnit;
    x1_ = (centre_x + fixed_mul(tx, place.scale)) >> kFracBits;
    tx += p.width * kFracUnit;
    x2_ = ((centre_x + fixed_mul(tx, place.scale)) >> kFracBits) - 1;
    visible_ = x1_ <= width && x2_ >= 0;
    texture_mid_ = kBaseYCentre * kFracUnit + kFracUnit / 2 - (psp.sy - p.top_offset * kFracUnit);
    first_ = std::max(x1_, 0);
    last_ = std::min(x2_, width - 1);
    step_ = pic.flipped ? -place.inverse_scale : place.inverse_scale;
    start_ = pic.flipped ? p.width * kFracUnit - 1 : 0;
    if (first_ > x1_) start_ += step_ * (first_ - x1_);
    top_screen_ = place.centre_y * kFracUnit - fixed_mul(texture_mid_, place.scale);
  }

  // f(x, y, palette index) for each pixel, top to bottom within each column.
  template <typename F>
  void each_pixel(F&& f) const {
    if (!visible_) return;
    Fixed frac = start_;
    for (int x = first_; x <= last_; ++x, frac += step_) {
      const int column = frac >> kFracBits;
      if (column < 0 || column >= pic_.width) continue;
      for (int top = 0; top < pic_.height;) {  // each run of opaque texels: a post
        if (!pic_.opaque[pic_.at(column, top)]) {
          ++top;
          continue;
        }
        int end = top;
        while (end < pic_.height && pic_.opaque[pic_.at(column, end)]) ++end;
        draw_run(column, top, end, x, f);
        top = end;
      }
    }
  }

 private:
  template <typename F>
  void draw_run(int column, int top, int end, int x, F& f) const {
    // Doom's int arithmetic, in 64 bits: huge pictures at huge scales would overflow it.
    const int64_t top_screen = top_screen_ + int64_t(place_.scale) * top;
    const int64_t bottom_screen = top_screen_ + int64_t(place_.scale) * end;
    const int y1 = int(std::max<int64_t>((top_screen + kFracUnit - 1) >> kFracBits, 0));
    const int y2 = int(std::min<int64_t>((bottom_screen - 1) >> kFracBits, height_ - 1));
    for (int y = y1; y <= y2; ++y) {
      // Doom's R_DrawColumn steps from the centre row by the inverse scale.
      const int64_t frac = texture_mid_ + int64_t(y - place_.centre_y) * place_.inverse_scale;
      const int row = int(std::clamp<int64_t>(frac >> kFracBits, top, end - 1));
      f(x, y, pic_.indices[pic_.at(column, row)]);
    }
  }

  const wad::IndexedImage& pic_;
  const Place& place_;
  int height_;
  int x1_ = 0, x2_ = 0, first_ = 0, last_ = -1;
  bool visible_ = false;
  Fixed texture_mid_ = 0, top_screen_ = 0, start_ = 0, step_ = 0;
};

// Writes one palette index (or colour) into the view, indexed or not.
class Painter {
 public:
  Painter(image::Frame& view, const std::vector<uint32_t>& palette) : view_(view), palette_(palette) {}
  bool indexed() const { return view_.indexed(); }
  void put(int x, int y, const Shade& shade, uint8_t texel) {
    const size_t at = size_t(y) * size_t(view_.width) + size_t(x);
    if (view_.indexed()) {
      const uint8_t index = shade.index[texel];
      view_.indices[at] = index;
      view_.pixels[at] = view_.palette.size() > index ? view_.palette[index] : shade.colour[texel];
    } else {
      view_.pixels[at] = shade.colour[texel];
    }
  }
  // Doom's fuzz: the pixel a row above or below, through the fuzz map.
  void fuzz(int x, int y, int from_y, const Shade& fuzz) {
    const size_t at = size_t(y) * size_t(view_.width) + size_t(x);
    const size_t from = size_t(from_y) * size_t(view_.width) + size_t(x);
    if (view_.indexed()) {
      put(x, y, fuzz, view_.indices[from]);
      return;
    }
    if (const auto it = index_of().find(view_.pixels[from]); it != index_of().end()) {
      view_.pixels[at] = fuzz.colour[it->second];
      return;
    }
    // Not a palette colour (a level shaded by multiplying): darkened as the map darkens.
    const uint32_t c = view_.pixels[from];
    constexpr uint32_t kKeep = kColormapsLit - kFuzzMap;
    view_.pixels[at] = image::rgba(image::red(c) * kKeep / kColormapsLit, image::green(c) * kKeep / kColormapsLit,
                                   image::blue(c) * kKeep / kColormapsLit, c >> 24);
  }

 private:
  const std::unordered_map<uint32_t, uint8_t>& index_of() {
    if (index_of_.empty())
      for (size_t i = palette_.size(); i-- > 0;) index_of_[palette_[i]] = uint8_t(i);  // the first index wins
    return index_of_;
  }

  image::Frame& view_;
  const std::vector<uint32_t>& palette_;
  std::unordered_map<uint32_t, uint8_t> index_of_;
};

}  // namespace

WeaponArt::WeaponArt(const wad::Stack& wads) : wads_(wads) {
  if (const wad::Lump* colormap = wads_.find("COLORMAP")) {
    const size_t n = std::min(colormap->bytes.size(), size_t(kDoomColormaps) * kPaletteColours);
    colormap_.assign(colormap->bytes.begin(), colormap->bytes.begin() + ptrdiff_t(n - n % kPaletteColours));
  }
  if (const wad::Lump* playpal = wads_.find("PLAYPAL"); playpal && playpal->bytes.size() >= 3 * kPaletteColours) {
    const uint8_t* rgb = playpal->bytes.data();
    for (int i = 0; i < kPaletteColours; ++i, rgb += 3) palette_.push_back(image::rgba(rgb[0], rgb[1], rgb[2]));
  }
}

const WeaponArt::Picture* WeaponArt::frame(Sprite sprite, int frame) {
  const int key = int(sprite) * 64 + frame;
  auto it = frames_.find(key);
  if (it == frames_.end()) it = frames_.emplace(key, find_frame(sprite, frame)).first;
  return it->second ? &*it->second : nullptr;
}

std::optional<WeaponArt::Picture> WeaponArt::find_frame(Sprite sprite, int frame) {
  if (size_t(sprite) >= size_t(Sprite::kCount) || frame < 0 || frame >= 29) return std::nullopt;
  const std::string prefix = kSpriteNames[size_t(sprite)];
  const char letter = char('A' + frame);
  auto decode = [&](const std::string& name, bool flipped) -> std::optional<Picture> {
    const wad::Lump* lump = wads_.find(name);
    if (!lump) return std::nullopt;
    try {
      return Picture{wad::decode_picture(lump->bytes, name), flipped};
    } catch (const std::exception&) {
      return std::nullopt;  // a broken frame is not drawn
    }
  };
  if (auto found = decode(prefix + letter + '0', false)) return found;  // the usual lump of its own
  // Else as Doom's sprite table has it: rotation 0, or failing that rotation 1, in either
  // half of a sprite lump's name (the second half mirrored).
  if (!listed_) {
    for (const wad::Lump* lump : wads_.namespace_lumps({"S", "SS"})) sprite_lumps_.push_back(lump->name);
    listed_ = true;
  }
  for (const char rotation : {'0', '1'})
    for (const std::string& name : sprite_lumps_) {
      if (name.size() < 6 || name.compare(0, 4, prefix) != 0) continue;
      if (name[4] == letter && name[5] == rotation) return decode(name, false);
      if (name.size() >= 8 && name[6] == letter && name[7] == rotation) return decode(name, true);
    }
  return std::nullopt;
}

void draw_weapon(const Player& player, WeaponArt& art, const level::Level& level, image::Frame& view,
                 int status_bar_rows) {
  if (view.width <= 0 || view.height <= 0) return;
  const Place place = place_in(view.width, view.height, status_bar_rows);
  const bool shadow = is_shadow(player);
  const Sector* sector = player.mo && player.mo->subsector ? player.mo->subsector->sector : nullptr;
  const int lit_map = sector_light_map(sector ? sector->light : 255, player.extra_light);
  Painter painter(view, palette_of(level, art));
  const Shade fuzz = shadow ? shade(kFuzzMap, level, art) : Shade{};
  for (const Psprite& psp : player.psprites) {  // the weapon, then its flash over it
    if (psp.state == StateId::kNull) continue;
    const StateInfo& state = state_info(psp.state);
    const WeaponArt::Picture* pic = art.frame(state.sprite, state.frame);
    if (!pic) continue;
    const SpriteColumns columns(psp, *pic, place, view.width, view.height);
    if (shadow) {
      if (!fuzz.ok || (painter.indexed() && !fuzz.has_indices)) continue;
      columns.each_pixel([&](int x, int y, uint8_t) {
        if (y < 1 || y > view.height - 2) return;  // Doom's fuzz keeps off the view's edge rows
        // Doom's fuzz position runs on from sprite to sprite; here it goes by the pixel,
        // so that the same frame fuzzes the same.
        const int at = int((int64_t(x) * view.height + y) % kFuzzTable);
        painter.fuzz(x, y, y + kFuzzOffset[at], fuzz);
      });
      continue;
    }
    const int map = player.fixed_colormap ? player.fixed_colormap : state.bright ? 0 : lit_map;
    const Shade lit = shade(map, level, art);
    if (!lit.ok || (painter.indexed() && !lit.has_indices)) continue;
    columns.each_pixel([&](int x, int y, uint8_t texel) { painter.put(x, y, lit, texel); });
  }
}

}  // namespace p3d::play
