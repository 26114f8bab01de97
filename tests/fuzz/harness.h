// What every fuzz target shares: where inputs' texture paths resolve, and a small render of a level through two
// renderers, so what a reader accepts is also drawn.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

#include "engine/bsp/build.h"
#include "engine/bsp/check.h"
#include "engine/level/io.h"
#include "engine/level/level.h"
#include "engine/map/source.h"
#include "engine/render/renderer.h"
#include "engine/util/error.h"

namespace p3d::fuzz {

inline std::filesystem::path maps_dir() { return std::filesystem::path(P3D_SOURCE_DIR) / "maps"; }
// .map and .grid inputs are read as if they lay in tests/fuzz/seeds/ (the seeds there
// use the smallest bundled textures, so an input is quick to load).
inline std::filesystem::path seeds_dir() { return std::filesystem::path(P3D_SOURCE_DIR) / "tests/fuzz/seeds"; }

// A few cameras (the player start, the level's corners) at 24x16, bsp and reference,
// at the start state and with its things.
inline void render_a_little(const level::Level& level) {
  const level::State state = level::start_state(level);
  render::Frame frame(24, 16);
  const geom::Vec2 spots[] = {level.player_start, level.bounds.min, level.bounds.max,
                              (level.bounds.min + level.bounds.max) * 0.5};
  for (const char* name : {"bsp", "reference"}) {
    auto r = render::make_renderer(name);
    r->prepare(level);
    for (size_t i = 0; i < std::size(spots); ++i)
      r->render(level, state, render::camera_at(level, spots[i], 45.0 * double(i)), frame);
  }
}

// A text map's path of inputs, whatever its format: validated, compiled, checked
// against the BSP invariants, written, read back and drawn. A broken promise traps.
inline void compile_and_draw(const map::Source& src) {
  map::validate(src);
  const level::Level level = bsp::build(src, {});
  if (!bsp::check_invariants(level).empty()) __builtin_trap();                  // the compiler's promise
  const level::Level back = level::decode(level::encode(level), "round trip");  // never writes what it cannot read
  render_a_little(back);
}

}  // namespace p3d::fuzz
