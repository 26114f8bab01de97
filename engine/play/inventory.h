// What the player carries, and Doom's rules for picking things up (P_TouchSpecialThing
// and the P_Give* functions of p_inter.c) and for armor taking damage: health, armor,
// ammo, weapons, keys and powers, with Doom's messages and sounds. Pure rules on a
// plain record; the simulation decides when the player touches a thing.
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
  Weapon pending = Weapon::kCount;  // the weapon to raise next; kCount: no change (Doom's wp_nochange)
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
  // Given but left where it lies, for the others (a netgame's placed weapons and keys):
  // the message and sound stand, the thing is not removed nor counted.
  bool stays = false;
  Sound sound = Sound::kItemup;
  std::string message;  // Doom's words; empty for nothing to say (a key already held)
};

// Which of PLAYPAL's palettes the screen shows (Doom's ST_doPaletteStuff): red while
// hurt or berserk, gold after a pickup, green while the radiation suit is on (it
// blinks when running out), else 0.
int flash_palette(const Inventory& inventory);

// ---- Doom's P_Give* (single player): each returns false when there is nothing to
// give, so that the thing stays where it lies.

// P_GiveAmmo: `clips` clips' worth (0: half a clip, as a dropped clip gives), doubled
// at skill 1 and 5, up to the maximum. Ammo after none may make a better weapon pending.
bool give_ammo(Inventory& inventory, AmmoType ammo, int clips, int skill);
// P_GiveWeapon: its ammo (two clips, one if dropped); a new weapon becomes pending.
bool give_weapon(Inventory& inventory, Weapon weapon, bool dropped, int skill);
// P_GiveBody: health up to 100.
bool give_body(Inventory& inventory, int amount);
// P_GiveArmor: type 1 (100 points) or 2 (200), unless the player has as many.
bool give_armor(Inventory& inventory, int type);
// P_GiveCard: `card` is the key's bit (0..5); a new key flashes gold.
void give_card(Inventory& inventory, uint8_t& keys, int card);
// P_GivePower: the timed powers restart; berserk also heals; the others once.
// (Invisibility also makes the player's thing a shadow: the World's part.)
bool give_power(Inventory& inventory, Power power);

// Doom's P_DamageMobj for a player, after the skill's halving and the god and
// invulnerability checks: armor takes its share (a third, or half for blue), health
// falls (not below 0) and the red flash grows (up to 100). Returns the damage left,
// which the player's thing loses too.
int absorb_damage(Inventory& inventory, int damage);
// The damage a player takes at this skill: half at skill 1.
constexpr int damage_at_skill(int damage, int skill) { return skill == 1 ? damage >> 1 : damage; }

// Doom's P_DamageMobj for the player hurt by the world (no attacker): halved at skill
// 1, nothing while invulnerable, then absorb_damage. Returns the health lost.
int damage(Inventory& inventory, int amount, int skill);

// A netgame's pickup rules (Doom's netgame and deathmatch): placed weapons stay unless
// in altdeath (5 clips of ammo in deathmatch, 2 in co-op, nothing if owned), keys stay.
struct NetRules {
  bool netgame = false;
  int deathmatch = 0;  // 0, 1 or 2 (altdeath)
};

// Doom's P_TouchSpecialThing, by the thing's sprite as Doom identifies it: what the
// player gains, or nothing (taken false: the thing stays, as a medikit at full
// health). `keys` holds the six key bits (blue, yellow, red card, then skulls);
// `dropped` is a thing a monster dropped (half a clip; one clip with a weapon);
// `counted` is a thing counted for the tally (Doom's MF_COUNTITEM). A pickup adds
// to the gold flash. `commercial`: Doom II's rules (the megasphere exists only there).
// New weapons, berserk and ammo after none set `pending`: the weapon's sprite lowers
// the old one and raises it (set `ready` yourself where no weapon sprite runs).
Pickup touch(Inventory& inventory, uint8_t& keys, Sprite sprite, bool dropped, bool counted, int skill,
             bool commercial, NetRules net = {});
// The same for a thing of this type, lying where the map put it or dropped.
Pickup touch(Inventory& inventory, uint8_t& keys, ThingType type, bool dropped, int skill, bool commercial = true,
             NetRules net = {});

}  // namespace p3d::play
