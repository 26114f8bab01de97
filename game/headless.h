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
};

// Throws Error if the demo was recorded on another level. Returns the frames written.
int replay_headless(Session& session, const sim::Demo& demo, const HeadlessOptions& options);

}  // namespace p3d::game
