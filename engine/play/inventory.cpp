#include "engine/play/inventory.h"

#include <algorithm>

namespace p3d::play {

namespace {

constexpr std::array<int, 4> kClipAmmo = {10, 4, 20, 1};  // a clip's worth of each ammo
constexpr int kInvulnerableTics = 30 * 35, kInvisibleTics = 60 * 35, kInfraredTics = 120 * 35, kIronFeetTics = 60 * 35;
constexpr int kMaxArmor = 200;

bool owns(const Inventory& inv, Weapon weapon) { return inv.weapons[size_t(weapon)]; }

// The weapon P_GiveAmmo raises when ammo comes after none: Doom's fixed preferences,
// only over the fist or pistol (the player chose anything else on purpose).
Weapon preferred_for(const Inventory& inv, AmmoType ammo) {
  const Weapon r = inv.ready;
  const bool bare = r == Weapon::kFist, light = r == Weapon::kFist || r == Weapon::kPistol;
  switch (ammo) {
    case AmmoType::kClip:
      if (bare) return owns(inv, Weapon::kChaingun) ? Weapon::kChaingun : Weapon::kPistol;
      break;
    case AmmoType::kShell:
      if (light && owns(inv, Weapon::kShotgun)) return Weapon::kShotgun;
      break;
    case AmmoType::kCell:
      if (light && owns(inv, Weapon::kPlasma)) return Weapon::kPlasma;
      break;
    case AmmoType::kMissile:
      if (bare && owns(inv, Weapon::kMissile)) return Weapon::kMissile;
      break;
    default:
      break;
  }
  return inv.pending;
}

// A key's bit and its message.
struct Key {
  int card;
  const char* message;
};

}  // namespace

bool give_ammo(Inventory& inv, AmmoType ammo, int clips, int skill) {
  if (ammo == AmmoType::kNone) return false;
  const size_t a = size_t(ammo);
  if (inv.ammo[a] == inv.max_ammo[a]) return false;
  int n = clips ? clips * kClipAmmo[a] : kClipAmmo[a] / 2;
  if (skill == 1 || skill == 5) n <<= 1;  // Doom's trainer and nightmare skills
  const int before = inv.ammo[a];
  inv.ammo[a] = std::min(inv.ammo[a] + n, inv.max_ammo[a]);
  if (!before) inv.pending = preferred_for(inv, ammo);
  return true;
}

bool give_weapon(Inventory& inv, Weapon weapon, bool dropped, int skill) {
  const bool gave_ammo = give_ammo(inv, ammo_of(weapon), dropped ? 1 : 2, skill);
  if (owns(inv, weapon)) return gave_ammo;
  inv.weapons[size_t(weapon)] = true;
  inv.pending = weapon;
  return true;
}

bool give_body(Inventory& inv, int amount) {
  if (inv.health >= kMaxHealth) return false;
  inv.health = std::min(inv.health + amount, kMaxHealth);
  return true;
}

bool give_armor(Inventory& inv, int type) {
  if (inv.armor >= type * 100) return false;
  inv.armor_type = type;
  inv.armor = type * 100;
  return true;
}

void give_card(Inventory& inv, uint8_t& keys, int card) {
  if (keys & (1 << card)) return;
  inv.bonus_count = kBonusAdd;  // set, not added: the pickup adds its own on top
  keys |= uint8_t(1 << card);
}

bool give_power(Inventory& inv, Power power) {
  int& left = inv.powers[size_t(power)];
  switch (power) {
    case Power::kInvulnerability: left = kInvulnerableTics; return true;
    case Power::kInvisibility: left = kInvisibleTics; return true;
    case Power::kInfrared: left = kInfraredTics; return true;
    case Power::kIronFeet: left = kIronFeetTics; return true;
    case Power::kStrength:
      give_body(inv, 100);
      left = 1;
      return true;
    default:
      if (left) return false;  // the map, once
      left = 1;
      return true;
  }
}

int absorb_damage(Inventory& inv, int damage) {
  if (inv.armor_type) {
    int saved = inv.armor_type == 1 ? damage / 3 : damage / 2;
    if (inv.armor <= saved) {  // the armor is used up
      saved = inv.armor;
      inv.armor_type = 0;
    }
    inv.armor -= saved;
    damage -= saved;
  }
  inv.health = std::max(inv.health - damage, 0);
  inv.damage_count = std::min(inv.damage_count + damage, 100);  // a telefrag's 10000 stops at 100
  return damage;
}

AmmoType ammo_of(Weapon weapon) {
  switch (weapon) {
    case Weapon::kPistol: case Weapon::kChaingun: return AmmoType::kClip;
    case Weapon::kShotgun: case Weapon::kSuperShotgun: return AmmoType::kShell;
    case Weapon::kMissile: return AmmoType::kMissile;
    case Weapon::kPlasma: case Weapon::kBfg: return AmmoType::kCell;
    default: return AmmoType::kNone;
  }
}

int damage(Inventory& inv, int amount, int skill) {
  amount = damage_at_skill(amount, skill);
  if (amount < 1000 && inv.powers[size_t(Power::kInvulnerability)]) return 0;
  const int before = inv.health;
  absorb_damage(inv, amount);
  return before - inv.health;
}

void Inventory::tic() {
  if (bonus_count) --bonus_count;
  if (damage_count) --damage_count;
  for (Power p : {Power::kInvulnerability, Power::kInvisibility, Power::kInfrared, Power::kIronFeet})
    if (powers[size_t(p)]) --powers[size_t(p)];
  if (powers[size_t(Power::kStrength)]) ++powers[size_t(Power::kStrength)];  // counts up: the red fades
}

int flash_palette(const Inventory& inv) {
  constexpr int kFirstRed = 1, kReds = 8, kFirstGold = 9, kGolds = 4, kRadiation = 13;
  int red = inv.damage_count;
  if (const int berserk = inv.powers[size_t(Power::kStrength)]) red = std::max(red, 12 - (berserk >> 6));
  if (red > 0) return kFirstRed + std::min((red + 7) >> 3, kReds - 1);
  if (inv.bonus_count) return kFirstGold + std::min((inv.bonus_count + 7) >> 3, kGolds - 1);
  const int suit = inv.powers[size_t(Power::kIronFeet)];
  if (suit > 4 * 32 || (suit & 8)) return kRadiation;
  return 0;
}

StatusValues Inventory::status(uint8_t keys, int face) const {
  StatusValues v;
  v.health = health;
  v.armor = armor;
  const AmmoType in_hand = ammo_of(ready);
  v.ready_ammo = in_hand == AmmoType::kNone ? kNoAmmoShown : ammo[size_t(in_hand)];
  v.ammo = ammo;
  v.max_ammo = max_ammo;
  for (int i = 0; i < 6; ++i) v.arms[size_t(i)] = weapons[size_t(i + 1)];
  v.arms[1] = v.arms[1] || weapons[size_t(Weapon::kSuperShotgun)];  // slot 3 lights for either shotgun
  v.keys = keys;
  v.face = face;
  return v;
}

Pickup touch(Inventory& inv, uint8_t& keys, Sprite sprite, bool dropped, bool counted, int skill, bool commercial,
             NetRules net) {
  Pickup p;
  std::string& m = p.message;
  // Each returns whether the thing is taken, its message said.
  auto armor = [&](int type, const char* message) { return give_armor(inv, type) && (m = message, true); };
  auto body = [&](int amount, const char* message) { return give_body(inv, amount) && (m = message, true); };
  auto ammo = [&](AmmoType a, int clips, const char* message) {
    return give_ammo(inv, a, clips, skill) && (m = message, true);
  };
  auto power = [&](Power w, const char* message) {
    if (!give_power(inv, w)) return false;
    m = message;
    p.sound = Sound::kGetpow;
    return true;
  };
  auto weapon = [&](Weapon w, bool drop, const char* message) {
    if (net.netgame && net.deathmatch != 2 && !drop) {  // a placed weapon stays for everyone
      if (inv.weapons[size_t(w)]) return false;
      inv.bonus_count += kBonusAdd;
      inv.weapons[size_t(w)] = true;
      give_ammo(inv, ammo_of(w), net.deathmatch ? 5 : 2, skill);
      inv.pending = w;
      p.stays = true;
      p.sound = Sound::kWpnup;
      return false;
    }
    if (!give_weapon(inv, w, drop, skill)) return false;
    m = message;
    p.sound = Sound::kWpnup;
    return true;
  };
  auto key = [&](const Key& k) {  // taken even when held, silently
    if (!(keys & (1 << k.card))) m = k.message;
    give_card(inv, keys, k.card);
    if (net.netgame) {  // left for everyone, silently
      p.stays = true;
      p.sound = Sound::kNone;
    }
    return true;
  };
  bool taken = true;
  switch (sprite) {
    case Sprite::kArm1: taken = armor(1, "Picked up the armor."); break;
    case Sprite::kArm2: taken = armor(2, "Picked up the MegaArmor!"); break;
    case Sprite::kBon1:
      inv.health = std::min(inv.health + 1, kMaxBonusHealth);
      m = "Picked up a health bonus.";
      break;
    case Sprite::kBon2:
      inv.armor = std::min(inv.armor + 1, kMaxArmor);
      if (!inv.armor_type) inv.armor_type = 1;
      m = "Picked up an armor bonus.";
      break;
    case Sprite::kSoul:
      inv.health = std::min(inv.health + 100, kMaxBonusHealth);
      m = "Supercharge!";
      p.sound = Sound::kGetpow;
      break;
    case Sprite::kMega:
      if (!commercial) return {};
      inv.health = 200;
      give_armor(inv, 2);
      m = "MegaSphere!";
      p.sound = Sound::kGetpow;
      break;
    case Sprite::kBkey: taken = key({0, "Picked up a blue keycard."}); break;
    case Sprite::kYkey: taken = key({1, "Picked up a yellow keycard."}); break;
    case Sprite::kRkey: taken = key({2, "Picked up a red keycard."}); break;
    case Sprite::kBsku: taken = key({3, "Picked up a blue skull key."}); break;
    case Sprite::kYsku: taken = key({4, "Picked up a yellow skull key."}); break;
    case Sprite::kRsku: taken = key({5, "Picked up a red skull key."}); break;
    case Sprite::kStim: taken = body(10, "Picked up a stimpack."); break;
    case Sprite::kMedi:
      taken = give_body(inv, 25);
      m = inv.health < 25 ? "Picked up a medikit that you REALLY need!" : "Picked up a medikit.";
      break;
    case Sprite::kPinv: taken = power(Power::kInvulnerability, "Invulnerability!"); break;
    case Sprite::kPstr:
      taken = power(Power::kStrength, "Berserk!");
      if (taken && inv.ready != Weapon::kFist) inv.pending = Weapon::kFist;
      break;
    case Sprite::kPins: taken = power(Power::kInvisibility, "Partial Invisibility"); break;
    case Sprite::kSuit: taken = power(Power::kIronFeet, "Radiation Shielding Suit"); break;
    case Sprite::kPmap: taken = power(Power::kAllMap, "Computer Area Map"); break;
    case Sprite::kPvis: taken = power(Power::kInfrared, "Light Amplification Visor"); break;
    case Sprite::kClip: taken = ammo(AmmoType::kClip, dropped ? 0 : 1, "Picked up a clip."); break;
    case Sprite::kAmmo: taken = ammo(AmmoType::kClip, 5, "Picked up a box of bullets."); break;
    case Sprite::kRock: taken = ammo(AmmoType::kMissile, 1, "Picked up a rocket."); break;
    case Sprite::kBrok: taken = ammo(AmmoType::kMissile, 5, "Picked up a box of rockets."); break;
    case Sprite::kCell: taken = ammo(AmmoType::kCell, 1, "Picked up an energy cell."); break;
    case Sprite::kCelp: taken = ammo(AmmoType::kCell, 5, "Picked up an energy cell pack."); break;
    case Sprite::kShel: taken = ammo(AmmoType::kShell, 1, "Picked up 4 shotgun shells."); break;
    case Sprite::kSbox: taken = ammo(AmmoType::kShell, 5, "Picked up a box of shotgun shells."); break;
    case Sprite::kBpak:
      if (!inv.backpack) {
        for (int& max : inv.max_ammo) max *= 2;
        inv.backpack = true;
      }
      for (int a = 0; a < int(AmmoType::kCount); ++a) give_ammo(inv, AmmoType(a), 1, skill);
      m = "Picked up a backpack full of ammo!";
      break;
    case Sprite::kBfug: taken = weapon(Weapon::kBfg, false, "You got the BFG9000!  Oh, yes."); break;
    case Sprite::kMgun: taken = weapon(Weapon::kChaingun, dropped, "You got the chaingun!"); break;
    case Sprite::kCsaw: taken = weapon(Weapon::kChainsaw, false, "A chainsaw!  Find some meat!"); break;
    case Sprite::kLaun: taken = weapon(Weapon::kMissile, false, "You got the rocket launcher!"); break;
    case Sprite::kPlas: taken = weapon(Weapon::kPlasma, false, "You got the plasma gun!"); break;
    case Sprite::kShot: taken = weapon(Weapon::kShotgun, dropped, "You got the shotgun!"); break;
    case Sprite::kSgn2: taken = weapon(Weapon::kSuperShotgun, dropped, "You got the super shotgun!"); break;
    default: return {};  // not a thing Doom lets the player pick up
  }
  if (p.stays) return p;
  if (!taken) return {};
  p.taken = true;
  if (counted) ++inv.items;
  inv.bonus_count += kBonusAdd;
  return p;
}

Pickup touch(Inventory& inv, uint8_t& keys, ThingType type, bool dropped, int skill, bool commercial, NetRules net) {
  const ThingInfo& info = thing_info(type);
  return touch(inv, keys, state_info(info.spawn).sprite, dropped, (info.flags & kCountitem) != 0, skill, commercial,
               net);
}

}  // namespace p3d::play
