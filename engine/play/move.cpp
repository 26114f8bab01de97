// Movement and collision (Doom's p_map.c): whether a thing fits at a place
// (P_CheckPosition: things first, then lines, each cell's list in the blockmap's
// order), moving it there and crossing the lines it passes, the player's slide along
// walls, teleport stomping, hitscan aiming and shooting, the use key, blast damage,
// and what a moving floor or ceiling does to the things in its sector.
#include <cstdlib>

#include "engine/play/world.h"

namespace p3d::play {

namespace {

// The thing's box at (x, y).
Box box_at(Fixed x, Fixed y, Fixed radius) {
  Box b;
  b[kBoxTop] = wrap_add(y, radius);
  b[kBoxBottom] = wrap_sub(y, radius);
  b[kBoxRight] = wrap_add(x, radius);
  b[kBoxLeft] = wrap_sub(x, radius);
  return b;
}

}  // namespace

// ---- position checks -----------------------------------------------------------

// The start of P_CheckPosition and P_TeleportMove: the thing's box at (x, y), and the
// floor and ceiling under its centre before the lines it touches lower and raise them.
void World::start_position_check(Mobj* thing, Fixed x, Fixed y) {
  tm_.thing = thing;
  tm_.flags = thing->flags;
  tm_.x = x;
  tm_.y = y;
  tm_.bbox = box_at(x, y, thing->radius);
  const Subsector* ss = map_.point_in_subsector(x, y);
  tm_.ceiling_line = nullptr;
  tm_.floor_z = tm_.dropoff_z = ss->sector->floor_height;
  tm_.ceiling_z = ss->sector->ceiling_height;
  ++valid_count_;
  tm_.special_hits.clear();
}

bool World::teleport_move(Mobj* thing, Fixed x, Fixed y) {
  start_position_check(thing, x, y);
  // Whatever shootable stands there is killed (only by players, except on MAP30).
  auto stomp = [&](Mobj* other) {
    if (!(other->flags & kShootable)) return true;
    const Fixed block = other->radius + tm_.thing->radius;
    if (std::abs(wrap_sub(other->x, tm_.x)) >= block || std::abs(wrap_sub(other->y, tm_.y)) >= block) return true;
    if (other == tm_.thing) return true;
    if (!tm_.thing->player && options_.map != 30) return false;
    damage_mobj(other, tm_.thing, tm_.thing, 10000);
    return true;
  };
  const Blockmap& bm = map_.blockmap;
  const int xl = wrap_sub(wrap_sub(tm_.bbox[kBoxLeft], bm.origin_x), kMaxRadius) >> kMapBlockShift;
  const int xh = wrap_add(wrap_sub(tm_.bbox[kBoxRight], bm.origin_x), kMaxRadius) >> kMapBlockShift;
  const int yl = wrap_sub(wrap_sub(tm_.bbox[kBoxBottom], bm.origin_y), kMaxRadius) >> kMapBlockShift;
  const int yh = wrap_add(wrap_sub(tm_.bbox[kBoxTop], bm.origin_y), kMaxRadius) >> kMapBlockShift;
  for (int bx = xl; bx <= xh; ++bx)
    for (int by = yl; by <= yh; ++by)
      if (!block_things(bx, by, stomp)) return false;
  unset_thing_position(thing);
  thing->floor_z = tm_.floor_z;
  thing->ceiling_z = tm_.ceiling_z;
  thing->x = x;
  thing->y = y;
  set_thing_position(thing);
  return true;
}

bool World::check_position(Mobj* thing, Fixed x, Fixed y) {
  start_position_check(thing, x, y);
  if (tm_.flags & kNoclip) return true;

  auto check_thing = [&](Mobj* other) {
    if (!(other->flags & (kSolid | kSpecial | kShootable))) return true;
    const Fixed block = other->radius + tm_.thing->radius;
    if (std::abs(wrap_sub(other->x, tm_.x)) >= block || std::abs(wrap_sub(other->y, tm_.y)) >= block) return true;
    if (other == tm_.thing) return true;
    Mobj* mover = tm_.thing;
    if (mover->flags & kSkullfly) {  // a charging lost soul bites what it hits
      const int damage = (random_.play() % 8 + 1) * mover->info->damage;
      damage_mobj(other, mover, mover, damage);
      // Doom then stops its tmthing, which the bite may have changed: a monster woken
      // by it chases at once, and the check of its own step takes tmthing over. Then
      // that monster stops and stands, and the soul flies on until its next move.
      Mobj* stopped = tm_.thing;
      stopped->flags &= ~kSkullfly;
      stopped->mom_x = stopped->mom_y = stopped->mom_z = 0;
      set_mobj_state(stopped, stopped->info->spawn);
      return false;
    }
    if (mover->flags & kMissile) {
      if (mover->z > wrap_add(other->z, other->height)) return true;  // overhead
      if (wrap_add(mover->z, mover->height) < other->z) return true;  // underneath
      // A monster's missile passes through its own kind (barons and knights are one kind).
      const Mobj* shooter = mover->target;
      if (shooter && (shooter->type == other->type ||
                      (shooter->type == ThingType::kKnight && other->type == ThingType::kBruiser) ||
                      (shooter->type == ThingType::kBruiser && other->type == ThingType::kKnight))) {
        if (other == shooter) return true;
        if (other->type != ThingType::kPlayer) return false;  // explodes, harmless
      }
      if (!(other->flags & kShootable)) return !(other->flags & kSolid);
      const int damage = (random_.play() % 8 + 1) * mover->info->damage;
      damage_mobj(other, mover, mover->target, damage);
      return false;
    }
    if (other->flags & kSpecial) {  // a pickup
      const bool solid = other->flags & kSolid;
      if (tm_.flags & kPickup) touch_special_thing(other, mover);
      return !solid;
    }
    return !(other->flags & kSolid);
  };
  auto check_line = [&](Line* ld) {
    if (tm_.bbox[kBoxRight] <= ld->bbox[kBoxLeft] || tm_.bbox[kBoxLeft] >= ld->bbox[kBoxRight] ||
        tm_.bbox[kBoxTop] <= ld->bbox[kBoxBottom] || tm_.bbox[kBoxBottom] >= ld->bbox[kBoxTop])
      return true;
    if (box_on_line_side(tm_.bbox, *ld) != -1) return true;
    // The box crosses the line.
    if (!ld->back) return false;  // one-sided
    if (!(tm_.thing->flags & kMissile)) {
      if (ld->flags & kMlBlocking) return false;
      if (!tm_.thing->player && (ld->flags & kMlBlockMonsters)) return false;
    }
    const Opening o = line_opening(*ld);
    if (o.top < tm_.ceiling_z) {
      tm_.ceiling_z = o.top;
      tm_.ceiling_line = ld;
    }
    if (o.bottom > tm_.floor_z) tm_.floor_z = o.bottom;
    if (o.low_floor < tm_.dropoff_z) tm_.dropoff_z = o.low_floor;
    if (ld->special) tm_.special_hits.push_back(ld);
    return true;
  };

  // Things first, in cells grown by the largest radius; then lines.
  const Blockmap& bm = map_.blockmap;
  int xl = wrap_sub(wrap_sub(tm_.bbox[kBoxLeft], bm.origin_x), kMaxRadius) >> kMapBlockShift;
  int xh = wrap_add(wrap_sub(tm_.bbox[kBoxRight], bm.origin_x), kMaxRadius) >> kMapBlockShift;
  int yl = wrap_sub(wrap_sub(tm_.bbox[kBoxBottom], bm.origin_y), kMaxRadius) >> kMapBlockShift;
  int yh = wrap_add(wrap_sub(tm_.bbox[kBoxTop], bm.origin_y), kMaxRadius) >> kMapBlockShift;
  for (int bx = xl; bx <= xh; ++bx)
    for (int by = yl; by <= yh; ++by)
      if (!block_things(bx, by, check_thing)) return false;
  xl = wrap_sub(tm_.bbox[kBoxLeft], bm.origin_x) >> kMapBlockShift;
  xh = wrap_sub(tm_.bbox[kBoxRight], bm.origin_x) >> kMapBlockShift;
  yl = wrap_sub(tm_.bbox[kBoxBottom], bm.origin_y) >> kMapBlockShift;
  yh = wrap_sub(tm_.bbox[kBoxTop], bm.origin_y) >> kMapBlockShift;
  for (int bx = xl; bx <= xh; ++bx)
    for (int by = yl; by <= yh; ++by)
      if (!block_lines(bx, by, check_line)) return false;
  return true;
}

bool World::try_move(Mobj* thing, Fixed x, Fixed y) {
  tm_.float_ok = false;
  if (!check_position(thing, x, y)) return false;  // a solid wall or thing
  if (!(thing->flags & kNoclip)) {
    if (wrap_sub(tm_.ceiling_z, tm_.floor_z) < thing->height) return false;  // does not fit
    tm_.float_ok = true;
    if (!(thing->flags & kTeleport) && wrap_sub(tm_.ceiling_z, thing->z) < thing->height) return false;  // must lower itself
    if (!(thing->flags & kTeleport) && wrap_sub(tm_.floor_z, thing->z) > 24 * kFracUnit) return false;  // too high a step
    if (!(thing->flags & (kDropoff | kFloat)) && wrap_sub(tm_.floor_z, tm_.dropoff_z) > 24 * kFracUnit)
      return false;  // would stand over a drop
  }
  unset_thing_position(thing);
  const Fixed old_x = thing->x, old_y = thing->y;
  thing->floor_z = tm_.floor_z;
  thing->ceiling_z = tm_.ceiling_z;
  thing->x = x;
  thing->y = y;
  set_thing_position(thing);
  if (!(thing->flags & (kTeleport | kNoclip))) {
    // The special lines it crossed, the last touched first. A special that checks
    // positions itself (a teleporter, a crushing floor) replaces the list, as in Doom.
    while (!tm_.special_hits.empty()) {
      Line* ld = tm_.special_hits.back();
      tm_.special_hits.pop_back();
      const int side = point_on_line_side(thing->x, thing->y, *ld);
      const int old_side = point_on_line_side(old_x, old_y, *ld);
      if (side != old_side && ld->special) cross_special_line(ld->index, old_side, thing);
    }
  }
  return true;
}

bool World::thing_height_clip(Mobj* thing) {
  const bool on_floor = thing->z == thing->floor_z;
  check_position(thing, thing->x, thing->y);
  thing->floor_z = tm_.floor_z;
  thing->ceiling_z = tm_.ceiling_z;
  if (on_floor)
    thing->z = thing->floor_z;  // it rides the floor
  else if (wrap_add(thing->z, thing->height) > thing->ceiling_z)
    thing->z = wrap_sub(thing->ceiling_z, thing->height);
  return wrap_sub(thing->ceiling_z, thing->floor_z) >= thing->height;
}

// ---- sliding along walls ----------------------------------------------------------

namespace {

// The move (xmove, ymove) turned along the line it hit (Doom's P_HitSlideLine).
void hit_slide_line(const Line& ld, const Mobj& mo, Fixed& xmove, Fixed& ymove) {
  if (ld.slope == Slope::kHorizontal) {
    ymove = 0;
    return;
  }
  if (ld.slope == Slope::kVertical) {
    xmove = 0;
    return;
  }
  const int side = World::point_on_line_side(mo.x, mo.y, ld);
  Angle line_angle = vector_angle(ld.dx, ld.dy);
  if (side == 1) line_angle += kAngle180;
  const Angle move_angle = vector_angle(xmove, ymove);
  Angle delta_angle = move_angle - line_angle;
  if (delta_angle > kAngle180) delta_angle += kAngle180;
  const Fixed move_len = approx_distance(xmove, ymove);
  const Fixed new_len = fixed_mul(move_len, fine_cosine(fine(delta_angle)));
  xmove = fixed_mul(new_len, fine_cosine(fine(line_angle)));
  ymove = fixed_mul(new_len, fine_sine(fine(line_angle)));
}

}  // namespace

void World::slide_move(Mobj* mo) {
  slide_mo_ = mo;
  // The nearest line that blocks the traces from the box's leading corners.
  auto slide_traverse = [&](Intercept& in) {
    Line* li = in.line;
    bool blocking = false;
    if (!(li->flags & kMlTwoSided)) {
      if (point_on_line_side(slide_mo_->x, slide_mo_->y, *li)) return true;  // its back: pass through
      blocking = true;
    } else {
      const Opening o = line_opening(*li);
      blocking = o.range < slide_mo_->height || wrap_sub(o.top, slide_mo_->z) < slide_mo_->height ||
                 wrap_sub(o.bottom, slide_mo_->z) > 24 * kFracUnit;
    }
    if (!blocking) return true;
    if (in.frac < best_slide_frac_) {
      second_slide_frac_ = best_slide_frac_;
      second_slide_line_ = best_slide_line_;
      best_slide_frac_ = in.frac;
      best_slide_line_ = li;
    }
    return false;
  };
  auto stairstep = [&] {  // no line found, or three tries: move along one axis
    if (!try_move(mo, mo->x, wrap_add(mo->y, mo->mom_y))) try_move(mo, wrap_add(mo->x, mo->mom_x), mo->y);
  };
  for (int hit_count = 1;; ++hit_count) {
    if (hit_count == 3) return stairstep();
    Fixed lead_x, lead_y, trail_x, trail_y;
    if (mo->mom_x > 0) {
      lead_x = wrap_add(mo->x, mo->radius);
      trail_x = wrap_sub(mo->x, mo->radius);
    } else {
      lead_x = wrap_sub(mo->x, mo->radius);
      trail_x = wrap_add(mo->x, mo->radius);
    }
    if (mo->mom_y > 0) {
      lead_y = wrap_add(mo->y, mo->radius);
      trail_y = wrap_sub(mo->y, mo->radius);
    } else {
      lead_y = wrap_sub(mo->y, mo->radius);
      trail_y = wrap_add(mo->y, mo->radius);
    }
    best_slide_frac_ = kFracUnit + 1;
    path_traverse(lead_x, lead_y, wrap_add(lead_x, mo->mom_x), wrap_add(lead_y, mo->mom_y), kAddLines, slide_traverse);
    path_traverse(trail_x, lead_y, wrap_add(trail_x, mo->mom_x), wrap_add(lead_y, mo->mom_y), kAddLines, slide_traverse);
    path_traverse(lead_x, trail_y, wrap_add(lead_x, mo->mom_x), wrap_add(trail_y, mo->mom_y), kAddLines, slide_traverse);
    if (best_slide_frac_ == kFracUnit + 1) return stairstep();  // the move hit nothing?
    // Up to the wall, a little short of it.
    best_slide_frac_ -= 0x800;
    if (best_slide_frac_ > 0) {
      const Fixed new_x = fixed_mul(mo->mom_x, best_slide_frac_), new_y = fixed_mul(mo->mom_y, best_slide_frac_);
      if (!try_move(mo, wrap_add(mo->x, new_x), wrap_add(mo->y, new_y))) return stairstep();
    }
    // The rest of the move, along the wall.
    best_slide_frac_ = kFracUnit - (best_slide_frac_ + 0x800);
    if (best_slide_frac_ > kFracUnit) best_slide_frac_ = kFracUnit;
    if (best_slide_frac_ <= 0) return;
    tm_xmove_ = fixed_mul(mo->mom_x, best_slide_frac_);
    tm_ymove_ = fixed_mul(mo->mom_y, best_slide_frac_);
    hit_slide_line(*best_slide_line_, *slide_mo_, tm_xmove_, tm_ymove_);
    mo->mom_x = tm_xmove_;
    mo->mom_y = tm_ymove_;
    if (try_move(mo, wrap_add(mo->x, tm_xmove_), wrap_add(mo->y, tm_ymove_))) return;
  }
}

// ---- hitscans ---------------------------------------------------------------------

Fixed World::aim_line_attack(Mobj* t1, Angle angle, Fixed distance) {
  static Mobj null_shooter;  // Doom's P_SubstNullMobj: a shooter at the origin
  if (!t1) t1 = &null_shooter;
  const int an = fine(angle);
  shoot_thing_ = t1;
  const Fixed x2 = wrap_add(t1->x, Fixed(uint32_t(distance >> kFracBits) * uint32_t(fine_cosine(an))));
  const Fixed y2 = wrap_add(t1->y, Fixed(uint32_t(distance >> kFracBits) * uint32_t(fine_sine(an))));
  shoot_z_ = wrap_add(wrap_add(t1->z, t1->height >> 1), 8 * kFracUnit);
  // The view's vertical reach: 100 of 160 (Doom's screen).
  top_slope_ = 100 * kFracUnit / 160;
  bottom_slope_ = -100 * kFracUnit / 160;
  attack_range_ = distance;
  line_target_ = nullptr;
  auto aim_traverse = [&](Intercept& in) {
    if (in.is_line) {
      const Line* li = in.line;
      if (!(li->flags & kMlTwoSided)) return false;
      const Opening o = line_opening(*li);
      if (o.bottom >= o.top) return false;  // closed
      const Fixed dist = fixed_mul(attack_range_, in.frac);
      if (!li->back || li->front->floor_height != li->back->floor_height) {
        const Fixed slope = fixed_div(wrap_sub(o.bottom, shoot_z_), dist);
        if (slope > bottom_slope_) bottom_slope_ = slope;
      }
      if (!li->back || li->front->ceiling_height != li->back->ceiling_height) {
        const Fixed slope = fixed_div(wrap_sub(o.top, shoot_z_), dist);
        if (slope < top_slope_) top_slope_ = slope;
      }
      return top_slope_ > bottom_slope_;
    }
    Mobj* th = in.thing;
    if (th == shoot_thing_) return true;
    if (!(th->flags & kShootable)) return true;  // a corpse
    const Fixed dist = fixed_mul(attack_range_, in.frac);
    Fixed thing_top = fixed_div(wrap_sub(wrap_add(th->z, th->height), shoot_z_), dist);
    if (thing_top < bottom_slope_) return true;  // over it
    Fixed thing_bottom = fixed_div(wrap_sub(th->z, shoot_z_), dist);
    if (thing_bottom > top_slope_) return true;  // under it
    if (thing_top > top_slope_) thing_top = top_slope_;
    if (thing_bottom < bottom_slope_) thing_bottom = bottom_slope_;
    aim_slope_ = Fixed((int64_t(thing_top) + thing_bottom) / 2);
    line_target_ = th;
    return false;
  };
  path_traverse(t1->x, t1->y, x2, y2, kAddLines | kAddThings, aim_traverse);
  return line_target_ ? aim_slope_ : 0;
}

void World::line_attack(Mobj* t1, Angle angle, Fixed distance, Fixed slope, int damage) {
  const int an = fine(angle);
  shoot_thing_ = t1;
  la_damage_ = damage;
  const Fixed x2 = wrap_add(t1->x, Fixed(uint32_t(distance >> kFracBits) * uint32_t(fine_cosine(an))));
  const Fixed y2 = wrap_add(t1->y, Fixed(uint32_t(distance >> kFracBits) * uint32_t(fine_sine(an))));
  shoot_z_ = wrap_add(wrap_add(t1->z, t1->height >> 1), 8 * kFracUnit);
  attack_range_ = distance;
  aim_slope_ = slope;
  // Where along the trace, `back` units short of frac, the shot ends.
  auto point_at = [&](Fixed frac, Fixed back, Fixed& x, Fixed& y, Fixed& z) {
    frac = wrap_sub(frac, fixed_div(back, attack_range_));
    x = wrap_add(trace_.x, fixed_mul(trace_.dx, frac));
    y = wrap_add(trace_.y, fixed_mul(trace_.dy, frac));
    z = wrap_add(shoot_z_, fixed_mul(aim_slope_, fixed_mul(frac, attack_range_)));
  };
  auto shoot_traverse = [&](Intercept& in) {
    if (in.is_line) {
      Line* li = in.line;
      if (li->special) shoot_special_line(shoot_thing_, li);
      bool hit = !(li->flags & kMlTwoSided);
      if (!hit) {
        const Opening o = line_opening(*li);
        const Fixed dist = fixed_mul(attack_range_, in.frac);
        const bool floor_step = !li->back || li->front->floor_height != li->back->floor_height;
        const bool ceiling_step = !li->back || li->front->ceiling_height != li->back->ceiling_height;
        if (floor_step && fixed_div(wrap_sub(o.bottom, shoot_z_), dist) > aim_slope_) hit = true;
        else if (ceiling_step && fixed_div(wrap_sub(o.top, shoot_z_), dist) < aim_slope_) hit = true;
      }
      if (!hit) return true;  // the shot goes on through the opening
      Fixed x, y, z;
      point_at(in.frac, 4 * kFracUnit, x, y, z);
      if (li->front->ceiling_pic == level::kSky) {  // no puff against the sky
        if (z > li->front->ceiling_height) return false;
        if (li->back && li->back->ceiling_pic == level::kSky) return false;
      }
      spawn_puff(x, y, z);
      return false;
    }
    Mobj* th = in.thing;
    if (th == shoot_thing_) return true;
    if (!(th->flags & kShootable)) return true;
    const Fixed dist = fixed_mul(attack_range_, in.frac);
    if (fixed_div(wrap_sub(wrap_add(th->z, th->height), shoot_z_), dist) < aim_slope_) return true;  // over it
    if (fixed_div(wrap_sub(th->z, shoot_z_), dist) > aim_slope_) return true;                      // under it
    Fixed x, y, z;
    point_at(in.frac, 10 * kFracUnit, x, y, z);
    if (th->flags & kNoblood)
      spawn_puff(x, y, z);
    else
      spawn_blood(x, y, z, la_damage_);
    if (la_damage_) damage_mobj(th, shoot_thing_, shoot_thing_, la_damage_);
    return false;
  };
  path_traverse(t1->x, t1->y, x2, y2, kAddLines | kAddThings, shoot_traverse);
}

// ---- use, blasts, crushing ---------------------------------------------------------

void World::use_lines(Player& player) {
  Mobj* user = player.mo;
  const int an = fine(user->angle);
  const Fixed x1 = user->x, y1 = user->y;
  const Fixed x2 = wrap_add(x1, Fixed(uint32_t(kUseRange >> kFracBits) * uint32_t(fine_cosine(an))));
  const Fixed y2 = wrap_add(y1, Fixed(uint32_t(kUseRange >> kFracBits) * uint32_t(fine_sine(an))));
  path_traverse(x1, y1, x2, y2, kAddLines, [&](Intercept& in) {
    if (!in.line->special) {
      if (line_opening(*in.line).range <= 0) {
        start_sound(user, Sound::kNoway);  // a wall in the way
        return false;
      }
      return true;
    }
    const int side = point_on_line_side(user->x, user->y, *in.line) == 1 ? 1 : 0;
    use_special_line(user, in.line, side);
    return false;  // only the first special line is used
  });
}

void World::radius_attack(Mobj* spot, Mobj* source, int damage) {
  // Doom adds MAXRADIUS (already 16.16) before shifting: it overflows away, leaving damage units.
  const Fixed dist = Fixed((uint32_t(damage) + uint32_t(kMaxRadius)) << kFracBits);
  const Blockmap& bm = map_.blockmap;
  const int yh = wrap_sub(wrap_add(spot->y, dist), bm.origin_y) >> kMapBlockShift;
  const int yl = wrap_sub(wrap_sub(spot->y, dist), bm.origin_y) >> kMapBlockShift;
  const int xh = wrap_sub(wrap_add(spot->x, dist), bm.origin_x) >> kMapBlockShift;
  const int xl = wrap_sub(wrap_sub(spot->x, dist), bm.origin_x) >> kMapBlockShift;
  bomb_spot_ = spot;
  bomb_source_ = source;
  bomb_damage_ = damage;
  auto blast = [&](Mobj* thing) {
    if (!(thing->flags & kShootable)) return true;
    if (thing->type == ThingType::kCyborg || thing->type == ThingType::kSpider) return true;  // immune
    const Fixed dx = std::abs(wrap_sub(thing->x, bomb_spot_->x)), dy = std::abs(wrap_sub(thing->y, bomb_spot_->y));
    int d = (wrap_sub(dx > dy ? dx : dy, thing->radius)) >> kFracBits;
    if (d < 0) d = 0;
    if (d >= bomb_damage_) return true;  // out of reach
    if (check_sight(thing, bomb_spot_)) damage_mobj(thing, bomb_spot_, bomb_source_, bomb_damage_ - d);
    return true;
  };
  for (int y = yl; y <= yh; ++y)
    for (int x = xl; x <= xh; ++x) block_things(x, y, blast);
}

bool World::change_sector(Sector* sector, bool crunch) {
  no_fit_ = false;
  crush_change_ = crunch;
  auto change = [&](Mobj* thing) {
    if (thing_height_clip(thing)) return true;  // it fits
    if (thing->health <= 0) {  // a corpse is crushed to gibs
      set_mobj_state(thing, StateId::kGibs);
      thing->flags &= ~kSolid;
      thing->height = 0;
      thing->radius = 0;
      return true;
    }
    if (thing->flags & kDropped) {  // dropped items are crushed away
      remove_mobj(thing);
      return true;
    }
    if (!(thing->flags & kShootable)) return true;  // decorations pass through
    no_fit_ = true;
    if (crush_change_ && !(level_time_ & 3)) {
      damage_mobj(thing, nullptr, nullptr, 10);
      Mobj* mo = spawn_mobj(thing->x, thing->y, wrap_add(thing->z, thing->height / 2), ThingType::kBlood);
      mo->mom_x = random_.play_difference() << 12;
      mo->mom_y = random_.play_difference() << 12;
    }
    return true;
  };
  for (int x = sector->block_box[kBoxLeft]; x <= sector->block_box[kBoxRight]; ++x)
    for (int y = sector->block_box[kBoxBottom]; y <= sector->block_box[kBoxTop]; ++y) block_things(x, y, change);
  return no_fit_;
}

}  // namespace p3d::play
