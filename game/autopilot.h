// Steers the player through waypoints with ordinary tic commands (turn toward the
// next point, run when facing it), so a demo can be scripted instead of played.
#pragma once

#include <vector>

#include "engine/sim/sim.h"

namespace p3d::game {

class Autopilot {
 public:
  explicit Autopilot(std::vector<geom::Vec2> waypoints) : waypoints_(std::move(waypoints)) {}
  // The command for this tic; done() once every waypoint is reached (or given up on).
  sim::TicCommand next(const sim::Player& player);
  bool done() const { return index_ >= waypoints_.size(); }

 private:
  std::vector<geom::Vec2> waypoints_;
  size_t index_ = 0;
  int stuck_tics_ = 0;
  double best_distance_ = INFINITY;
};

}  // namespace p3d::game
