// The player (Doom's p_user.c): thrust from the tic's command, the view's height and
// bob, the weapon chosen, the use key, powers running down, and the slow turn toward
// the killer after death.
#include "engine/play/world.h"

namespace p3d::play {

namespace {
constexpr Fixed kMaxBob = 0x100000;
constexpr Angle kAngle5 = kAngle90 / 18;
constexpr int kInverseColormap = 32;  // invulnerability's white view
}  // namespace

void World::thrust(Player& player, Angle angle, Fixed move) {
  player.mo->mom_x = wrap_add(player.mo->mom_x, fixed_mul(move, cosine(angle)));
  player.mo->mom_y = wrap_add(player.mo->mom_y, fixed_mul(move, sine(angle)));
}

void World::calc_height(Player& player) {
  Mobj* mo = player.mo;
  // The bob grows with the square of the speed.
  player.bob = wrap_add(fixed_mul(mo->mom_x, mo->mom_x), fixed_mul(mo->mom_y, mo->mom_y));
  player.bob >>= 2;
  if (player.bob > kMaxBob) player.bob = kMaxBob;
  if (!on_ground_) {
    // (Doom first sets the view at the full eye height under the ceiling, then replaces it.)
    player.view_z = wrap_add(mo->z, player.view_height);
    return;
  }
  const int angle = int((uint32_t(kFineAngles / 20) * uint32_t(level_time_)) & kFineMask);  // Doom's int wraps
  const Fixed bob = fixed_mul(player.bob / 2, fine_sine(angle));
  if (player.state == PlayerState::kLive) {
    // The view springs back after a landing or a step up.
    player.view_height += player.delta_view_height;
    if (player.view_height > kViewHeight) {
      player.view_height = kViewHeight;
      player.delta_view_height = 0;
    }
    if (player.view_height < kViewHeight / 2) {
      player.view_height = kViewHeight / 2;
      if (player.delta_view_height <= 0) player.delta_view_height = 1;
    }
    if (player.delta_view_height) {
      player.delta_view_height += kFracUnit / 4;
      if (!player.delta_view_height) player.delta_view_height = 1;
    }
  }
  player.view_z = wrap_add(wrap_add(mo->z, player.view_height), bob);
  const Fixed under_ceiling = wrap_sub(mo->ceiling_z, 4 * kFracUnit);
  if (player.view_z > under_ceiling) player.view_z = under_ceiling;
}

void World::move_player(Player& player) {
  const TicCmd& cmd = player.cmd;
  Mobj* mo = player.mo;
  mo->angle += Angle(uint32_t(uint16_t(cmd.turn)) << kFracBits);
  on_ground_ = mo->z <= mo->floor_z;  // no thrust in the air
  if (cmd.forward && on_ground_) thrust(player, mo->angle, cmd.forward * 2048);
  if (cmd.side && on_ground_) thrust(player, mo->angle - kAngle90, cmd.side * 2048);
  if ((cmd.forward || cmd.side) && mo->state == StateId::kPlay) set_mobj_state(mo, StateId::kPlayRun1);
}

void World::death_think(Player& player) {
  move_psprites(player);
  // The view sinks to the floor.
  if (player.view_height > 6 * kFracUnit) player.view_height -= kFracUnit;
  if (player.view_height < 6 * kFracUnit) player.view_height = 6 * kFracUnit;
  player.delta_view_height = 0;
  on_ground_ = player.mo->z <= player.mo->floor_z;
  calc_height(player);
  Mobj* mo = player.mo;
  if (player.attacker && player.attacker != mo) {  // turn toward the killer
    const Angle angle = point_to_angle(mo->x, mo->y, player.attacker->x, player.attacker->y);
    const Angle delta = angle - mo->angle;
    if (delta < kAngle5 || delta > Angle(-kAngle5)) {
      mo->angle = angle;
      if (player.inv.damage_count) --player.inv.damage_count;
    } else if (delta < kAngle180) {
      mo->angle += kAngle5;
    } else {
      mo->angle -= kAngle5;
    }
  } else if (player.inv.damage_count) {
    --player.inv.damage_count;
  }
  if (player.cmd.buttons & kBtUse) player.state = PlayerState::kReborn;
}

void World::player_think(Player& player) {
  Mobj* mo = player.mo;
  if (player.cheats & kCheatNoclip)
    mo->flags |= kNoclip;
  else
    mo->flags &= ~kNoclip;
  TicCmd& cmd = player.cmd;
  if (mo->flags & kJustattacked) {  // a chainsaw lunge: forward, no turn
    cmd.turn = 0;
    cmd.forward = 0xc800 / 512;
    cmd.side = 0;
    mo->flags &= ~kJustattacked;
  }
  if (player.state == PlayerState::kDead) {
    death_think(player);
    return;
  }
  // Frozen after a teleport.
  if (mo->reaction_time)
    --mo->reaction_time;
  else
    move_player(player);
  calc_height(player);
  if (mo->subsector->sector->special) player_in_special_sector(player);

  if (cmd.buttons & kBtSpecial) cmd.buttons = 0;  // pause and save are not play
  if (cmd.buttons & kBtChange) choose_weapon(player, Weapon((cmd.buttons & kBtWeaponMask) >> kBtWeaponShift));
  if (cmd.buttons & kBtUse) {
    if (!player.use_down) {
      use_lines(player);
      player.use_down = true;
    }
  } else {
    player.use_down = false;
  }
  move_psprites(player);
  run_down_powers(player);
}

// The weapon key pressed: the chainsaw shares the fist's key, the super shotgun the shotgun's.
void World::choose_weapon(Player& player, Weapon weapon) {
  Inventory& inv = player.inv;
  auto owned = [&](Weapon w) { return inv.weapons[size_t(w)]; };
  if (weapon == Weapon::kFist && owned(Weapon::kChainsaw) &&
      !(inv.ready == Weapon::kChainsaw && inv.powers[size_t(Power::kStrength)]))
    weapon = Weapon::kChainsaw;
  if (options_.commercial && weapon == Weapon::kShotgun && owned(Weapon::kSuperShotgun) &&
      inv.ready != Weapon::kSuperShotgun)
    weapon = Weapon::kSuperShotgun;
  if (size_t(weapon) < inv.weapons.size() && owned(weapon) && weapon != inv.ready) inv.pending = weapon;
}

void World::run_down_powers(Player& player) {
  auto& powers = player.inv.powers;
  int& strength = powers[size_t(Power::kStrength)];
  if (strength) ++strength;  // counts up: berserk's red fades
  int& invulnerable = powers[size_t(Power::kInvulnerability)];
  if (invulnerable) --invulnerable;
  int& invisible = powers[size_t(Power::kInvisibility)];
  if (invisible && !--invisible) player.mo->flags &= ~kShadow;
  int& infrared = powers[size_t(Power::kInfrared)];
  if (infrared) --infrared;
  int& iron_feet = powers[size_t(Power::kIronFeet)];
  if (iron_feet) --iron_feet;
  if (player.inv.damage_count) --player.inv.damage_count;
  if (player.inv.bonus_count) --player.inv.bonus_count;
  // The view's colour map: blinking as a power runs out.
  auto blinking_on = [](int left) { return left > 4 * 32 || (left & 8); };
  if (invulnerable)
    player.fixed_colormap = blinking_on(invulnerable) ? kInverseColormap : 0;
  else if (infrared)
    player.fixed_colormap = blinking_on(infrared) ? 1 : 0;
  else
    player.fixed_colormap = 0;
}

void World::reborn_player(Player& p) {
  const int kills = p.kill_count, items = p.inv.items, secrets = p.secret_count, number = p.number;
  const auto frags = p.frags;
  p = Player{};
  p.number = number;
  p.frags = frags;
  p.kill_count = kills;
  p.inv.items = items;
  p.secret_count = secrets;
  p.use_down = p.attack_down = true;  // nothing happens before the keys are let go
  p.state = PlayerState::kLive;
  p.inv.ready = p.inv.pending = Weapon::kPistol;
}

}  // namespace p3d::play
