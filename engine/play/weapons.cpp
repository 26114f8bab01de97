// The player's weapons (Doom's p_pspr.c): the weapon sprite's states, which lower,
// raise, ready and fire the weapon in hand, its flash, and every weapon's attack.
#include <array>

#include "engine/play/world.h"

namespace p3d::play {

namespace {

using S = StateId;

constexpr Fixed kLowerSpeed = 6 * kFracUnit, kRaiseSpeed = 6 * kFracUnit;
constexpr Fixed kWeaponBottom = 128 * kFracUnit, kWeaponTop = 32 * kFracUnit;
constexpr Fixed kAimRange = 16 * 64 * kFracUnit;  // bullets' and the BFG spray's autoaim
constexpr int kBfgCellsPerShot = 40;              // Doom's deh_bfg_cells_per_shot

// A weapon's states (Doom's weaponinfo; the ammo it uses is ammo_of).
struct WeaponStates {
  StateId up, down, ready, attack, flash;
};
constexpr std::array<WeaponStates, size_t(Weapon::kCount)> kWeaponStates = {{
    {S::kPunchup, S::kPunchdown, S::kPunch, S::kPunch1, S::kNull},
    {S::kPistolup, S::kPistoldown, S::kPistol, S::kPistol1, S::kPistolflash},
    {S::kSgunup, S::kSgundown, S::kSgun, S::kSgun1, S::kSgunflash1},
    {S::kChainup, S::kChaindown, S::kChain, S::kChain1, S::kChainflash1},
    {S::kMissileup, S::kMissiledown, S::kMissile, S::kMissile1, S::kMissileflash1},
    {S::kPlasmaup, S::kPlasmadown, S::kPlasma, S::kPlasma1, S::kPlasmaflash1},
    {S::kBfgup, S::kBfgdown, S::kBfg, S::kBfg1, S::kBfgflash1},
    {S::kSawup, S::kSawdown, S::kSaw, S::kSaw1, S::kNull},
    {S::kDsgunup, S::kDsgundown, S::kDsgun, S::kDsgun1, S::kDsgunflash1},
}};

const WeaponStates& states_of(Weapon weapon) { return kWeaponStates[size_t(weapon)]; }

// A state some states after another (the chaingun's and plasma gun's flashes).
StateId offset(StateId state, int by) { return StateId(int(state) + by); }

// Doom's small random turn of a shot: P_SubRandom() << 18.
Angle spread(Random& random) { return Angle(random.play_difference() * (1 << 18)); }

// The weapon Doom switches to when the one in hand is out of ammo, by its fixed
// preference (the shareware checks always pass: no shareware game is played).
Weapon weapon_with_ammo(const Inventory& inv, bool commercial) {
  auto owns = [&](Weapon w) { return inv.weapons[size_t(w)]; };
  auto ammo = [&](AmmoType a) { return inv.ammo[size_t(a)]; };
  if (owns(Weapon::kPlasma) && ammo(AmmoType::kCell)) return Weapon::kPlasma;
  if (owns(Weapon::kSuperShotgun) && ammo(AmmoType::kShell) > 2 && commercial) return Weapon::kSuperShotgun;
  if (owns(Weapon::kChaingun) && ammo(AmmoType::kClip)) return Weapon::kChaingun;
  if (owns(Weapon::kShotgun) && ammo(AmmoType::kShell)) return Weapon::kShotgun;
  if (ammo(AmmoType::kClip)) return Weapon::kPistol;
  if (owns(Weapon::kChainsaw)) return Weapon::kChainsaw;
  if (owns(Weapon::kMissile) && ammo(AmmoType::kMissile)) return Weapon::kMissile;
  if (owns(Weapon::kBfg) && ammo(AmmoType::kCell) > 40) return Weapon::kBfg;
  return Weapon::kFist;
}

// The weapons' actions, as Doom's A_* functions of p_pspr.c: each gets the World, the
// player and the weapon sprite whose state called it.
class WeaponActions {
 public:
  WeaponActions(World& world, Player& player, Psprite& psp)
      : w_(world), player_(player), psp_(psp), inv_(player.inv), mo_(player.mo) {}

