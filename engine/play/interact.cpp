// Things meeting things (Doom's p_inter.c): the player picking things up, damage
// with its push, pain and anger, and death with its drops. What a pickup gives is
// the inventory's rules (inventory.h); here is what it does to the world.
#include "engine/play/world.h"

namespace p3d::play {

namespace {

using S = StateId;

constexpr int kHellExitSpecial = 11;  // the sector special where the player cannot die (E1M8's end)
constexpr int kGodModeLimit = 1000;   // damage this big hurts even a god (a telefrag)

// What a dead monster drops, or kCount for nothing.
ThingType dropped_by(ThingType type) {
  switch (type) {
    case ThingType::kWolfss:
    case ThingType::kPossessed: return ThingType::kClip;
    case ThingType::kShotguy: return ThingType::kShotgun;
    case ThingType::kChainguy: return ThingType::kChaingun;
    default: return ThingType::kCount;
  }
}

}  // namespace

// Doom's P_TouchSpecialThing: the thing must be within the toucher's height above its
// feet and at most 8 units below them, the toucher alive.
void World::touch_special_thing(Mobj* special, Mobj* toucher) {
  const Fixed delta = wrap_sub(special->z, toucher->z);
  if (delta > toucher->height || delta < -8 * kFracUnit) return;
  if (toucher->health <= 0) return;  // a sliding corpse
  Player* player = toucher->player;
  if (!player) return;  // only players pick up (Doom would crash)
  const bool dropped = special->flags & kDropped, counted = special->flags & kCountitem;
  const Pickup got = touch(player->inv, player->cards, special->sprite, dropped, counted, options_.skill,
                           options_.commercial, NetRules{options_.netgame, int(options_.deathmatch)});
  if (got.stays) {  // a netgame's weapon or key, left for the others
    if (!got.message.empty()) say(*player, got.message);
    if (is_console(*player)) start_sound(nullptr, got.sound);
    return;
  }
  if (!got.taken) return;
  // The player's thing mirrors its health (as P_GiveBody and the spheres set it; the
  // two are equal while the player lives).
  toucher->health = player->inv.health;
  if (special->sprite == Sprite::kPins) toucher->flags |= kShadow;  // P_GivePower's invisibility
  if (!got.message.empty()) say(*player, got.message);
  remove_mobj(special);
  if (is_console(*player)) start_sound(nullptr, got.sound);  // the console player's own: heard from nowhere
}

// Doom's P_KillMobj: the body falls as a corpse, the kill is counted, a dead player's
// weapon goes down, and some monsters drop their guns or clips.
void World::kill_mobj(Mobj* source, Mobj* target) {
  target->flags &= ~(kShootable | kFloat | kSkullfly);
  if (target->type != ThingType::kSkull) target->flags &= ~kNogravity;
  target->flags |= kCorpse | kDropoff;
  target->height >>= 2;
  if (source && source->player) {
    if (target->flags & kCountkill) ++source->player->kill_count;
    if (target->player) ++source->player->frags[size_t(target->player->number)];
  } else if (!options_.netgame && (target->flags & kCountkill)) {
    ++players_[0].kill_count;  // by a monster's hand or the world's: it still counts (Doom's player 1)
  }
  if (Player* player = target->player) {
    if (!source) ++player->frags[size_t(player->number)];  // the world's kill counts against the player
    target->flags &= ~kSolid;
    player->state = PlayerState::kDead;
    drop_weapon(*player);
    // (Doom also leaves the automap here: nothing of play.)
  }
  const ThingInfo& info = *target->info;
  if (target->health < -info.health && info.extreme_death != S::kNull)
    set_mobj_state(target, info.extreme_death);
  else
    set_mobj_state(target, info.death);
  target->tics -= random_.play() & 3;
  if (target->tics < 1) target->tics = 1;
  const ThingType drop = dropped_by(target->type);
  if (drop == ThingType::kCount) return;
  Mobj* mo = spawn_mobj(target->x, target->y, kOnFloorZ, drop);
  mo->flags |= kDropped;
}

// Doom's P_DamageMobj. `inflictor` is what hit (a missile, a monster's fist; nullptr
// for the floor's slime), pushing the target away from it; `source` is who is to
// blame, whom the target turns on (nullptr for slime and barrels).
void World::damage_mobj(Mobj* target, Mobj* inflictor, Mobj* source, int damage) {
  if (!(target->flags & kShootable)) return;
  if (target->health <= 0) return;
  if (target->flags & kSkullfly) target->mom_x = target->mom_y = target->mom_z = 0;  // a lost soul's charge ends
  Player* player = target->player;
  if (player) damage = damage_at_skill(damage, options_.skill);

  // The push, away from the inflictor, except from a chainsaw (it would push its
  // victim out of reach). Doom's int products wrap (a telefrag's 10000).
  if (inflictor && !(target->flags & kNoclip) &&
      (!source || !source->player || source->player->inv.ready != Weapon::kChainsaw)) {
    Angle angle = point_to_angle(inflictor->x, inflictor->y, target->x, target->y);
    Fixed thrust = Fixed(uint32_t(damage) * uint32_t(kFracUnit >> 3) * 100u) / target->info->mass;
    // Killed from well below by a small blow: now and then it falls forwards.
    if (damage < 40 && damage > target->health && wrap_sub(target->z, inflictor->z) > 64 * kFracUnit &&
        (random_.play() & 1)) {
      angle += kAngle180;
      thrust *= 4;
    }
    target->mom_x = wrap_add(target->mom_x, fixed_mul(thrust, cosine(angle)));
    target->mom_y = wrap_add(target->mom_y, fixed_mul(thrust, sine(angle)));
  }

  if (player) {
    if (target->subsector->sector->special == kHellExitSpecial && damage >= target->health) damage = target->health - 1;
    const bool invulnerable = (player->cheats & kCheatGodMode) || player->inv.powers[size_t(Power::kInvulnerability)];
    if (damage < kGodModeLimit && invulnerable) return;
    damage = absorb_damage(player->inv, damage);
    player->attacker = source;
  }

  target->health -= damage;
  if (target->health <= 0) {
    kill_mobj(source, target);
    return;
  }
  if (random_.play() < target->info->pain_chance && !(target->flags & kSkullfly)) {
    target->flags |= kJusthit;  // it fights back
    set_mobj_state(target, target->info->pain);
  }
  target->reaction_time = 0;  // awake now
  // It turns on its attacker, unless busy with another (an Arch-vile always turns),
  // never on itself, and never on an Arch-vile.
  if ((!target->threshold || target->type == ThingType::kVile) && source && source != target &&
      source->type != ThingType::kVile) {
    target->target = source;
    target->threshold = kBaseThreshold;
    if (target->state == target->info->spawn && target->info->see != S::kNull)
      set_mobj_state(target, target->info->see);
  }
}

}  // namespace p3d::play
