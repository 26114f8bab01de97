// Replaying a demo with no window: frames as PNG files every N tics and a CSV of
// their statistics. Same demo, same files, byte for byte.
#pragma once

#include <filesystem>
#include <string>

#include "engine/sim/demo.h"
#include "game/session.h"

namespace p3d::game {

struct HeadlessOptions {
  int capture_every = 35;  // tics between frames; frame 0 is the start
  std::filesystem::path out_dir;
  int width = 640, height = 400;
  bool json = false;  // also stats.json: the same fields by name
};

struct HeadlessResult {
  int frames = 0;     // PNG files written
  size_t tics = 0;    // tics replayed: all of them, or up to the exit
  sim::Exit exit = sim::Exit::kNone;
};

// Replays from the demo's start (its skill is the session's, its keys given); stops
// at the level's exit, whose tic gets a last frame. Throws Error if the demo was
// recorded on another level.
HeadlessResult replay_headless(Session& session, const sim::Demo& demo, const HeadlessOptions& options);

// "normal", "secret" or "none".
const char* exit_name(sim::Exit exit);

}  // namespace p3d::game
