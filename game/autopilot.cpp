#include "game/autopilot.h"

#include <cmath>

namespace p3d::game {

sim::TicCommand Autopilot::next(const sim::Player& p) {
  sim::TicCommand cmd;
  while (!done()) {
    const double distance = glm::length(waypoints_[index_] - p.pos);
    if (distance < 24 || stuck_tics_ > 3 * sim::kTicRate) {  // reached, or stuck for three seconds: next
      ++index_;
      stuck_tics_ = 0;
      best_distance_ = INFINITY;
      continue;
    }
    if (distance < best_distance_ - 1) {
      best_distance_ = distance;
      stuck_tics_ = 0;
    } else {
      ++stuck_tics_;
    }
    const geom::Vec2 to = waypoints_[index_] - p.pos;
    double turn = std::atan2(to.y, to.x) * 180 / M_PI - p.angle;
    turn = std::remainder(turn, 360.0);
    cmd.turn = int16_t(std::clamp(turn * 65536.0 / 360.0, -1280.0, 1280.0));
    cmd.forward = int8_t(std::fabs(turn) < 30 ? (distance > 96 ? 50 : 25) : 0);
    break;
  }
  return cmd;
}

}  // namespace p3d::game
