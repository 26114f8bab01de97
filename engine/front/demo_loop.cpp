#include "engine/front/demo_loop.h"

namespace p3d::front {

DemoStep DemoLoop::advance() {
  const bool commercial = mode_ == GameMode::kCommercial, ultimate = mode_ == GameMode::kRetail;
  // The Ultimate Doom added DEMO4 as a seventh step; Doom II plays three demos.
  sequence_ = (sequence_ + 1) % (ultimate ? 7 : 6);
  const play::Track title_music = play::title_track(commercial);
  constexpr int kTicRate = 35;
  using Kind = DemoStep::Kind;
  switch (sequence_) {
    case 0: return {Kind::kPage, "TITLEPIC", commercial ? 11 * kTicRate : 170, title_music};
    case 1: return {Kind::kDemo, "DEMO1"};
    case 2: return {Kind::kPage, "CREDIT", 200};
    case 3: return {Kind::kDemo, "DEMO2"};
    case 4:
      if (commercial) return {Kind::kPage, "TITLEPIC", 11 * kTicRate, title_music};
      return {Kind::kPage, ultimate ? "CREDIT" : "HELP2", 200};
    case 5: return {Kind::kDemo, "DEMO3"};
    default: return {Kind::kDemo, "DEMO4"};
  }
}

}  // namespace p3d::front
