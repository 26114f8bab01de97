#include "game/autopilot.h"

#include <cmath>

namespace p3d::game {

namespace {

constexpr double kReached = 24;
constexpr int kGiveUpTics = 3 * 35;  // stuck this long: on to the next waypoint
constexpr int kAfterUseTics = 35;     // a door needs a second to open
constexpr int kWaitTics = 2 * 35;

// The turn (1/65536 of a turn) toward `degrees`, at most a fast keyboard turn a tic.
int16_t turn_toward(double from, double degrees) {
  const double turn = std::remainder(degrees - from, 360.0);
  return int16_t(std::clamp(turn * 65536.0 / 360.0, -1280.0, 1280.0));
}

}  // namespace

std::vector<Waypoint> route_from_cameras(const std::vector<render::CameraSpec>& cameras) {
  std::vector<Waypoint> route;
  for (const render::CameraSpec& c : cameras) {
    Waypoint w{c.pos, c.angle};
    if (c.name == "use") w.action = Waypoint::Action::kUse;
    if (c.name == "wait") w.action = Waypoint::Action::kWait;
    route.push_back(w);
  }
  return route;
}

void Autopilot::advance() {
  ++index_;
  arrived_ = false;
  stuck_tics_ = action_tics_ = 0;
  best_distance_ = INFINITY;
}

play::TicCmd Autopilot::walk_to(geom::Vec2 pos, double angle, geom::Vec2 target, double distance) const {
  const geom::Vec2 to = target - pos;
  play::TicCmd cmd;
  cmd.turn = turn_toward(angle, std::atan2(to.y, to.x) * 180 / M_PI);
  const double off = std::fabs(std::remainder(std::atan2(to.y, to.x) * 180 / M_PI - angle, 360.0));
  cmd.forward = int8_t(off < 30 ? (distance > 96 ? 50 : 25) : 0);
  return cmd;
}

play::TicCmd Autopilot::next(geom::Vec2 pos, double angle) {
  while (!done()) {
    const Waypoint& w = waypoints_[index_];
    if (!arrived_) {
      const double distance = glm::length(w.pos - pos);
      if (distance < kReached || stuck_tics_ > kGiveUpTics) {
        arrived_ = true;
        if (w.action == Waypoint::Action::kWalk) advance();
        continue;
      }
      if (distance < best_distance_ - 1) {
        best_distance_ = distance;
        stuck_tics_ = 0;
      } else {
        ++stuck_tics_;
      }
      return walk_to(pos, angle, w.pos, distance);
    }
    play::TicCmd cmd;
    ++action_tics_;
    if (w.action == Waypoint::Action::kWait) {
      if (action_tics_ > kWaitTics) {
        advance();
        continue;
      }
      return cmd;
    }
    // kUse: face the way, press once, give the door a second.
    if (action_tics_ > kAfterUseTics + kGiveUpTics) {
      advance();
      continue;
    }
    const int16_t turn = turn_toward(angle, w.angle);
    if (std::abs(turn) > 60 && action_tics_ < kGiveUpTics) {
      cmd.turn = turn;
      return cmd;
    }
    if (action_tics_ < kGiveUpTics) {
      cmd.buttons = play::kBtUse;
      action_tics_ = kGiveUpTics;  // pressed: now wait
      return cmd;
    }
    return cmd;
  }
  return {};
}

}  // namespace p3d::game
