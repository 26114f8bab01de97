// Key scripts: the front end driven headless, tic by tic, by keys pressed, held,
// typed and frames captured at given tics, so that a title, a menu, a save typed
// into its slot can be captured and checked without a window:
//
//   # tic  what
//   35 key escape        press and let go
//   40 hold w            held until released
//   75 release w
//   80 type my save      the letters, one key each
//   90 shot menu.png     the frame now, into the output directory
//   400 end              stop (else after the last line)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "game/front_end.h"

namespace p3d::game {

struct ScriptStep {
  enum class Kind : uint8_t { kKey, kHold, kRelease, kType, kShot, kEnd };
  uint64_t tic = 0;
  Kind kind = Kind::kKey;
  int key = 0;       // kKey, kHold, kRelease
  std::string text;  // kType: the letters; kShot: the file name
  int line = 0;      // where it was written, for messages
};

// Throws Error("<where>:<line>: ...") for an unknown step, key or a tic out of order.
std::vector<ScriptStep> parse_key_script(const std::string& text, const std::string& where);

struct ScriptResult {
  uint64_t tics = 0;
  int shots = 0;
  std::string log;  // a line per tic with sounds or music: "35 sound swtchn", "36 music D_DM2TTL loop"
};

// Runs the front end through the script, writing each shot as a PNG of width x
// height into out_dir (created), and the log as out_dir/log.txt.
ScriptResult run_key_script(FrontEnd& front, const std::vector<ScriptStep>& steps, const std::filesystem::path& out_dir,
                            int width, int height);

}  // namespace p3d::game
