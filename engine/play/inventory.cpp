#include "engine/play/inventory.h"

#include <algorithm>

namespace p3d::play {

namespace {

constexpr std::array<int, 4> kClipAmmo = {10, 4, 20, 1};
constexpr int kInvulnerableTics = 30 * 35, kInvisibleTics = 60 * 35, kInfraredTics = 120 * 35, kIronFeetTics = 60 * 35;

// P_GiveAmmo: `clips` clips' worth (0: half a clip, as dropped clips give), none when
// full; an empty weapon in hand may give way to a better one that uses this ammo.
bool give_ammo(Inventory& inv, AmmoType ammo, int clips, int skill) {
  if (ammo == AmmoType::kNone) return false;
  const size_t a = size_t(ammo);
  if (inv.ammo[a] == inv.max_ammo[a]) return false;
  int n = clips ? clips * kClipAmmo[a] : kClipAmmo[a] / 2;
  if (skill == 1 || skill == 5) n <<= 1;  // Doom's trainer and nightmare skills
  const int before = inv.ammo[a];
  inv.ammo[a] = std::min(inv.ammo[a] + n, inv.max_ammo[a]);
  if (before) return true;
  auto owned = [&](Weapon w) { return inv.weapons[size_t(w)]; };
  const Weapon r = inv.ready;
  switch (ammo) {  // Doom's fixed preferences
    case AmmoType::kClip:
      if (r == Weapon::kFist) inv.ready = owned(Weapon::kChaingun) ? Weapon::kChaingun : Weapon::kPistol;
      break;
    case AmmoType::kShell:
      if ((r == Weapon::kFist || r == Weapon::kPistol) && owned(Weapon::kShotgun)) inv.ready = Weapon::kShotgun;
      break;
    case AmmoType::kCell:
      if ((r == Weapon::kFist || r == Weapon::kPistol) && owned(Weapon::kPlasma)) inv.ready = Weapon::kPlasma;
      break;
    case AmmoType::kMissile:
      if (r == Weapon::kFist && owned(Weapon::kMissile)) inv.ready = Weapon::kMissile;
      break;
    default:
      break;
  }
  return true;
}

// P_GiveWeapon in a single-player game: its ammo (two clips, one if dropped), and the
// weapon taken in hand if new.
bool give_weapon(Inventory& inv, Weapon weapon, bool dropped, int skill) {
  const bool ammo = give_ammo(inv, ammo_of(weapon), dropped ? 1 : 2, skill);
  if (inv.weapons[size_t(weapon)]) return ammo;
  inv.weapons[size_t(weapon)] = true;
  inv.ready = weapon;  // Doom lowers the old one and raises this one; weapons do not act yet
  return true;
}

bool give_body(Inventory& inv, int n) {
  if (inv.health >= kMaxHealth) return false;
  inv.health = std::min(inv.health + n, kMaxHealth);
  return true;
}

bool give_armor(Inventory& inv, int type) {
  if (inv.armor >= type * 100) return false;
  inv.armor_type = type;
  inv.armor = type * 100;
  return true;
}

bool give_power(Inventory& inv, Power p) {
  int& left = inv.powers[size_t(p)];
  switch (p) {
    case Power::kInvulnerability: left = kInvulnerableTics; return true;
    case Power::kInvisibility: left = kInvisibleTics; return true;
    case Power::kInfrared: left = kInfraredTics; return true;
    case Power::kIronFeet: left = kIronFeetTics; return true;
    case Power::kStrength:
      give_body(inv, 100);
      left = 1;
      return true;
    default:
      if (left) return false;
      left = 1;
      return true;
  }
}

std::string key_pickup(uint8_t& keys, int bit, const char* message) {
  const bool had = keys & (1 << bit);
  keys |= uint8_t(1 << bit);
  return had ? "" : message;
}

}  // namespace

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
  if (skill == 1) amount >>= 1;  // Doom's trainer skill takes half
  if (inv.powers[size_t(Power::kInvulnerability)]) return 0;
  if (inv.armor_type) {
    int saved = inv.armor_type == 1 ? amount / 3 : amount / 2;
    if (inv.armor <= saved) {  // the armor is used up
      saved = inv.armor;
      inv.armor_type = 0;
    }
    inv.armor -= saved;
    amount -= saved;
  }
  const int before = inv.health;
  inv.health = std::max(inv.health - amount, 0);
  inv.damage_count = std::min(inv.damage_count + amount, 100);
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

Pickup touch(Inventory& inv, uint8_t& keys, ThingType type, bool dropped, int skill, bool commercial) {
  Pickup p;
  std::string& m = p.message;
  const Sprite sprite = state_info(thing_info(type).spawn).sprite;
  auto weapon = [&](Weapon w, bool drop, const char* message) {
    if (!give_weapon(inv, w, drop, skill)) return false;
    m = message;
    p.sound = Sound::kWpnup;
    return true;
  };
  auto ammo = [&](AmmoType a, int clips, const char* message) {
    if (!give_ammo(inv, a, clips, skill)) return false;
    m = message;
    return true;
  };
  auto power = [&](Power w, const char* message) {
    if (!give_power(inv, w)) return false;
    m = message;
    p.sound = Sound::kGetpow;
    return true;
  };
  bool taken = true;
  switch (sprite) {
    case Sprite::kArm1: taken = give_armor(inv, 1), m = "Picked up the armor."; break;
    case Sprite::kArm2: taken = give_armor(inv, 2), m = "Picked up the MegaArmor!"; break;
    case Sprite::kBon1:
      inv.health = std::min(inv.health + 1, kMaxBonusHealth);
      m = "Picked up a health bonus.";
      break;
    case Sprite::kBon2:
      inv.armor = std::min(inv.armor + 1, 200);
      if (!inv.armor_type) inv.armor_type = 1;
      m = "Picked up an armor bonus.";
      break;
    case Sprite::kSoul:
      inv.health = std::min(inv.health + 100, kMaxBonusHealth);
      m = "Supercharge!";
      p.sound = Sound::kGetpow;
      break;
    case Sprite::kMega:
      if (!commercial) return p;
      inv.health = 200;
      give_armor(inv, 2);
      m = "MegaSphere!";
      p.sound = Sound::kGetpow;
      break;
    case Sprite::kBkey: m = key_pickup(keys, 0, "Picked up a blue keycard."); break;
    case Sprite::kYkey: m = key_pickup(keys, 1, "Picked up a yellow keycard."); break;
    case Sprite::kRkey: m = key_pickup(keys, 2, "Picked up a red keycard."); break;
    case Sprite::kBsku: m = key_pickup(keys, 3, "Picked up a blue skull key."); break;
    case Sprite::kYsku: m = key_pickup(keys, 4, "Picked up a yellow skull key."); break;
    case Sprite::kRsku: m = key_pickup(keys, 5, "Picked up a red skull key."); break;
    case Sprite::kStim: taken = give_body(inv, 10), m = "Picked up a stimpack."; break;
    case Sprite::kMedi:
      taken = give_body(inv, 25);
      m = inv.health < 25 ? "Picked up a medikit that you REALLY need!" : "Picked up a medikit.";
      break;
    case Sprite::kPinv: taken = power(Power::kInvulnerability, "Invulnerability!"); break;
    case Sprite::kPstr:
      taken = power(Power::kStrength, "Berserk!");
      if (taken) inv.ready = Weapon::kFist;
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
      for (int a = 0; a < 4; ++a) give_ammo(inv, AmmoType(a), 1, skill);
      m = "Picked up a backpack full of ammo!";
      break;
    case Sprite::kBfug: taken = weapon(Weapon::kBfg, false, "You got the BFG9000!  Oh, yes."); break;
    case Sprite::kMgun: taken = weapon(Weapon::kChaingun, dropped, "You got the chaingun!"); break;
    case Sprite::kCsaw: taken = weapon(Weapon::kChainsaw, false, "A chainsaw!  Find some meat!"); break;
    case Sprite::kLaun: taken = weapon(Weapon::kMissile, false, "You got the rocket launcher!"); break;
    case Sprite::kPlas: taken = weapon(Weapon::kPlasma, false, "You got the plasma gun!"); break;
    case Sprite::kShot: taken = weapon(Weapon::kShotgun, dropped, "You got the shotgun!"); break;
    case Sprite::kSgn2: taken = weapon(Weapon::kSuperShotgun, dropped, "You got the super shotgun!"); break;
    default: return p;  // not a thing Doom lets the player pick up
  }
  if (!taken) return {};
  p.taken = true;
  if (thing_info(type).flags & kCountitem) ++inv.items;
  inv.bonus_count += kBonusAdd;
  return p;
}

}  // namespace p3d::play
