#include "engine/render/doom_rules.h"

#include <climits>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

namespace p3d::render::doom {

using play::fixed_div;
using play::fixed_mul;
using play::kAngle180;
using play::kAngle90;
using play::kAngleToFineShift;
using play::kFineAngles;
using play::kFineSine;
using play::kFineTangent;

namespace {

constexpr int kFieldOfView = 2048;  // FIELDOFVIEW: 90 degrees in fine angles
// The centre column looks straight ahead, so from a player start on a whole unit, facing
// along an axis, its ray would run exactly along walls and splitters through the eye,
// where the tree's near-side-first order does not hold. Our rays (which wall a column
// shows, never Doom's texture arithmetic) lean right by this much, far below a texel.
constexpr double kRayNudge = 1.0 / (1 << 24);

Fixed fine_cos(Angle a) { return kFineSine[(a >> kAngleToFineShift) + kFineAngles / 4]; }

}  // namespace

// With l = ceil(log2 d) and magic = 2^(bits + l) / d + 1: d * magic exceeds 2^(bits + l)
// by at most d <= 2^l, which no n < 2^bits can carry across a multiple of d.
void magic_for(uint64_t d, int bits, uint64_t& magic, int& shift) {
  int l = 0;
  while ((uint64_t(1) << l) < d) ++l;
  shift = bits + l;
  magic = uint64_t((U128(1) << shift) / d + 1);
}

namespace {

Tables make_tables(int width, int height, int screen_width) {
  Tables t;
  t.width = width;
  t.height = height;
  t.crispy = (screen_width ? screen_width : width) != kDoomWidth;
  t.light_at_view = !t.crispy && width != kDoomWidth;
  t.centerx = width / 2;
  t.centery = height / 2;
  t.centerxfrac = Fixed(t.centerx) << kFracBits;
  t.centeryfrac = Fixed(t.centery) << kFracBits;
  t.projection = t.centerxfrac;
  // R_InitTextureMapping: viewangletox gives the first column at or right of a fine
  // angle's screen position; xtoviewangle the smallest fine angle that maps to a column.
  const Fixed focal = fixed_div(t.centerxfrac, kFineTangent[kFineAngles / 4 + kFieldOfView / 2]);
  std::vector<int> viewangletox(kFineAngles / 2);
  for (int i = 0; i < kFineAngles / 2; ++i) {
    int x;
    if (kFineTangent[i] > kFracUnit * 2) {
      x = -1;
    } else if (kFineTangent[i] < -kFracUnit * 2) {
      x = width + 1;
    } else {
      x = (t.centerxfrac - fixed_mul(kFineTangent[i], focal) + kFracUnit - 1) >> kFracBits;
      x = std::clamp(x, -1, width + 1);
    }
    viewangletox[size_t(i)] = x;
  }
  t.xtoviewangle.resize(size_t(width) + 1);
  t.lateral.resize(size_t(width) + 1);
  for (int x = width, i = 0; x >= 0; --x) {  // the angles grow leftwards
    while (i < kFineAngles / 2 - 1 && viewangletox[size_t(i)] > x) ++i;
    t.xtoviewangle[size_t(x)] = (Angle(i) << kAngleToFineShift) - kAngle90;
    t.lateral[size_t(x)] = -std::tan(to_radians(t.xtoviewangle[size_t(x)])) + kRayNudge;
  }
  // Culling finds a wall's columns by our projection: how far Doom's rays stray from it
  // (under a column at 320 wide, more where fine angles are coarser than columns).
  double slack = 0;
  for (int x = 0; x < width; ++x)
    slack = std::max(slack, std::fabs(width / 2.0 * (1 + t.lateral[size_t(x)]) - (x + 0.5)));
  t.ray_slack = int(std::ceil(slack));
  for (int& x : viewangletox) x = x == -1 ? 0 : x == width + 1 ? width : x;  // the fencepost cases
  t.viewangletox = std::move(viewangletox);
  t.clipangle = t.xtoviewangle[0];
  t.distscale.resize(size_t(width));
  for (int x = 0; x < width; ++x) t.distscale[size_t(x)] = fixed_div(kFracUnit, std::abs(fine_cos(t.xtoviewangle[size_t(x)])));
  t.view_sine.resize(size_t(width));
  for (int x = 0; x < width; ++x)
    t.view_sine[size_t(x)] = play::kFineSine[(play::kAngle90 + t.xtoviewangle[size_t(x)]) >> kAngleToFineShift];
  t.yslope.resize(size_t(height));
  for (int y = 0; y < height; ++y) {
    const Fixed dy = std::abs(((y - height / 2) << kFracBits) + kFracUnit / 2);
    t.yslope[size_t(y)] = fixed_div(Fixed(width / 2) * kFracUnit, dy);
  }
  // A scale at Doom's 320 columns: vanilla's windows light by their own scale.
  const int light_width = t.crispy ? width : kDoomWidth;
  magic_for(uint64_t(light_width) << kLightScaleShift, 32 + 9, t.light_magic, t.light_shift);  // scale * 320 < 2^41
  // DISTMAP; vanilla's smaller views drop faster, as its scales there are smaller.
  for (int j = 0; j < kMaxLightScale; ++j) t.scale_light_drop[j] = t.light_at_view ? j * kDoomWidth / width / 2 : j / 2;
  for (int j = 0; j < kMaxLightZ; ++j) {
    const Fixed scale = fixed_div(kDoomWidth / 2 * kFracUnit, (j + 1) << kLightZShift) >> kLightScaleShift;
    t.zlight_drop[j] = scale / 2;
  }
  t.sky_iscale = Fixed(int64_t(kFracUnit) * kDoomWidth / width);
  return t;
}

}  // namespace

const Tables& tables(int width, int height, int screen_width) {
  static std::mutex mutex;
  static std::map<std::tuple<int, int, bool>, std::unique_ptr<Tables>> made;
  static thread_local const Tables* last = nullptr;
  const bool crispy = (screen_width ? screen_width : width) != kDoomWidth;
  if (last && last->width == width && last->height == height && last->crispy == crispy) return *last;
  const std::lock_guard lock(mutex);
  auto& t = made[{width, height, crispy}];
  if (!t) t = std::make_unique<Tables>(make_tables(width, height, screen_width));
  last = t.get();
  return *t;
}

Angle to_angle(double degrees) {
  const double turns = degrees / 360.0;
  const double frac = turns - std::floor(turns);
  return Angle(uint64_t(std::llround(frac * 4294967296.0)) & 0xFFFFFFFFu);
}

Fixed point_to_dist(Fixed vx, Fixed vy, Fixed x, Fixed y) {
  Fixed dx = std::abs(play::wrap_sub(x, vx)), dy = std::abs(play::wrap_sub(y, vy));
  if (dy > dx) std::swap(dx, dy);
  const Fixed frac = dx != 0 ? fixed_div(dy, dx) : 0;
  constexpr int kDBits = kFracBits - play::kSlopeBits;
  const Angle angle = (play::kTanToAngle[uint32_t(frac) >> kDBits] + kAngle90) >> kAngleToFineShift;
  return fixed_div(dx, kFineSine[angle]);
}

int start_map(int light, int contrast, int extra) {
  const int level = std::clamp((light >> kLightSegShift) + extra + contrast, 0, kLightLevels - 1);
  return (kLightLevels - 1 - level) * 2 * kColormaps / kLightLevels;
}

Seg make_seg(const Tables& t, Fixed vx, Fixed vy, Angle view_angle, Fixed v1x, Fixed v1y, Angle angle) {
  (void)t;
  Seg s;
  s.normal = angle + kAngle90;
  const Angle angle1 = point_to_angle(vx, vy, v1x, v1y);
  Angle offset_angle = Angle(std::abs(int32_t(s.normal - angle1)));  // abs(INT_MIN) stays: more than 90 degrees
  if (offset_angle > kAngle90) offset_angle = kAngle90;
  const Fixed hyp = point_to_dist(vx, vy, v1x, v1y);
  s.distance = fixed_mul(hyp, kFineSine[(kAngle90 - offset_angle) >> kAngleToFineShift]);
  offset_angle = s.normal - angle1;
  if (offset_angle > kAngle180) offset_angle = 0u - offset_angle;
  if (offset_angle > kAngle90) offset_angle = kAngle90;
  s.offset = fixed_mul(hyp, kFineSine[offset_angle >> kAngleToFineShift]);
  if (s.normal - angle1 < kAngle180) s.offset = -s.offset;
  s.center = kAngle90 + view_angle - s.normal;
  return s;
}

Seg make_crispy_seg(Fixed vx, Fixed vy, Angle view_angle, Fixed v1x, Fixed v1y, Fixed v2x, Fixed v2y, Angle angle) {
  Seg s;
  const int64_t full_dx = int64_t(v2x) - v1x, full_dy = int64_t(v2y) - v1y;
  Angle line = play::vector_angle(Fixed(full_dx), Fixed(full_dy));
  const Angle off = line - angle;
  if ((off < kAngle180 ? off : 0u - off) > play::kAngle45 * 2 / 3) line = angle;  // ANG60 / 2
  s.normal = line + kAngle90;
  // Halved, so that the products stay within 64 bits; the length is halved too.
  const int64_t dx = full_dx >> 1, dy = full_dy >> 1;
  const int64_t dx1 = (int64_t(vx) - v1x) >> 1, dy1 = (int64_t(vy) - v1y) >> 1;
  const double length = std::sqrt(double(full_dx) * double(full_dx) + double(full_dy) * double(full_dy)) / 2;
  const int64_t len = std::max<int64_t>(1, int64_t(uint32_t(length)));  // a zero-length seg: Crispy divides by 0
  const int64_t distance = ((dy * dx1 - dx * dy1) / len) * 2;
  s.distance = Fixed(std::clamp<int64_t>(distance, INT32_MIN, INT32_MAX));
  s.offset = Fixed(uint32_t(uint64_t(((dx * dx1 + dy * dy1) / len) * 2)));
  s.center = kAngle90 + view_angle - s.normal;
  return s;
}

Fixed crispy_seg_offset(Fixed v1x, Fixed v1y, Fixed ax, Fixed ay) {
  const double dx = double(play::wrap_sub(v1x, ax) >> kFracBits), dy = double(play::wrap_sub(v1y, ay) >> kFracBits);
  return Fixed(uint32_t(int32_t(std::sqrt(dx * dx + dy * dy))) << kFracBits);
}

void crispy_onto_line(Fixed& x, Fixed& y, Fixed ax, Fixed ay, Fixed dx, Fixed dy) {
  if (!dx || !dy) return;  // only diagonal lines
  const int64_t dx2 = int64_t(dx >> kFracBits) * (dx >> kFracBits), dy2 = int64_t(dy >> kFracBits) * (dy >> kFracBits);
  const int64_t dxy = int64_t(dx >> kFracBits) * (dy >> kFracBits), s = dx2 + dy2;
  if (s == 0) return;
  const int64_t rx = (dx2 * x + dy2 * ax + dxy * (int64_t(y) - ay)) / s;
  const int64_t ry = (dy2 * y + dx2 * ay + dxy * (int64_t(x) - ax)) / s;
  if (std::abs(rx - x) > 8 * kFracUnit || std::abs(ry - y) > 8 * kFracUnit) return;  // not a split: a gap
  x = Fixed(rx), y = Fixed(ry);
}

WallPrecision wall_precision(const Tables& t, int64_t height) {
  if (!t.crispy) return {};
  // Taller sectors step their edges in fewer bits, so that scale * height stays in range.
  static constexpr WallPrecision kSteps[8] = {{2048 * kFracUnit, 12}, {1024 * kFracUnit, 12}, {1024 * kFracUnit, 11},
                                              {512 * kFracUnit, 11},  {512 * kFracUnit, 10},  {256 * kFracUnit, 10},
                                              {256 * kFracUnit, 9},   {128 * kFracUnit, 9}};
  int64_t h = std::max<int64_t>(height, 1) >> 7;
  int step = 0;
  while (h >>= 1) ++step;
  return kSteps[std::min(step, 7)];
}

Angle seg_angle(double dx, double dy) {
  const double bams = std::atan2(dy, dx) * (32768.0 / 3.14159265358979323846);
  return Angle(uint32_t(uint16_t(int32_t(std::lround(bams)))) << 16);
}

void seg_columns(const Tables& t, Fixed vx, Fixed vy, Angle view_angle, Fixed v1x, Fixed v1y, Fixed v2x, Fixed v2y,
                 int& x1, int& x2) {
  x1 = x2 = 0;
  Angle angle1 = point_to_angle(vx, vy, v1x, v1y), angle2 = point_to_angle(vx, vy, v2x, v2y);
  const Angle span = angle1 - angle2;
  if (span >= kAngle180) return;  // the back side
  angle1 -= view_angle;
  angle2 -= view_angle;
  const Angle clip = t.clipangle;
  Angle tspan = angle1 + clip;
  if (tspan > 2 * clip) {
    tspan -= 2 * clip;
    if (tspan >= span) return;  // off the left
    angle1 = clip;
  }
  tspan = clip - angle2;
  if (tspan > 2 * clip) {
    tspan -= 2 * clip;
    if (tspan >= span) return;  // off the right
    angle2 = 0u - clip;
  }
  x1 = t.viewangletox[(angle1 + kAngle90) >> kAngleToFineShift];
  x2 = t.viewangletox[(angle2 + kAngle90) >> kAngleToFineShift];
}

int point_on_seg_side(Fixed x, Fixed y, Fixed v1x, Fixed v1y, Fixed v2x, Fixed v2y) {
  const Fixed ldx = play::wrap_sub(v2x, v1x), ldy = play::wrap_sub(v2y, v1y);
  if (!ldx) return x <= v1x ? ldy > 0 : ldy < 0;
  if (!ldy) return y <= v1y ? ldx < 0 : ldx > 0;
  const Fixed dx = play::wrap_sub(x, v1x), dy = play::wrap_sub(y, v1y);
  if ((ldy ^ ldx ^ dx ^ dy) & int32_t(0x80000000)) return ((ldy ^ dx) & int32_t(0x80000000)) ? 1 : 0;
  const Fixed left = fixed_mul(ldy >> kFracBits, dx), right = fixed_mul(dy, ldx >> kFracBits);
  return right < left ? 0 : 1;
}

}  // namespace p3d::render::doom
