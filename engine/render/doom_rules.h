// Doom's drawing arithmetic (Chocolate Doom's r_main.c, r_segs.c, r_plane.c,
// r_things.c learnt rule by rule; our code): the tables a view size makes
// (R_InitTextureMapping's viewangletox and xtoviewangle, R_ExecuteSetViewSize's
// distscale, yslope and scale light levels) and the per-wall numbers of
// R_StoreWallRange, in Doom's own 16.16 fixed point and binary angles, so that a WAD
// level's pixels are Doom's: which texel of a wall column and row, which texel of a
// flat, which light map, where a wall's columns begin and end, where a sprite lands.
//
// The rules scale as Doom's did with its view size: column x of a W-wide view looks
// along xtoviewangle[x] (the smallest fine angle whose screen position rounds up to x),
// the focal length is W/2, light diminishes with the same distances. At Doom's own 320
// columns they are Chocolate Doom's (vanilla's, to its bugs); at any other width Crispy
// Doom's hires ones (its 640x400), which mend what goes wrong as pixels get smaller:
// flats by each pixel's distance from the centre column, textures of any height wrap
// (no tutti-frutti), walls measured from their exact line (no wobble), wall edges in
// as many bits as the sector's height allows (no wiggle). Only for a 90-degree field
// of view (Doom's FIELDOFVIEW); View keeps our own projection for any other.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/play/angle.h"
#include "engine/play/fixed.h"

