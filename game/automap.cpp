#include "game/automap.h"

#include "engine/play/line_kinds.h"
#include "engine/wad/things.h"

#include <cmath>

#include "engine/image/draw2d.h"

namespace p3d::game {

namespace {

// Red (first drawn) through yellow and green to violet (last).
uint32_t order_colour(size_t k, size_t n) {
  const double h = 280.0 * double(k) / double(std::max<size_t>(n, 2) - 1) / 60.0;
  const double x = 1 - std::fabs(std::fmod(h, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (int(h)) {
    case 0: r = 1, g = x; break;
    case 1: r = x, g = 1; break;
    case 2: g = 1, b = x; break;
    case 3: g = x, b = 1; break;
    default: r = x, b = 1; break;
  }
  return image::rgba(uint32_t(60 + 195 * r), uint32_t(60 + 195 * g), uint32_t(60 + 195 * b));
}

}  // namespace

void Automap::set_level(const level::Level& level) {
  bounds_ = level.bounds;
  bounds_.min -= geom::Vec2(64);
  bounds_.max += geom::Vec2(64);
  chords_ = level::node_chords(level, bounds_);
}

namespace {

uint32_t key_colour(play::Lock lock) {
  switch (lock) {
    case play::Lock::kBlue: return image::rgba(70, 110, 255);
    case play::Lock::kYellow: return image::rgba(240, 220, 40);
    case play::Lock::kRed: return image::rgba(240, 40, 40);
    case play::Lock::kNone: break;
  }
  return image::rgba(230, 230, 230);
}

// The colour of a line by its special: doors, locked doors in their key's colour,
// teleporters, exits. False for other lines (colour unchanged).
bool special_colour(int special, uint32_t& colour) {
  switch (play::line_kind(special)) {
    case play::LineKind::kDoor: colour = image::rgba(240, 140, 40); return true;
    case play::LineKind::kLockedDoor: colour = key_colour(play::line_lock(special)); return true;
    case play::LineKind::kTeleporter: colour = image::rgba(60, 230, 100); return true;
    case play::LineKind::kExit: colour = image::rgba(255, 90, 200); return true;
    case play::LineKind::kPlain: break;
  }
  return false;
}

uint32_t thing_colour(int type) {
  const wad::ThingInfo* info = wad::thing_info(type);
  if (!info) return image::rgba(150, 150, 150);
  switch (info->kind) {
    case wad::ThingKind::kMonster: return image::rgba(230, 60, 50);
    case wad::ThingKind::kPickup: return image::rgba(80, 210, 90);
    case wad::ThingKind::kKey:
      return type == 5 || type == 40 ? image::rgba(70, 110, 255) : type == 6 || type == 39 ? image::rgba(240, 220, 40)
                                                                                           : image::rgba(240, 40, 40);
    case wad::ThingKind::kDecoration: break;
  }
  return image::rgba(150, 150, 150);
}

}  // namespace

void Automap::draw(render::Frame& frame, const level::Level& level, const level::State& state,
                   const render::Camera& camera, const std::vector<uint32_t>& draw_order,
                   const AutomapSettings& settings) const {
  const double scale = settings.scale * frame.width / 640.0;
  const geom::Vec2 centre{frame.width / 2.0, frame.height / 2.0};
  auto screen = [&](geom::Vec2 p) { return geom::Vec2{centre.x + (p.x - camera.pos.x) * scale, centre.y - (p.y - camera.pos.y) * scale}; };
  // The part of the world on screen, to skip everything else cheaply on big maps.
  const geom::Vec2 half{frame.width / (2 * scale), frame.height / (2 * scale)};
  geom::BBox view;
  view.add(camera.pos - half);
  view.add(camera.pos + half);
  auto visible = [&](geom::Vec2 a, geom::Vec2 b) {
    return std::max(a.x, b.x) >= view.min.x && std::min(a.x, b.x) <= view.max.x && std::max(a.y, b.y) >= view.min.y &&
           std::min(a.y, b.y) <= view.max.y;
  };

  image::fill_rect(frame, 0, 0, frame.width, frame.height, image::rgba(0, 0, 0), settings.overlay ? 190 : 255);
  std::vector<geom::Vec2> cell = level::cell_at(level, camera.pos, bounds_);
  for (geom::Vec2& p : cell) p = screen(p);
  image::fill_convex(frame, cell, image::rgba(230, 200, 60), 70);
  if (settings.splitters)
    for (const level::Chord& c : chords_)
      if (!c.empty && visible(c.a, c.b)) image::draw_line(frame, screen(c.a), screen(c.b), image::rgba(70, 110, 220), 110);
  for (const level::Wall& w : level.walls) {
    if (!visible(w.a, w.b)) continue;
    uint32_t colour = image::rgba(230, 230, 230);
    if (w.segment()) colour = image::rgba(90, 200, 230);
    else if (w.two_sided()) {
      const level::Sector& f = level.sectors[w.sides[0].sector];
      const level::Sector& b = level.sectors[w.sides[1].sector];
      colour = f.floor != b.floor ? image::rgba(200, 150, 80) : f.ceiling != b.ceiling ? image::rgba(220, 220, 90)
                                                                                       : image::rgba(110, 110, 110);
    }
    const bool special = special_colour(w.special, colour);
    image::draw_line(frame, screen(w.a), screen(w.b), colour);
    if (special) {  // doors, locks, teleporters and exits twice as thick
      const geom::Vec2 d = screen(w.b) - screen(w.a);
      const geom::Vec2 n = glm::length(d) > 0 ? geom::Vec2(-d.y, d.x) / glm::length(d) : geom::Vec2(0);
      image::draw_line(frame, screen(w.a) + n, screen(w.b) + n, colour);
    }
  }
  // The player's leaf: the fragments bounding its region, on their side facing it.
  const level::Leaf& leaf = level.leaves[size_t(level.leaf_at(camera.pos))];
  for (uint32_t i = leaf.first_fragment; i < leaf.first_fragment + leaf.fragment_count; ++i) {
    const level::Fragment& f = level.fragments[i];
    const geom::Vec2 a = screen(f.p0), b = screen(f.p1);
    if (glm::length(b - a) == 0) continue;
    const geom::Vec2 d = glm::normalize(b - a), inward = (f.side == 0 ? 2.0 : -2.0) * geom::Vec2(-d.y, d.x);
    image::draw_line(frame, a + inward, b + inward, image::rgba(250, 220, 70));
  }
  for (size_t k = 0; k < draw_order.size(); ++k) {  // the last frame's fragments, in the order drawn
    if (draw_order[k] >= level.fragments.size()) continue;
    const level::Fragment& f = level.fragments[draw_order[k]];
    const geom::Vec2 a = screen(f.p0), b = screen(f.p1), n = glm::length(b - a) > 0 ? glm::normalize(b - a) : geom::Vec2(0);
    for (int offset : {-1, 0, 1})
      image::draw_line(frame, a + geom::Vec2(-n.y, n.x) * double(offset), b + geom::Vec2(-n.y, n.x) * double(offset),
                       order_colour(k, draw_order.size()));
  }
  if (settings.things)
    for (const level::ShownThing& t : state.things) {
      if (!visible(t.pos, t.pos)) continue;
      const geom::Vec2 c = screen(t.pos);
      const double a = t.angle * M_PI / 180, r = std::max(2.0, 10 * scale);
      const geom::Vec2 tip = c + geom::Vec2(std::cos(a), -std::sin(a)) * r;  // a triangle facing its way
      const geom::Vec2 left = c + geom::Vec2(std::cos(a + 2.4), -std::sin(a + 2.4)) * r;
      const geom::Vec2 right = c + geom::Vec2(std::cos(a - 2.4), -std::sin(a - 2.4)) * r;
      const uint32_t colour = thing_colour(t.placed != level::kNone ? level.things[size_t(t.placed)].type : 0);
      image::draw_line(frame, tip, left, colour);
      image::draw_line(frame, left, right, colour);
      image::draw_line(frame, right, tip, colour);
    }
  const double angle = camera.angle * M_PI / 180, half_fov = camera.fov * M_PI / 360;
  const double reach = 2 * std::max(frame.width, frame.height);
  for (double side : {-1.0, 1.0}) {
    const double a = angle + side * half_fov;
    image::draw_line(frame, centre, centre + geom::Vec2(std::cos(a), -std::sin(a)) * reach, image::rgba(120, 230, 120), 150);
  }
  const geom::Vec2 tip = centre + geom::Vec2(std::cos(angle), -std::sin(angle)) * 10.0;
  for (double side : {-2.5, 2.5})
    image::draw_line(frame, tip, centre + geom::Vec2(std::cos(angle + side), -std::sin(angle + side)) * 6.0,
                     image::rgba(120, 255, 120));
  image::draw_line(frame, centre, tip, image::rgba(120, 255, 120));
}

}  // namespace p3d::game
