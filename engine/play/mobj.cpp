// Things (Doom's p_mobj.c): spawning them where the map places them, their state
// clocks, momentum with Doom's friction, gravity and floating, missiles and their
// explosions, puffs and blood, and removal.
#include <cstdlib>

#include "engine/play/world.h"

namespace p3d::play {

namespace {
constexpr Fixed kStopSpeed = 0x1000;
constexpr Fixed kFriction = 0xe800;
}  // namespace

// Enters `state`, running its action, and on through states of no tics; false when the
// chain ends in kNull and the thing is removed.
bool World::set_mobj_state(Mobj* mo, StateId state) {
  do {
    if (state == StateId::kNull) {
      mo->state = StateId::kNull;
      remove_mobj(mo);
      return false;
    }
    const StateInfo& st = state_of(state);
    mo->state = state;
    mo->tics = st.tics;
    mo->sprite = st.sprite;
    mo->frame = st.frame | (st.bright ? kFullBright : 0);
    if (st.action != Action::kNone) act(mo, st.action);
    state = st.next;
  } while (!mo->tics);
  return true;
}

void World::explode_missile(Mobj* mo) {
  mo->mom_x = mo->mom_y = mo->mom_z = 0;
  set_mobj_state(mo, mo->info->death);
  mo->tics -= random_.play() & 3;
  if (mo->tics < 1) mo->tics = 1;
  mo->flags &= ~kMissile;
  if (mo->info->death_sound != Sound::kNone) start_sound(mo, mo->info->death_sound);
}

void World::xy_movement(Mobj* mo) {
  if (!mo->mom_x && !mo->mom_y) {
    if (mo->flags & kSkullfly) {  // a lost soul's charge ends
      mo->flags &= ~kSkullfly;
      mo->mom_x = mo->mom_y = mo->mom_z = 0;
      set_mobj_state(mo, mo->info->spawn);
    }
    return;
  }
  Player* player = mo->player;
  mo->mom_x = std::clamp(mo->mom_x, -kMaxMove, kMaxMove);
  mo->mom_y = std::clamp(mo->mom_y, -kMaxMove, kMaxMove);
  Fixed xmove = mo->mom_x, ymove = mo->mom_y;
  do {
    // Fast moves go in halves, so that nothing steps through a thin wall.
    Fixed try_x, try_y;
    if (xmove > kMaxMove / 2 || ymove > kMaxMove / 2) {
      try_x = wrap_add(mo->x, xmove / 2);
      try_y = wrap_add(mo->y, ymove / 2);
      xmove >>= 1;
      ymove >>= 1;
    } else {
      try_x = wrap_add(mo->x, xmove);
      try_y = wrap_add(mo->y, ymove);
      xmove = ymove = 0;
    }
    if (!try_move(mo, try_x, try_y)) {
      if (mo->player) {
        slide_move(mo);
      } else if (mo->flags & kMissile) {
        // A missile into the sky vanishes.
        if (tm_.ceiling_line && tm_.ceiling_line->back && tm_.ceiling_line->back->ceiling_pic == level::kSky) {
          remove_mobj(mo);
          return;
        }
        explode_missile(mo);
      } else {
        mo->mom_x = mo->mom_y = 0;
      }
    }
  } while (xmove || ymove);

  if (mo->flags & (kMissile | kSkullfly)) return;  // no friction for missiles
  if (mo->z > mo->floor_z) return;                 // nor in the air
  if (mo->flags & kCorpse) {  // a corpse sliding off a step keeps sliding
    if (mo->mom_x > kFracUnit / 4 || mo->mom_x < -kFracUnit / 4 || mo->mom_y > kFracUnit / 4 ||
        mo->mom_y < -kFracUnit / 4)
      if (mo->floor_z != mo->subsector->sector->floor_height) return;
  }
  if (mo->mom_x > -kStopSpeed && mo->mom_x < kStopSpeed && mo->mom_y > -kStopSpeed && mo->mom_y < kStopSpeed &&
      (!player || (player->cmd.forward == 0 && player->cmd.side == 0))) {
    // Stopped: a running player stands.
    if (player && unsigned(int(player->mo->state) - int(StateId::kPlayRun1)) < 4)
      set_mobj_state(player->mo, StateId::kPlay);
    mo->mom_x = mo->mom_y = 0;
  } else {
    mo->mom_x = fixed_mul(mo->mom_x, kFriction);
    mo->mom_y = fixed_mul(mo->mom_y, kFriction);
  }
}

void World::z_movement(Mobj* mo) {
  if (mo->player && mo->z < mo->floor_z) {  // the view squats after a step up
    mo->player->view_height = wrap_sub(mo->player->view_height, wrap_sub(mo->floor_z, mo->z));  // Doom's ints wrap
    mo->player->delta_view_height = wrap_sub(kViewHeight, mo->player->view_height) >> 3;
  }
  mo->z = wrap_add(mo->z, mo->mom_z);
  if ((mo->flags & kFloat) && mo->target && !(mo->flags & kSkullfly) && !(mo->flags & kInfloat)) {
    // Floaters drift toward their target's height.
    const Fixed dist = approx_distance(wrap_sub(mo->x, mo->target->x), wrap_sub(mo->y, mo->target->y));
    const Fixed delta = wrap_sub(wrap_add(mo->target->z, mo->height >> 1), mo->z);
    if (delta < 0 && dist < -(delta * 3))
      mo->z -= kFloatSpeed;
    else if (delta > 0 && dist < delta * 3)
      mo->z += kFloatSpeed;
  }
  if (mo->z <= mo->floor_z) {
    // Ultimate Doom's lost souls bounce off floors (Doom II's 1.9 as well, by its version).
    const bool bounce_first = !options_.commercial && options_.ultimate;
    if (bounce_first && (mo->flags & kSkullfly)) mo->mom_z = -mo->mom_z;
    if (mo->mom_z < 0) {
      if (mo->player && mo->mom_z < -kGravity * 8) {  // a hard landing: the view dips, a grunt
        mo->player->delta_view_height = mo->mom_z >> 3;
        start_sound(mo, Sound::kOof);
      }
      mo->mom_z = 0;
    }
    mo->z = mo->floor_z;
    if (!bounce_first && (mo->flags & kSkullfly)) mo->mom_z = -mo->mom_z;
    if ((mo->flags & kMissile) && !(mo->flags & kNoclip)) {
      explode_missile(mo);
      return;
    }
  } else if (!(mo->flags & kNogravity)) {
    mo->mom_z = mo->mom_z == 0 ? -kGravity * 2 : wrap_sub(mo->mom_z, kGravity);
  }
  if (wrap_add(mo->z, mo->height) > mo->ceiling_z) {
    if (mo->mom_z > 0) mo->mom_z = 0;
    mo->z = wrap_sub(mo->ceiling_z, mo->height);
    if (mo->flags & kSkullfly) mo->mom_z = -mo->mom_z;  // the skull slammed into the ceiling
    if ((mo->flags & kMissile) && !(mo->flags & kNoclip)) {
      explode_missile(mo);
      return;
    }
  }
}

void World::nightmare_respawn(Mobj* mobj) {
  const Fixed x = Fixed(mobj->spawn_point.x) << kFracBits, y = Fixed(mobj->spawn_point.y) << kFracBits;
  if (!check_position(mobj, x, y)) return;  // something stands on the spot
  Mobj* fog = spawn_mobj(mobj->x, mobj->y, mobj->subsector->sector->floor_height, ThingType::kTfog);
  start_sound(fog, Sound::kTelept);
  const Subsector* ss = map_.point_in_subsector(x, y);
  fog = spawn_mobj(x, y, ss->sector->floor_height, ThingType::kTfog);
  start_sound(fog, Sound::kTelept);
  const Fixed z = (mobj->info->flags & kSpawnceiling) ? kOnCeilingZ : kOnFloorZ;
  Mobj* mo = spawn_mobj(x, y, z, mobj->type);
  mo->spawn_point = mobj->spawn_point;
  mo->angle = kAngle45 * Angle(mobj->spawn_point.angle / 45);
  if (mobj->spawn_point.options & kMtfAmbush) mo->flags |= kAmbush;
  mo->reaction_time = 18;
  remove_mobj(mobj);
}

void World::mobj_thinker(Mobj* mobj) {
  if (mobj->mom_x || mobj->mom_y || (mobj->flags & kSkullfly)) {
    xy_movement(mobj);
    if (mobj->removed) return;
  }
  if (mobj->z != mobj->floor_z || mobj->mom_z) {
    z_movement(mobj);
    if (mobj->removed) return;
  }
  if (mobj->tics != kInfiniteTics) {
    --mobj->tics;
    if (!mobj->tics) set_mobj_state(mobj, state_of(mobj->state).next);
    return;
  }
  // A monster lying dead may come back in nightmare (or with -respawn).
  if (!(mobj->flags & kCountkill) || !respawn_monsters_) return;
  ++mobj->move_count;
  if (mobj->move_count < 12 * 35) return;
  if (level_time_ & 31) return;
  if (random_.play() > 4) return;
  nightmare_respawn(mobj);
}

Mobj* World::spawn_mobj(Fixed x, Fixed y, Fixed z, ThingType type) {
  auto owned = std::make_unique<Mobj>();
  Mobj* mobj = owned.get();
  const ThingInfo& info = thing_info_[size_t(type)];
  mobj->id = next_id_++;
  mobj->type = type;
  mobj->info = &info;
  mobj->x = x;
  mobj->y = y;
  mobj->radius = info.radius;
  mobj->height = info.height;
  mobj->flags = info.flags;
  mobj->health = info.health;
  if (options_.skill != 5) mobj->reaction_time = info.reaction_time;
  mobj->last_look = random_.play() % 4;  // Doom's MAXPLAYERS
  const StateInfo& st = state_of(info.spawn);
  mobj->state = info.spawn;
  mobj->tics = st.tics;
  mobj->sprite = st.sprite;
  mobj->frame = st.frame | (st.bright ? kFullBright : 0);
  set_thing_position(mobj);
  mobj->floor_z = mobj->subsector->sector->floor_height;
  mobj->ceiling_z = mobj->subsector->sector->ceiling_height;
  if (z == kOnFloorZ)
    mobj->z = mobj->floor_z;
  else if (z == kOnCeilingZ)
    mobj->z = wrap_sub(mobj->ceiling_z, info.height);
  else
    mobj->z = z;
  add_thinker(std::move(owned));
  return mobj;
}

void World::queue_item_respawn(const Mobj& mobj) {
  if (!(mobj.flags & kSpecial) || (mobj.flags & kDropped) || mobj.type == ThingType::kInv || mobj.type == ThingType::kIns)
    return;
  item_queue_[item_queue_head_] = mobj.spawn_point;
  item_queue_time_[item_queue_head_] = level_time_;
  item_queue_head_ = (item_queue_head_ + 1) % kItemQueueSize;
  if (item_queue_head_ == item_queue_tail_) item_queue_tail_ = (item_queue_tail_ + 1) % kItemQueueSize;
}

void World::remove_mobj(Mobj* mobj) {
  queue_item_respawn(*mobj);
  unset_thing_position(mobj);
  stop_sound(mobj);
  remove_thinker(mobj);
}

void World::spawn_player(const MapThing& start) {
  if (start.type < 1 || start.type > kMaxPlayers || !in_game(start.type - 1)) return;
  Player& p = players_[size_t(start.type - 1)];
  if (p.state == PlayerState::kReborn) reborn_player(p);
  Mobj* mobj = spawn_mobj(Fixed(start.x) << kFracBits, Fixed(start.y) << kFracBits, kOnFloorZ, ThingType::kPlayer);
  mobj->flags |= uint32_t(start.type - 1) << kTranslationShift;  // the player's colour
  mobj->angle = kAngle45 * Angle(start.angle / 45);
  mobj->player = &p;
  mobj->health = p.inv.health;
  p.mo = mobj;
  p.state = PlayerState::kLive;
  p.refire = 0;
  p.message.clear();
  p.inv.damage_count = 0;
  p.inv.bonus_count = 0;
  p.extra_light = 0;
  p.fixed_colormap = 0;
  p.view_height = kViewHeight;
  setup_psprites(p);
  if (options_.deathmatch != Deathmatch::kNone) p.cards = 0x3f;  // every key in deathmatch
  if (is_console(p)) console_spawned_ = true;
}

void World::spawn_map_thing(const MapThing& mt) {
  if (mt.type == 11) {  // a deathmatch start: Doom keeps the first ten
    if (deathmatch_starts_.size() < kDeathmatchStarts) deathmatch_starts_.push_back(mt);
    return;
  }
  if (mt.type <= 0) return;   // Doom 2's type 0, left by some editors
  if (mt.type <= 4) {         // player starts, kept for respawning in a netgame
    player_starts_[size_t(mt.type - 1)] = mt;
    if (options_.deathmatch == Deathmatch::kNone) spawn_player(mt);
    return;
  }
  if (!options_.netgame && (mt.options & 16)) return;  // multiplayer only
  const int skill = options_.skill - 1;  // Doom's gameskill
  const int bit = skill == 0 ? 1 : skill == 4 ? 4 : int(1u << ((skill - 1) & 0x1F));
  if (!(mt.options & bit)) return;
  const ThingType type = thing_type_for_editor_number(mt.type);
  if (type == ThingType::kCount) {
    // Doom stops with an error here; we leave the thing out (the importer warned).
    return;
  }
  const ThingInfo& info = thing_info_[size_t(type)];
  if (options_.deathmatch != Deathmatch::kNone && (info.flags & kNotdmatch)) return;  // keys
  if (options_.no_monsters && (type == ThingType::kSkull || (info.flags & kCountkill))) return;
  const Fixed z = (info.flags & kSpawnceiling) ? kOnCeilingZ : kOnFloorZ;
  Mobj* mobj = spawn_mobj(Fixed(mt.x) << kFracBits, Fixed(mt.y) << kFracBits, z, type);
  mobj->spawn_point = mt;
  if (mobj->tics > 0) mobj->tics = 1 + random_.play() % mobj->tics;  // start at a random point of the loop
  if (mobj->flags & kCountkill) ++total_kills_;
  if (mobj->flags & kCountitem) ++total_items_;
  mobj->angle = kAngle45 * Angle(mt.angle / 45);
  if (mt.options & kMtfAmbush) mobj->flags |= kAmbush;
}

void World::spawn_puff(Fixed x, Fixed y, Fixed z) {
  z = wrap_add(z, random_.play_difference() << 10);
  Mobj* th = spawn_mobj(x, y, z, ThingType::kPuff);
  th->mom_z = kFracUnit;
  th->tics -= random_.play() & 3;
  if (th->tics < 1) th->tics = 1;
  if (attack_range_ == kMeleeRange) set_mobj_state(th, StateId::kPuff3);  // no sparks from a punch
}

void World::spawn_blood(Fixed x, Fixed y, Fixed z, int damage) {
  z = wrap_add(z, random_.play_difference() << 10);
  Mobj* th = spawn_mobj(x, y, z, ThingType::kBlood);
  th->mom_z = kFracUnit * 2;
  th->tics -= random_.play() & 3;
  if (th->tics < 1) th->tics = 1;
  if (damage <= 12 && damage >= 9)
    set_mobj_state(th, StateId::kBlood2);
  else if (damage < 9)
    set_mobj_state(th, StateId::kBlood3);
}

// A missile starts half a tic along, so that one fired point-blank into a wall explodes.
void World::check_missile_spawn(Mobj* th) {
  th->tics -= random_.play() & 3;
  if (th->tics < 1) th->tics = 1;
  th->x = wrap_add(th->x, th->mom_x >> 1);
  th->y = wrap_add(th->y, th->mom_y >> 1);
  th->z = wrap_add(th->z, th->mom_z >> 1);
  if (!try_move(th, th->x, th->y)) explode_missile(th);
}

Mobj* World::spawn_missile(Mobj* source, Mobj* dest, ThingType type) {
  Mobj* th = spawn_mobj(source->x, source->y, wrap_add(source->z, 4 * 8 * kFracUnit), type);
  if (th->info->see_sound != Sound::kNone) start_sound(th, th->info->see_sound);
  th->target = source;
  Angle an = point_to_angle(source->x, source->y, dest->x, dest->y);
  if (dest->flags & kShadow) an += Angle(random_.play_difference() << 20);  // aiming at a blur
  th->angle = an;
  const int fine_an = fine(an);
  th->mom_x = fixed_mul(th->info->speed, fine_cosine(fine_an));
  th->mom_y = fixed_mul(th->info->speed, fine_sine(fine_an));
  int dist = approx_distance(wrap_sub(dest->x, source->x), wrap_sub(dest->y, source->y));
  dist = dist / th->info->speed;
  if (dist < 1) dist = 1;
  th->mom_z = wrap_sub(dest->z, source->z) / dist;
  check_missile_spawn(th);
  return th;
}

void World::spawn_player_missile(Mobj* source, ThingType type) {
  // Aim at something straight ahead, or a little to either side, or fire level.
  Angle an = source->angle;
  Fixed slope = aim_line_attack(source, an, 16 * 64 * kFracUnit);
  if (!line_target_) {
    an += 1 << 26;
    slope = aim_line_attack(source, an, 16 * 64 * kFracUnit);
    if (!line_target_) {
      an -= 2 << 26;
      slope = aim_line_attack(source, an, 16 * 64 * kFracUnit);
    }
    if (!line_target_) {
      an = source->angle;
      slope = 0;
    }
  }
  Mobj* th = spawn_mobj(source->x, source->y, wrap_add(source->z, 4 * 8 * kFracUnit), type);
  if (th->info->see_sound != Sound::kNone) start_sound(th, th->info->see_sound);
  th->target = source;
  th->angle = an;
  th->mom_x = fixed_mul(th->info->speed, fine_cosine(fine(an)));
  th->mom_y = fixed_mul(th->info->speed, fine_sine(fine(an)));
  th->mom_z = fixed_mul(th->info->speed, slope);
  check_missile_spawn(th);
}

}  // namespace p3d::play