namespace p3d::render::doom {

using play::Angle;
using play::Fixed;
using play::kFracBits;
using play::kFracUnit;

constexpr int kLightLevels = 16;      // LIGHTLEVELS
constexpr int kLightSegShift = 4;     // LIGHTSEGSHIFT: a sector's 0..255 light >> 4
constexpr int kMaxLightScale = 48;    // MAXLIGHTSCALE
constexpr int kLightScaleShift = 12;  // LIGHTSCALESHIFT
constexpr int kMaxLightZ = 128;       // MAXLIGHTZ
constexpr int kLightZShift = 20;      // LIGHTZSHIFT
constexpr int kColormaps = 32;        // NUMCOLORMAPS
constexpr int kHeightBits = 12;       // HEIGHTBITS: wall edges step in 20.12
constexpr Fixed kMinZ = kFracUnit * 4;  // MINZ: nearer things are not drawn
constexpr int kDoomWidth = 320;         // SCREENWIDTH, which Doom's light tables are made for

// What a view size decides (R_ExecuteSetViewSize, R_InitTextureMapping), made once per size.
struct Tables {
  int width = 0, height = 0;
  bool crispy = false;              // Crispy Doom's hires rules (any width but Doom's 320), else vanilla's
  bool light_at_view = false;       // vanilla's view in a window of its 320 columns: light by the view's own scale
  int centerx = 0, centery = 0;
  Fixed centerxfrac = 0, centeryfrac = 0, projection = 0;
  std::vector<int> viewangletox;    // per fine angle of the half turn ahead: the first column at or right of it
  Angle clipangle = 0;              // xtoviewangle[0]: the view's left edge
  std::vector<Angle> xtoviewangle;  // width + 1 columns: the angle column x looks along, left of the view positive
  std::vector<double> lateral;      // per column: where its ray crosses the screen plane at depth W/2, right positive
  int ray_slack = 0;                // the most whole columns a ray lies from our column centre x + 1/2
  std::vector<Fixed> distscale;     // per column: 1 / cos(xtoviewangle)
  // Per column: R_ScaleFromGlobalAngle's sine of the view, finesine[(ANG90 +
  // xtoviewangle) >> 19] (its angle less the view's is the column's own angle).
  std::vector<Fixed> view_sine;
  std::vector<Fixed> yslope;        // per row: (W/2) / |y - centery + 1/2|
  int scale_light_drop[kMaxLightScale] = {};  // scalelight: maps brighter at wall scale index j (at 320 columns)
  // wall_map's index, scale * 320 / light_width >> LIGHTSCALESHIFT, by a multiply
  // (exact_quotient): that division took a tenth of a wall column's set-up.
  uint64_t light_magic = 0;
  int light_shift = 0;
  int zlight_drop[kMaxLightZ] = {};           // zlight: maps brighter at flat distance index j
  Fixed sky_iscale = 0;                       // the sky's texel rows per screen row (pspriteiscale)
};

// The tables of a W x H view (cached: each size is made once per process). A view that
// is a window of Doom's 320x200 screen (screen_width 320: its smaller screen sizes)
// keeps vanilla's rules at any width; otherwise 320 columns are vanilla's, any other
// width Crispy's.
const Tables& tables(int width, int height, int screen_width = 0);

// A double of map units (a multiple of 1/65536, as every position our levels and
// simulation hold) in 16.16; an angle in degrees as a binary angle.
inline Fixed to_fixed(double v) { return Fixed(int64_t(v * kFracUnit + (v < 0 ? -0.5 : 0.5))); }
Angle to_angle(double degrees);
inline double to_radians(Angle a) { return int32_t(a) * (3.14159265358979323846 / 2147483648.0); }

// R_PointToAngle from (vx, vy), and R_PointToDist.
inline Angle point_to_angle(Fixed vx, Fixed vy, Fixed x, Fixed y) { return play::point_to_angle(vx, vy, x, y); }
Fixed point_to_dist(Fixed vx, Fixed vy, Fixed x, Fixed y);

// The light map numbers (0 brightest) of R_StoreWallRange and R_DrawPlanes: `light` is
// a sector's 0..255 level, `contrast` Doom's fake contrast (-1, 0, +1), extra the gun's.
int start_map(int light, int contrast, int extra);
// Granlund and Montgomery's division by an invariant d as a multiply: for every
// n < 2^bits, n / d == (n * magic) >> shift. magic_for sets magic and shift.
__extension__ typedef unsigned __int128 U128;
void magic_for(uint64_t d, int bits, uint64_t& magic, int& shift);
inline uint64_t exact_quotient(uint64_t n, uint64_t magic, int shift) { return uint64_t((U128(n) * magic) >> shift); }
// A wall's (or sprite's) scale is taken at Doom's 320 columns (Crispy Doom's hires shifts
// it once more), so light diminishes with distance alike at any width.
inline int wall_map(const Tables& t, int start, Fixed scale) {
  const uint64_t index = exact_quotient(uint64_t(uint32_t(scale)) * kDoomWidth, t.light_magic, t.light_shift);
  const int map = start - t.scale_light_drop[std::min<uint64_t>(index, kMaxLightScale - 1)];
  return map < 0 ? 0 : map >= kColormaps ? kColormaps - 1 : map;
}
inline int flat_map(const Tables& t, int start, Fixed distance) {
  const int index = std::min(int(uint32_t(distance) >> kLightZShift), kMaxLightZ - 1);
  const int map = start - t.zlight_drop[index];
  return map < 0 ? 0 : map >= kColormaps ? kColormaps - 1 : map;
}

// One side of a wall as R_StoreWallRange sets it up for the view: its normal, its
// distance from the viewer along the normal, its texture offset at the column where
// the view's axis meets it.
struct Seg {
  Angle normal = 0;       // rw_normalangle: the side's direction + 90 degrees
  Angle center = 0;       // rw_centerangle
  Fixed distance = 0;     // rw_distance
  Fixed offset = 0;       // rw_offset (texture columns), without the side's own offsets
};
// v1 -> v2: the side's start and end as its seg runs (the front side p1 -> p2, the back
// p2 -> p1), in 16.16; `angle` the seg's direction.
Seg make_seg(const Tables& t, Fixed vx, Fixed vy, Angle view_angle, Fixed v1x, Fixed v1y, Angle angle);
// Crispy Doom's: the distance and offset measured exactly from the seg's own line v1 -> v2
// (its long-wall-wobble fix), its direction the line's unless that strays more than 30
// degrees from the node builder's `angle`.
Seg make_crispy_seg(Fixed vx, Fixed vy, Angle view_angle, Fixed v1x, Fixed v1y, Fixed v2x, Fixed v2y, Angle angle);
// Crispy Doom's moved vertex: a split point (x, y) of a diagonal line through (ax, ay)
// along (dx, dy) put back onto the line, unless that moves it more than 8 units.
void crispy_onto_line(Fixed& x, Fixed& y, Fixed ax, Fixed ay, Fixed dx, Fixed dy);
// Crispy Doom's seg offset (its GetOffset, from PrBoom+): the whole map units from the
// side's start (ax, ay) to the seg's first vertex, truncated, not the SEGS lump's.
Fixed crispy_seg_offset(Fixed v1x, Fixed v1y, Fixed ax, Fixed ay);
// Crispy Doom's wiggle fix (R_FixWiggle): for a sector `height` units tall, the largest
// wall scale and the fraction bits of the wall edges. Vanilla's: 64 and 12.
struct WallPrecision {
  Fixed max_scale = 64 * kFracUnit;
  int height_bits = kHeightBits;
};
WallPrecision wall_precision(const Tables& t, int64_t height);
// The direction of v1 -> v2 as a node builder writes it in SEGS (16-bit binary angles).
Angle seg_angle(double dx, double dy);

// The columns [x1, x2) R_AddLine gives a seg from v1 (left) to v2 seen from the view,
// by Doom's angles (R_PointToAngle, clipped to the view, viewangletox); x1 == x2: none.
void seg_columns(const Tables& t, Fixed vx, Fixed vy, Angle view_angle, Fixed v1x, Fixed v1y, Fixed v2x, Fixed v2y,
                 int& x1, int& x2);
// R_PointOnSegSide: 0 on the seg's front (right of v1 -> v2), 1 behind.
int point_on_seg_side(Fixed x, Fixed y, Fixed v1x, Fixed v1y, Fixed v2x, Fixed v2y);

// The two sines R_ScaleFromGlobalAngle takes at column x: of 90 degrees plus the
// column's angle from the view's axis (anglea), and plus its angle from the seg's
// normal (angleb).
struct ScaleSines {
  Fixed view, seg;
};
inline ScaleSines scale_sines(const Tables& t, const Seg& seg, Angle view_angle, int x) {
  const Angle angleb = play::kAngle90 + (view_angle + t.xtoviewangle[size_t(x)] - seg.normal);
  return {t.view_sine[size_t(x)], play::kFineSine[angleb >> play::kAngleToFineShift]};
}
// Where scale_sines looks one seg's sines up, for a loop that looks up many columns':
// at column x, view_sine[x] and fine_sine[(seg_angle + column_angle[x]) >> 19].
struct SegSines {
  const Fixed* view_sine;     // Tables::view_sine
  const Angle* column_angle;  // Tables::xtoviewangle
  const Fixed* fine_sine;     // play::kFineSine
  Angle seg_angle;            // angleb less the column's angle
};
inline SegSines seg_sines(const Tables& t, const Seg& seg, Angle view_angle) {
  return {t.view_sine.data(), t.xtoviewangle.data(), play::kFineSine, play::kAngle90 + (view_angle - seg.normal)};
}
// The rest of R_ScaleFromGlobalAngle: the scale from those sines (Tables::projection,
// the seg's distance), at most max_scale.
inline Fixed scale_from_sines(Fixed projection, ScaleSines sines, Fixed distance, Fixed max_scale) {
  const Fixed num = play::fixed_mul(projection, sines.seg);
  const Fixed den = play::fixed_mul(distance, sines.view);
  if (den > (num >> kFracBits)) {
    const Fixed scale = play::fixed_div(num, den);
    return scale > max_scale ? max_scale : scale < 256 ? 256 : scale;
  }
  return max_scale;
}
// R_ScaleFromGlobalAngle at column x, at most max_scale (inline: every wall column takes one).
inline Fixed scale_at(const Tables& t, const Seg& seg, Angle view_angle, int x, Fixed max_scale = 64 * kFracUnit) {
  return scale_from_sines(t.projection, scale_sines(t, seg, view_angle, x), seg.distance, max_scale);
}
// The texture column (R_RenderSegLoop's texturecolumn before >> 16) at column x.
inline Fixed texture_column(const Tables& t, const Seg& seg, int x) {
  const Angle a = (seg.center + t.xtoviewangle[size_t(x)]) >> play::kAngleToFineShift;
  return play::wrap_sub(seg.offset, play::fixed_mul(play::kFineTangent[a & (play::kFineAngles / 2 - 1)], seg.distance));
}

}  // namespace p3d::render::doom
