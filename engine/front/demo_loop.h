// Doom's title loop (d_main.c's D_DoAdvanceDemo and D_PageTicker): the title page
// with its music, the WAD's demos and the credit or help pages between them, in
// the order Doom, the Ultimate Doom and Doom II use, round and round.
#pragma once

#include <cstdint>
#include <string>

#include "engine/front/game_mode.h"
#include "engine/play/music.h"

namespace p3d::front {

struct DemoStep {
  enum class Kind : uint8_t { kPage, kDemo };
  Kind kind = Kind::kPage;
  std::string lump;   // the page's picture (TITLEPIC, CREDIT, HELP2) or the demo (DEMO1..DEMO4)
  int tics = 0;       // a page's time on screen
  play::Track music{play::Music::kNone, false};  // a page's music (the title's, once), or none: it goes on
};

class DemoLoop {
 public:
  explicit DemoLoop(GameMode mode) : mode_(mode) {}
  // The next step (the first: the title page), as D_DoAdvanceDemo.
  DemoStep advance();
  // Back to the start, the title next (D_StartTitle).
  void restart() { sequence_ = -1; }

 private:
  GameMode mode_;
  int sequence_ = -1;
};

}  // namespace p3d::front
