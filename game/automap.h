// The automap, its own screen as Doom's (or over the dimmed view): walls from above
// around the player (north up), the BSP's splitting lines, the player's leaf (its
// cell, and the fragments bounding its region, drawn on their side facing it), the
// view cone, the fragments the last frame drew, coloured in draw order, and the
// things present (monsters red, keys in their colour, pickups green, the rest grey).
// Doors are orange, locked doors in their key's colour, teleporters green and exits
// pink, drawn thick.
#pragma once

#include <vector>

#include "engine/level/level.h"
#include "engine/render/camera.h"

namespace p3d::game {

struct AutomapSettings {
  double scale = 0.5;      // pixels per map unit (at a 640-pixel-wide frame)
  bool splitters = true;   // draw the BSP's splitting lines
  bool things = true;      // draw the things present, coloured by kind
  bool overlay = false;    // over the dimmed view instead of on black
};

class Automap {
 public:
  // Caches what depends only on the level (the splitters' chords).
  void set_level(const level::Level& level);
  void draw(render::Frame& frame, const level::Level& level, const level::State& state, const render::Camera& camera,
            const std::vector<uint32_t>& draw_order, const AutomapSettings& settings) const;

 private:
  std::vector<level::Chord> chords_;
  geom::BBox bounds_;
};

}  // namespace p3d::game
