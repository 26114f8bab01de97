// Steers the player through waypoints with ordinary tic commands (turn toward the
// next point, run when facing it), so a demo can be scripted instead of played. A
// waypoint may also press use there (facing a given way) or wait a while (for a
// door or a lift).
#pragma once

#include <vector>

#include "engine/render/camera_file.h"
#include "engine/play/world.h"

namespace p3d::game {

struct Waypoint {
  enum class Action { kWalk, kUse, kWait };
  geom::Vec2 pos;
  double angle = 0;  // kUse: the way to face
  Action action = Action::kWalk;
};

// A route from a camera list: a camera named "use" presses use there facing its
// angle, one named "wait" stands there for two seconds, any other is walked through.
std::vector<Waypoint> route_from_cameras(const std::vector<render::CameraSpec>& cameras);

class Autopilot {
 public:
  explicit Autopilot(std::vector<Waypoint> waypoints) : waypoints_(std::move(waypoints)) {}
  // done() once every waypoint is reached (or given up on).
  // The command for this tic, for a player at `pos` facing `angle` (degrees).
  play::TicCmd next(geom::Vec2 pos, double angle);
  bool done() const { return index_ >= waypoints_.size(); }

 private:
  void advance();
  play::TicCmd walk_to(geom::Vec2 pos, double angle, geom::Vec2 target, double distance) const;

  std::vector<Waypoint> waypoints_;
  size_t index_ = 0;
  bool arrived_ = false;  // at the current waypoint, doing its action
  int stuck_tics_ = 0, action_tics_ = 0;
  double best_distance_ = INFINITY;
};

}  // namespace p3d::game