  void run(Action action);

 private:
  const WeaponStates& in_hand() const { return states_of(inv_.ready); }
  void use_ammo(int amount);
  void bullet_slope();
  void gun_shot(bool accurate);
  void weapon_ready();
  void re_fire();
  void lower();
  void raise();
  void gun_flash();
  void punch();
  void saw();
  void fire_pistol();
  void fire_shotgun();
  void fire_super_shotgun();
  void fire_chaingun();
  void fire_plasma();

  World& w_;
  Player& player_;
  Psprite& psp_;
  Inventory& inv_;
  Mobj* mo_;
};

void WeaponActions::run(Action action) {
  switch (action) {
    case Action::kLight0: player_.extra_light = 0; break;
    case Action::kLight1: player_.extra_light = 1; break;
    case Action::kLight2: player_.extra_light = 2; break;
    case Action::kWeaponReady: weapon_ready(); break;
    case Action::kLower: lower(); break;
    case Action::kRaise: raise(); break;
    case Action::kReFire: re_fire(); break;
    case Action::kCheckReload: w_.check_ammo(player_); break;
    case Action::kGunFlash: gun_flash(); break;
    case Action::kPunch: punch(); break;
    case Action::kSaw: saw(); break;
    case Action::kFirePistol: fire_pistol(); break;
    case Action::kFireShotgun: fire_shotgun(); break;
    case Action::kFireShotgun2: fire_super_shotgun(); break;
    case Action::kOpenShotgun2: w_.start_sound(mo_, Sound::kDbopn); break;
    case Action::kLoadShotgun2: w_.start_sound(mo_, Sound::kDbload); break;
    case Action::kCloseShotgun2:
      w_.start_sound(mo_, Sound::kDbcls);
      re_fire();
      break;
    case Action::kFireCGun: fire_chaingun(); break;
    case Action::kFireMissile:
      use_ammo(1);
      w_.spawn_player_missile(mo_, ThingType::kRocket);
      break;
    case Action::kFirePlasma: fire_plasma(); break;
    case Action::kBFGsound: w_.start_sound(mo_, Sound::kBfg); break;
    case Action::kFireBFG:
      use_ammo(kBfgCellsPerShot);
      w_.spawn_player_missile(mo_, ThingType::kBfg);
      break;
    default: break;  // not a weapon's action
  }
}

void WeaponActions::use_ammo(int amount) {
  // Doom would take a weapon without ammo's shots from the shells' maximum; no
  // weapon of the game fires that way.
  const AmmoType ammo = ammo_of(inv_.ready);
  if (ammo != AmmoType::kNone) inv_.ammo[size_t(ammo)] -= amount;
}

// Doom's P_BulletSlope: aim straight ahead, else a little to the left, else a little
// to the right, so that a near miss still hits at the target's height.
void WeaponActions::bullet_slope() {
  Angle angle = mo_->angle;
  w_.bullet_slope_ = w_.aim_line_attack(mo_, angle, kAimRange);
  if (w_.line_target_) return;
  angle += 1 << 26;
  w_.bullet_slope_ = w_.aim_line_attack(mo_, angle, kAimRange);
  if (w_.line_target_) return;
  angle -= 2 << 26;
  w_.bullet_slope_ = w_.aim_line_attack(mo_, angle, kAimRange);
}

// Doom's P_GunShot: one bullet, turned a little unless it is the first of a burst.
void WeaponActions::gun_shot(bool accurate) {
  const int damage = 5 * (w_.random_.play() % 3 + 1);
  Angle angle = mo_->angle;
  if (!accurate) angle += spread(w_.random_);
  w_.line_attack(mo_, angle, kMissileRange, w_.bullet_slope_, damage);
}

// A_WeaponReady: back from the attack frames; lower the weapon for a change (or
// death), fire (the launcher and the BFG not again while the button stays down), or
// bob with the player's walk.
void WeaponActions::weapon_ready() {
  if (mo_->state == S::kPlayAtk1 || mo_->state == S::kPlayAtk2) w_.set_mobj_state(mo_, S::kPlay);
  if (inv_.ready == Weapon::kChainsaw && psp_.state == S::kSaw) w_.start_sound(mo_, Sound::kSawidl);
  if (inv_.pending != Weapon::kCount || !inv_.health) {
    w_.set_psprite(player_, kPsWeapon, in_hand().down);
    return;
  }
  if (player_.cmd.buttons & kBtAttack) {
    if (!player_.attack_down || (inv_.ready != Weapon::kMissile && inv_.ready != Weapon::kBfg)) {
      player_.attack_down = true;
      w_.fire_weapon(player_);
      return;
    }
  } else {
    player_.attack_down = false;
  }
  const int angle = int((uint32_t(w_.level_time_) * 128) & kFineMask);
  psp_.sx = kFracUnit + fixed_mul(player_.bob, fine_cosine(angle));
  psp_.sy = kWeaponTop + fixed_mul(player_.bob, fine_sine(angle & (kFineAngles / 2 - 1)));
}

// A_ReFire: fire again while the button is held (unless a change waits), else stop
// counting the burst and check the ammo.
void WeaponActions::re_fire() {
  if ((player_.cmd.buttons & kBtAttack) && inv_.pending == Weapon::kCount && inv_.health) {
    ++player_.refire;
    w_.fire_weapon(player_);
  } else {
    player_.refire = 0;
    w_.check_ammo(player_);
  }
}

// A_Lower: down a step; at the bottom the pending weapon comes up, unless the player
// is dead.
void WeaponActions::lower() {
  psp_.sy += kLowerSpeed;
  if (psp_.sy < kWeaponBottom) return;
  if (player_.state == PlayerState::kDead) {
    psp_.sy = kWeaponBottom;
    return;
  }
  if (!inv_.health) {  // dying: keep it off the screen
    w_.set_psprite(player_, kPsWeapon, S::kNull);
    return;
  }
  if (inv_.pending != Weapon::kCount) inv_.ready = inv_.pending;  // (no weapon pending: only a broken save; Doom read past its table)
  w_.bring_up_weapon(player_);
}

// A_Raise: up a step; at the top the weapon is ready.
void WeaponActions::raise() {
  psp_.sy -= kRaiseSpeed;
  if (psp_.sy > kWeaponTop) return;
  psp_.sy = kWeaponTop;
  w_.set_psprite(player_, kPsWeapon, in_hand().ready);
}

void WeaponActions::gun_flash() {
  w_.set_mobj_state(mo_, S::kPlayAtk2);
  w_.set_psprite(player_, kPsFlash, in_hand().flash);
}

// A_Punch: ten times as hard with berserk; the player turns to what it hit.
void WeaponActions::punch() {
  int damage = (w_.random_.play() % 10 + 1) << 1;
  if (inv_.powers[size_t(Power::kStrength)]) damage *= 10;
  const Angle angle = mo_->angle + spread(w_.random_);
  const Fixed slope = w_.aim_line_attack(mo_, angle, kMeleeRange);
  w_.line_attack(mo_, angle, kMeleeRange, slope, damage);
  if (!w_.line_target_) return;
  w_.start_sound(mo_, Sound::kPunch);
  mo_->angle = point_to_angle(mo_->x, mo_->y, w_.line_target_->x, w_.line_target_->y);
}

// A_Saw: a unit past melee range, so that the puff shows; it drags the player's aim
// towards what it cuts, a little at a time.
void WeaponActions::saw() {
  const int damage = 2 * (w_.random_.play() % 10 + 1);
  Angle angle = mo_->angle + spread(w_.random_);
  const Fixed slope = w_.aim_line_attack(mo_, angle, kMeleeRange + 1);
  w_.line_attack(mo_, angle, kMeleeRange + 1, slope, damage);
  if (!w_.line_target_) {
    w_.start_sound(mo_, Sound::kSawful);
    return;
  }
  w_.start_sound(mo_, Sound::kSawhit);
  angle = point_to_angle(mo_->x, mo_->y, w_.line_target_->x, w_.line_target_->y);
  constexpr Angle kStep = kAngle90 / 20, kNear = kAngle90 / 21;
  const Angle turn = angle - mo_->angle;
  if (turn > kAngle180) {  // to the right
    if (int32_t(turn) < -int32_t(kStep))
      mo_->angle = angle + kNear;
    else
      mo_->angle -= kStep;
  } else {
    if (turn > kStep)
      mo_->angle = angle - kNear;
    else
      mo_->angle += kStep;
  }
  mo_->flags |= kJustattacked;
}

void WeaponActions::fire_pistol() {
  w_.start_sound(mo_, Sound::kPistol);
  w_.set_mobj_state(mo_, S::kPlayAtk2);
  use_ammo(1);
  w_.set_psprite(player_, kPsFlash, in_hand().flash);
  bullet_slope();
  gun_shot(!player_.refire);
}

void WeaponActions::fire_shotgun() {
  w_.start_sound(mo_, Sound::kShotgn);
  w_.set_mobj_state(mo_, S::kPlayAtk2);
  use_ammo(1);
  w_.set_psprite(player_, kPsFlash, in_hand().flash);
  bullet_slope();
  for (int i = 0; i < 7; ++i) gun_shot(false);
}

// A_FireShotgun2: two shells, twenty pellets spread wide and up and down.
void WeaponActions::fire_super_shotgun() {
  w_.start_sound(mo_, Sound::kDshtgn);
  w_.set_mobj_state(mo_, S::kPlayAtk2);
  use_ammo(2);
  w_.set_psprite(player_, kPsFlash, in_hand().flash);
  bullet_slope();
  for (int i = 0; i < 20; ++i) {
    const int damage = 5 * (w_.random_.play() % 3 + 1);
    const Angle angle = mo_->angle + Angle(w_.random_.play_difference() * (1 << kAngleToFineShift));
    const Fixed slope = w_.bullet_slope_ + w_.random_.play_difference() * (1 << 5);
    w_.line_attack(mo_, angle, kMissileRange, slope, damage);
  }
}

// A_FireCGun: the sound even when empty; the flash follows the barrel's frame.
void WeaponActions::fire_chaingun() {
  w_.start_sound(mo_, Sound::kPistol);
  const AmmoType ammo = ammo_of(inv_.ready);
  if (ammo == AmmoType::kNone || !inv_.ammo[size_t(ammo)]) return;
  w_.set_mobj_state(mo_, S::kPlayAtk2);
  use_ammo(1);
  w_.set_psprite(player_, kPsFlash, offset(in_hand().flash, int(psp_.state) - int(S::kChain1)));
  bullet_slope();
  gun_shot(!player_.refire);
}

// A_FirePlasma: one of its two flashes at random.
void WeaponActions::fire_plasma() {
  use_ammo(1);
  w_.set_psprite(player_, kPsFlash, offset(in_hand().flash, w_.random_.play() & 1));
  w_.spawn_player_missile(mo_, ThingType::kPlasma);
}

}  // namespace

void World::act_weapon(Player& player, Psprite& psp, Action action) { WeaponActions(*this, player, psp).run(action); }

// Doom's P_SetPsprite: enter the state, run its action, and go on through states of
// no tics; kNull takes the sprite away.
void World::set_psprite(Player& player, int layer, StateId state) {
  Psprite& psp = player.psprites[size_t(layer)];
  do {
    if (state == S::kNull) {
      psp.state = S::kNull;
      break;
    }
    const StateInfo& info = state_info(state);
    psp.state = state;
    psp.tics = info.tics;
    if (info.misc1) {  // a state that places the sprite
      psp.sx = to_fixed(info.misc1);
      psp.sy = to_fixed(info.misc2);
    }
    if (info.action != Action::kNone) {
      act_weapon(player, psp, info.action);
      if (psp.state == S::kNull) break;
    }
    state = state_info(psp.state).next;
  } while (!psp.tics);
}

// Doom's P_BringUpWeapon: the pending weapon (else the one in hand) starts up from
// below the screen.
void World::bring_up_weapon(Player& player) {
  Inventory& inv = player.inv;
  if (inv.pending == Weapon::kCount) inv.pending = inv.ready;
  if (inv.pending == Weapon::kChainsaw) start_sound(player.mo, Sound::kSawup);
  const StateId up = states_of(inv.pending).up;
  inv.pending = Weapon::kCount;
  player.psprites[kPsWeapon].sy = kWeaponBottom;
  set_psprite(player, kPsWeapon, up);
}

// Doom's P_CheckAmmo: enough for a shot, or the best weapon with ammo becomes
// pending and the empty one starts down.
bool World::check_ammo(Player& player) {
  Inventory& inv = player.inv;
  const AmmoType ammo = ammo_of(inv.ready);
  const int count = inv.ready == Weapon::kBfg ? kBfgCellsPerShot : inv.ready == Weapon::kSuperShotgun ? 2 : 1;
  if (ammo == AmmoType::kNone || inv.ammo[size_t(ammo)] >= count) return true;
  inv.pending = weapon_with_ammo(inv, options_.commercial);
  set_psprite(player, kPsWeapon, states_of(inv.ready).down);
  return false;
}

// Doom's P_FireWeapon: the attack frames, and every monster that hears it wakes.
void World::fire_weapon(Player& player) {
  if (!check_ammo(player)) return;
  set_mobj_state(player.mo, S::kPlayAtk1);
  set_psprite(player, kPsWeapon, states_of(player.inv.ready).attack);
  noise_alert(player.mo, player.mo);
}

// Doom's P_DropWeapon: the dead player's weapon goes down.
void World::drop_weapon(Player& player) { set_psprite(player, kPsWeapon, states_of(player.inv.ready).down); }

// Doom's P_SetupPsprites: at the level's start, the weapon in hand comes up.
void World::setup_psprites(Player& player) {
  for (Psprite& psp : player.psprites) psp.state = S::kNull;
  player.inv.pending = player.inv.ready;
  bring_up_weapon(player);
}

// Doom's P_MovePsprites: each sprite's tics run down to its next state; the flash
// goes where the weapon is.
void World::move_psprites(Player& player) {
  for (int layer = 0; layer < kPsCount; ++layer) {
    Psprite& psp = player.psprites[size_t(layer)];
    if (psp.state == S::kNull || psp.tics == kInfiniteTics) continue;
    if (!--psp.tics) set_psprite(player, layer, state_info(psp.state).next);
  }
  Psprite& flash = player.psprites[kPsFlash];
  const Psprite& weapon = player.psprites[kPsWeapon];
  flash.sx = weapon.sx;
  flash.sy = weapon.sy;
}

// Doom's A_BFGSpray: forty lines fanned over a quarter turn from the ball's flight,
// aimed from its shooter; each that finds a target hurts it by 15 rolls of 1..8.
void World::bfg_spray(Mobj* mo) {
  for (int i = 0; i < 40; ++i) {
    const Angle angle = mo->angle - kAngle90 / 2 + kAngle90 / 40 * Angle(i);
    aim_line_attack(mo->target, angle, kAimRange);
    if (!line_target_) continue;
    spawn_mobj(line_target_->x, line_target_->y, wrap_add(line_target_->z, line_target_->height >> 2), ThingType::kExtrabfg);
    int damage = 0;
    for (int j = 0; j < 15; ++j) damage += (random_.play() & 7) + 1;
    damage_mobj(line_target_, mo->target, mo->target, damage);
  }
}

}  // namespace p3d::play
