// What the player carries, and Doom's rules for picking things up (P_TouchSpecialThing
// and the P_Give* functions of p_inter.c): health, armor, ammo, weapons, keys and
// powers, with Doom's messages and sounds. Pure rules on a plain record; the
// simulation decides when the player touches a thing.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "engine/play/info.h"
#include "engine/play/status_bar.h"

namespace p3d::play {

enum class Weapon : uint8_t { kFist, kPistol, kShotgun, kChaingun, kMissile, kPlasma, kBfg, kChainsaw, kSuperShotgun, kCount };
enum class AmmoType : uint8_t { kClip, kShell, kCell, kMissile, kCount, kNone = kCount };
enum class Power : uint8_t { kInvulnerability, kStrength, kInvisibility, kIronFeet, kAllMap, kInfrared, kCount };

constexpr int kMaxHealth = 100;       // what medikits and stimpacks fill to
constexpr int kMaxBonusHealth = 200;  // what bonuses and the soulsphere reach
constexpr int kBonusAdd = 6;          // the gold flash each pickup adds (Doom's BONUSADD)

// The ammo a weapon fires.
AmmoType ammo_of(Weapon weapon);

struct Inventory {
  int health = kMaxHealth;
  int armor = 0, armor_type = 0;  // type 1 (green) absorbs a third of the damage, 2 (blue) half
  std::array<int, 4> ammo{50, 0, 0, 0};            // Doom's order: bullets, shells, cells, rockets
  std::array<int, 4> max_ammo{200, 50, 300, 50};
  bool backpack = false;
  std::array<bool, size_t(Weapon::kCount)> weapons{true, true};  // the fist and the pistol
  Weapon ready = Weapon::kPistol;
  std::array<int, size_t(Power::kCount)> powers{};  // tics left (strength: on once taken)
  int bonus_count = 0;   // tics of gold flash left
  int damage_count = 0;  // the red flash: damage taken lately, fading a unit a tic (at most 100)
  int items = 0;        // items counted for the tally

  // One tic: the flash fades and timed powers run down (Doom's P_PlayerThink).
  void tic();
  // What the status bar shows of it (keys and the face come from elsewhere).
  StatusValues status(uint8_t keys, int face) const;
};

struct Pickup {
  bool taken = false;
  Sound sound = Sound::kItemup;
  std::string message;  // Doom's words; empty for nothing to say (a key already held)
};

// Which of PLAYPAL's palettes the screen shows (Doom's ST_doPaletteStuff): red while
// hurt or berserk, gold after a pickup, green while the radiation suit is on (it
// blinks when running out), else 0.
int flash_palette(const Inventory& inventory);

// Doom's P_DamageMobj for the player hurt by the world (no attacker): halved at skill
// 1, nothing while invulnerable, armor taking its share (a third, or half for blue),
// the red flash. Returns the health lost.
int damage(Inventory& inventory, int amount, int skill);

// Doom's rules for touching a thing of this type: what the player gains, or nothing
// (taken false: the thing stays, as a medikit at full health). `keys` holds the six
// key bits (blue, yellow, red card, then skulls). Skill 1 and 5 double the ammo.
// `commercial`: Doom II's rules (the megasphere exists only there).
Pickup touch(Inventory& inventory, uint8_t& keys, ThingType type, bool dropped, int skill, bool commercial = true);

}  // namespace p3d::play
