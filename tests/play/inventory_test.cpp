// Doom's pickup rules (p_inter.c): what each thing gives, when it is left lying, the
// ammo doubled at skill 1 and 5, the weapon made pending, the messages and sounds, the
// items counted for the tally and the gold flash; and armor's share of damage.
#include <gtest/gtest.h>

#include <utility>

#include "engine/play/inventory.h"

namespace p3d::play {
namespace {

Pickup take(Inventory& inv, int editor_number, int skill = 3, bool dropped = false) {
  uint8_t keys = 0;
  return touch(inv, keys, thing_type_for_editor_number(editor_number), dropped, skill);
}

TEST(Inventory, HealthAndArmorFollowDoomsCaps) {
  Inventory inv;
  EXPECT_FALSE(take(inv, 2011).taken) << "a stimpack stays at full health";
  inv.health = 50;
  EXPECT_EQ(take(inv, 2012).message, "Picked up a medikit.");
  EXPECT_EQ(inv.health, 75);
  for (int i = 0; i < 200; ++i) take(inv, 2014);  // health bonuses
  EXPECT_EQ(inv.health, 200) << "bonuses go past 100, up to 200";
  inv.health = 150;
  const Pickup soul = take(inv, 2013);
  EXPECT_EQ(inv.health, 200);
  EXPECT_EQ(soul.sound, Sound::kGetpow);
  EXPECT_EQ(soul.message, "Supercharge!");
  EXPECT_TRUE(take(inv, 2018).taken);
  EXPECT_EQ(inv.armor, 100);
  EXPECT_EQ(inv.armor_type, 1);
  EXPECT_FALSE(take(inv, 2018).taken) << "green armor is not taken over 100";
  EXPECT_TRUE(take(inv, 2019).taken);
  EXPECT_EQ(inv.armor, 200);
  EXPECT_EQ(inv.armor_type, 2);
  Inventory bare;
  take(bare, 2015);  // an armor bonus
  EXPECT_EQ(bare.armor, 1);
  EXPECT_EQ(bare.armor_type, 1);
}

TEST(Inventory, AmmoByClipsDoubledAtTheEasiestAndHardestSkills) {
  Inventory inv;
  EXPECT_EQ(take(inv, 2007).message, "Picked up a clip.");
  EXPECT_EQ(inv.ammo[0], 60);
  take(inv, 2007, 3, true);
  EXPECT_EQ(inv.ammo[0], 65) << "a dropped clip gives half";
  take(inv, 2007, 1);
  EXPECT_EQ(inv.ammo[0], 85) << "skill 1 doubles";
  take(inv, 2008, 5);
  EXPECT_EQ(inv.ammo[1], 8);
  inv.ammo[0] = 200;
  EXPECT_FALSE(take(inv, 2048).taken) << "a box of bullets stays when full";
  EXPECT_TRUE(take(inv, 8).taken);
  EXPECT_EQ(inv.max_ammo, (std::array<int, 4>{400, 100, 600, 100})) << "the backpack doubles the maximums";
  EXPECT_EQ(inv.ammo[0], 210);
  EXPECT_EQ(inv.ammo[2], 20);
  take(inv, 8);
  EXPECT_EQ(inv.max_ammo[0], 400) << "once";
}

TEST(Inventory, NewWeaponsComeWithAmmoAndArePending) {
  Inventory inv;
  const Pickup shotgun = take(inv, 2001);
  EXPECT_EQ(shotgun.sound, Sound::kWpnup);
  EXPECT_EQ(shotgun.message, "You got the shotgun!");
  EXPECT_TRUE(inv.weapons[size_t(Weapon::kShotgun)]);
  EXPECT_EQ(inv.pending, Weapon::kShotgun) << "the new weapon comes up once the old one is down";
  EXPECT_EQ(inv.ready, Weapon::kPistol) << "the pistol stays in hand until the weapon sprite lowers it";
  EXPECT_EQ(inv.ammo[1], 8) << "two clips' worth of shells";
  inv.ready = std::exchange(inv.pending, Weapon::kCount);
  EXPECT_TRUE(take(inv, 2001).taken) << "again: for its shells";
  EXPECT_EQ(inv.ammo[1], 16);
  EXPECT_EQ(inv.pending, Weapon::kCount) << "a weapon already held changes nothing";
  EXPECT_TRUE(take(inv, 2005).taken);
  EXPECT_EQ(inv.pending, Weapon::kChainsaw);
  EXPECT_FALSE(take(inv, 2005).taken) << "a second chainsaw has nothing to give";
  inv.ready = Weapon::kChainsaw;
  EXPECT_EQ(inv.status(0, 0).ready_ammo, kNoAmmoShown) << "the chainsaw uses no ammo";
  EXPECT_TRUE(inv.status(0, 0).arms[1]);
  Inventory dropped;
  take(dropped, 2002, 3, true);  // a chaingun a chaingunner dropped
  EXPECT_EQ(dropped.ammo[0], 50 + 10) << "one clip with a dropped weapon";
}

TEST(Inventory, AmmoAfterNoneRaisesDoomsPreferredWeapon) {
  // Out of bullets with the fist in hand: a clip brings the pistol back.
  Inventory empty;
  empty.ammo[0] = 0;
  empty.ready = Weapon::kFist;
  take(empty, 2007);
  EXPECT_EQ(empty.pending, Weapon::kPistol);
  EXPECT_EQ(empty.ready, Weapon::kFist);
  // ... or the chaingun, if the player has one.
  Inventory chaingun;
  chaingun.ammo[0] = 0;
  chaingun.ready = Weapon::kFist;
  chaingun.weapons[size_t(Weapon::kChaingun)] = true;
  take(chaingun, 2007);
  EXPECT_EQ(chaingun.pending, Weapon::kChaingun);
  // Shells after none: the shotgun over the pistol, not over a better choice.
  Inventory shells;
  shells.weapons[size_t(Weapon::kShotgun)] = true;
  take(shells, 2008);
  EXPECT_EQ(shells.pending, Weapon::kShotgun);
  Inventory chosen;
  chosen.weapons[size_t(Weapon::kShotgun)] = true;
  chosen.ready = Weapon::kChaingun;
  take(chosen, 2008);
  EXPECT_EQ(chosen.pending, Weapon::kCount) << "the player chose the chaingun on purpose";
  Inventory some;
  some.ammo[1] = 1;
  some.weapons[size_t(Weapon::kShotgun)] = true;
  take(some, 2008);
  EXPECT_EQ(some.pending, Weapon::kCount) << "only ammo after none changes weapons";
  // Rockets only over the fist.
  Inventory rockets;
  rockets.weapons[size_t(Weapon::kMissile)] = true;
  take(rockets, 2010);
  EXPECT_EQ(rockets.pending, Weapon::kCount);
  rockets.ammo[3] = 0;
  rockets.ready = Weapon::kFist;
  take(rockets, 2010);
  EXPECT_EQ(rockets.pending, Weapon::kMissile);
}

TEST(Inventory, BerserkHealsAndPutsUpTheFists) {
  Inventory inv;
  inv.health = 30;
  const Pickup berserk = take(inv, 2023);
  EXPECT_EQ(berserk.message, "Berserk!");
  EXPECT_EQ(berserk.sound, Sound::kGetpow);
  EXPECT_EQ(inv.health, 100);
  EXPECT_EQ(inv.pending, Weapon::kFist);
  Inventory fists;
  fists.ready = Weapon::kFist;
  take(fists, 2023);
  EXPECT_EQ(fists.pending, Weapon::kCount) << "the fists already in hand";
}

TEST(Inventory, MegasphereOnlyInDoomII) {
  Inventory inv;
  uint8_t keys = 0;
  const ThingType mega = thing_type_for_editor_number(83);
  EXPECT_FALSE(touch(inv, keys, mega, false, 3, false).taken);
  EXPECT_TRUE(touch(inv, keys, mega, false, 3, true).taken);
  EXPECT_EQ(inv.health, 200);
  EXPECT_EQ(inv.armor, 200);
  EXPECT_EQ(inv.armor_type, 2);
}

TEST(Inventory, ArmorTakesItsShareOfDamage) {
  Inventory inv;
  inv.armor = 100;
  inv.armor_type = 1;
  EXPECT_EQ(absorb_damage(inv, 30), 20) << "green armor: a third";
  EXPECT_EQ(inv.armor, 90);
  EXPECT_EQ(inv.health, 80);
  inv.armor_type = 2;
  EXPECT_EQ(absorb_damage(inv, 31), 16) << "blue armor: half, rounded down";
  EXPECT_EQ(inv.armor, 75);
  inv.armor = 5;
  EXPECT_EQ(absorb_damage(inv, 40), 35) << "the last points of armor";
  EXPECT_EQ(inv.armor, 0);
  EXPECT_EQ(inv.armor_type, 0);
  EXPECT_EQ(absorb_damage(inv, 10000), 10000);
  EXPECT_EQ(inv.health, 0);
  EXPECT_EQ(inv.damage_count, 100);
  Inventory trainer;
  EXPECT_EQ(damage(trainer, 21, 1), 10) << "skill 1 halves";
  trainer.powers[size_t(Power::kInvulnerability)] = 10;
  EXPECT_EQ(damage(trainer, 999, 3), 0);
  EXPECT_EQ(damage(trainer, 1000, 3), 90) << "a telefrag gets through";
}

TEST(Inventory, KeysPowersItemsAndTheFlash) {
  Inventory inv;
  uint8_t keys = 0;
  EXPECT_EQ(touch(inv, keys, thing_type_for_editor_number(5), false, 3).message, "Picked up a blue keycard.");
  EXPECT_EQ(keys, 1);
  EXPECT_EQ(inv.bonus_count, 2 * kBonusAdd) << "a new key's flash is set, then the pickup's added";
  const Pickup again = touch(inv, keys, thing_type_for_editor_number(5), false, 3);
  EXPECT_TRUE(again.taken);
  EXPECT_EQ(again.message, "") << "a key already held says nothing";
  EXPECT_EQ(inv.bonus_count, 3 * kBonusAdd);
  EXPECT_EQ(take(inv, 2025).message, "Radiation Shielding Suit");
  EXPECT_EQ(inv.powers[size_t(Power::kIronFeet)], 60 * 35);
  const int items = inv.items;
  take(inv, 2014);
  EXPECT_EQ(inv.items, items + 1) << "a health bonus counts for the tally";
  inv.bonus_count = 0;
  take(inv, 2014);
  EXPECT_EQ(inv.bonus_count, kBonusAdd);
  for (int t = 0; t < 10; ++t) inv.tic();
  EXPECT_EQ(inv.bonus_count, 0);
  EXPECT_EQ(inv.powers[size_t(Power::kIronFeet)], 60 * 35 - 10);
  EXPECT_FALSE(take(inv, 2028).taken) << "a floor lamp is no pickup";
}

TEST(Inventory, PaletteFlashesAsDoomsStatusBarPicksThem) {
  Inventory inv;
  EXPECT_EQ(flash_palette(inv), 0);
  inv.bonus_count = kBonusAdd;
  EXPECT_EQ(flash_palette(inv), 9 + 1) << "a fresh pickup: the second gold";
  inv.bonus_count = 40;
  EXPECT_EQ(flash_palette(inv), 12) << "the golds stop at the fourth";
  inv.bonus_count = 0;
  inv.powers[size_t(Power::kIronFeet)] = 60 * 35;
  EXPECT_EQ(flash_palette(inv), 13) << "the radiation suit's green";
  inv.powers[size_t(Power::kIronFeet)] = 100;
  EXPECT_EQ(flash_palette(inv), 0) << "running out: it blinks";
  inv.powers[size_t(Power::kIronFeet)] = 104;
  EXPECT_EQ(flash_palette(inv), 13);
  inv.bonus_count = 3;
  EXPECT_EQ(flash_palette(inv), 9 + 1) << "gold before green";
  inv.damage_count = 20;
  EXPECT_EQ(flash_palette(inv), 1 + 3) << "red before gold: damage 20";
  inv.damage_count = 0;
  Inventory berserk;
  take(berserk, 2023);
  EXPECT_EQ(flash_palette(berserk), 1 + 2) << "berserk's red, fading over 12 x 64 tics";
  for (int t = 0; t < 12 * 64; ++t) berserk.tic();
  EXPECT_EQ(flash_palette(berserk), 0);
}

}  // namespace
}  // namespace p3d::play
