#include "game/input.h"

#include <algorithm>
#include <cmath>

namespace p3d::game {

play::DemoTic make_command(const Controls& c, int turn_held_tics, const InputSettings& settings) {
  play::TicCmd cmd;
  const int forward = c.run ? 50 : 25, side = c.run ? 40 : 24;
  const int turn = turn_held_tics < 6 ? 320 : c.run ? 1280 : 640;
  cmd.forward = int8_t((c.forward - c.back) * forward);
  int strafe = c.strafe_right - c.strafe_left;
  int turning = c.turn_left - c.turn_right;  // counter-clockwise is positive
  if (c.strafe_modifier) {
    strafe -= turning;  // Alt+Left strafes left
    turning = 0;
  }
  cmd.side = int8_t(std::clamp(strafe, -1, 1) * side);
  const double mouse = -c.mouse_dx * settings.mouse_sensitivity;
  cmd.turn = int16_t(std::clamp(turning * turn + std::lround(mouse), -32767L, 32767L));
  cmd.buttons = uint8_t((c.attack ? play::kBtAttack : 0) | (c.use ? play::kBtUse : 0));
  if (c.weapon >= 1 && c.weapon <= 7)  // Doom's keys 1..7 name weapons 0..6
    cmd.buttons |= uint8_t(play::kBtChange | (c.weapon - 1) << play::kBtWeaponShift);
  return {cmd, c.cheats};
}

uint8_t Cheats::type(char letter) {
  typed_ += letter;
  if (typed_.size() > 16) typed_.erase(0, typed_.size() - 16);
  auto ends_with = [&](std::string_view s) { return typed_.size() >= s.size() && typed_.ends_with(s); };
  uint8_t cheat = 0;
  if (ends_with("idclip") || ends_with("idspispopd")) cheat = play::kToggleNoclip;
  if (ends_with("iddqd")) cheat = play::kToggleGod;
  if (ends_with("idkfa")) cheat = play::kGiveAll;
  if (cheat) typed_.clear();
  return cheat;
}

}  // namespace p3d::game
