// Monsters' thinking and the actions things' states run (Doom's p_enemy.c): how a
// monster wakes, walks toward its target eight directions at a time, and attacks;
// the Arch-vile's raising, the lost souls, the bosses' deaths and the icon of sin.
// Every P_Random call and every comparison is Doom's, in Doom's order.
#include <array>
#include <utility>

#include "engine/play/world.h"

namespace p3d::play {

namespace {

// Doom's eight directions, counterclockwise from east, and none.
enum Direction : int { kEast, kNorthEast, kNorth, kNorthWest, kWest, kSouthWest, kSouth, kSouthEast, kNoDir };
constexpr std::array<int, 9> kOpposite = {kWest,      kSouthWest, kSouth,     kSouthEast, kEast,
                                          kNorthEast, kNorth,     kNorthWest, kNoDir};
// Indexed by (dy < 0) * 2 + (dx > 0).
constexpr std::array<int, 4> kDiagonal = {kNorthWest, kNorthEast, kSouthWest, kSouthEast};
// A step in each direction per unit of speed (47000 is about 1/sqrt(2)).
constexpr std::array<Fixed, 8> kStepX = {kFracUnit, 47000, 0, -47000, -kFracUnit, -47000, 0, 47000};
constexpr std::array<Fixed, 8> kStepY = {0, 47000, kFracUnit, 47000, 0, -47000, -kFracUnit, -47000};

constexpr Angle kTracerTurn = 0xc000000;    // a revenant missile's turn per adjustment
constexpr Angle kFatSpread = kAngle90 / 8;  // between a mancubus's shots
constexpr Fixed kSkullSpeed = 20 * kFracUnit;
constexpr int kMaxSkulls = 20;  // a pain elemental spits no more once there are more than this

// speed * unit as Doom's int product (wrapping like it).
Fixed step(Fixed speed, Fixed unit) { return Fixed(uint32_t(speed) * uint32_t(unit)); }

// abs as Doom's C library computed it: the most negative int stays negative.
Fixed wrapping_abs(Fixed v) { return v < 0 ? wrap_sub(0, v) : v; }

// A thing still in the thinker list as a thing (Doom skipped the others by function).
Mobj* live_mobj(const std::unique_ptr<Thinker>& t) {
  return t->kind == Thinker::Kind::kMobj && !t->removed ? static_cast<Mobj*>(t.get()) : nullptr;
}

bool is_boss(const Mobj* mo) { return mo->type == ThingType::kSpider || mo->type == ThingType::kCyborg; }

// One of `count` consecutive sounds from `first`.
Sound pick_sound(Sound first, int roll, int count) { return Sound(int(first) + roll % count); }

// The actions of things' states, on one world.
class ThingActions {
 public:
  explicit ThingActions(World& world) : w_(world) {}
  void run(Mobj* mo, Action action);

 private:
  int roll() { return w_.random_.play(); }
  // Doom's (P_Random() - P_Random()) << shift, as an angle.
  Angle spread(int shift) { return Angle(w_.random_.play_difference()) << shift; }
  bool fast_monsters() const { return w_.options_.skill >= 5 || w_.options_.fast; }

  void look(Mobj* actor);
  void chase(Mobj* actor);
  void face_target(Mobj* actor);
  void pistol_shot(Mobj* actor);
  void shotgun_blast(Mobj* actor);
  void chaingun_shot(Mobj* actor);
  void keep_firing(Mobj* actor, int stop_below);
  void missile_at_target(Mobj* actor, ThingType missile);
  void melee_or_missile(Mobj* actor, bool face, ThingType missile, Sound melee_sound, int damage_dice,
                        int damage_scale);
  void sergeant_bite(Mobj* actor);
  void revenant_missile(Mobj* actor);
  void steer_tracer(Mobj* actor);
  void revenant_swing(Mobj* actor);
  void revenant_punch(Mobj* actor);
  bool keep_looking_for_corpse(Mobj* thing);
  void vile_chase(Mobj* actor);
  void keep_fire_ahead(Mobj* fire);
  void vile_target(Mobj* actor);
  void vile_attack(Mobj* actor);
  void fat_raise(Mobj* actor);
  void fat_attack(Mobj* actor, Angle actor_turn, Angle first_turn, Angle second_turn);
  void skull_charge(Mobj* actor);
  void shoot_skull(Mobj* actor, Angle angle);
  void pain_attack(Mobj* actor);
  void pain_die(Mobj* actor);
  void scream(Mobj* actor);
  void pain(Mobj* actor);
  void fall(Mobj* actor) { actor->flags &= ~kSolid; }
  bool another_alive(const Mobj* mo) const;
  bool boss_death_counts(ThingType type) const;
  void boss_death(Mobj* mo);
  void keen_die(Mobj* mo);
  void brain_awake();
  void brain_explosion(Fixed x, Fixed y, Fixed z);
  void brain_scream(Mobj* mo);
  void brain_explode(Mobj* mo);
  void brain_spit(Mobj* mo);
  void spawn_fly(Mobj* mo);
  void player_scream(Mobj* mo);

  World& w_;
};

// ---- waking and chasing

void ThingActions::look(Mobj* actor) {
  actor->threshold = 0;  // any shot wakes it
  Mobj* heard = actor->subsector->sector->sound_target;
  bool noticed = false;
  if (heard && (heard->flags & kShootable)) {
    actor->target = heard;
    noticed = !(actor->flags & kAmbush) || w_.check_sight(actor, actor->target);
  }
  if (!noticed && !w_.look_for_players(actor, false)) return;

  Sound sound = actor->info->see_sound;
  if (sound != Sound::kNone) {
    if (sound == Sound::kPosit1 || sound == Sound::kPosit2 || sound == Sound::kPosit3)
      sound = pick_sound(Sound::kPosit1, roll(), 3);
    else if (sound == Sound::kBgsit1 || sound == Sound::kBgsit2)
      sound = pick_sound(Sound::kBgsit1, roll(), 2);
    w_.start_sound(is_boss(actor) ? nullptr : actor, sound);  // bosses are heard everywhere
  }
  w_.set_mobj_state(actor, actor->info->see);
}

void ThingActions::chase(Mobj* actor) {
  if (actor->reaction_time) actor->reaction_time--;
  if (actor->threshold) {
    if (!actor->target || actor->target->health <= 0)
      actor->threshold = 0;
    else
      actor->threshold--;
  }

  // Turn 45 degrees toward where it walks.
  if (actor->move_dir < 8) {
    actor->angle &= 7u << 29;
    const int delta = int(actor->angle - (uint32_t(actor->move_dir) << 29));
    if (delta > 0)
      actor->angle -= kAngle45;
    else if (delta < 0)
      actor->angle += kAngle45;
  }

  if (!actor->target || !(actor->target->flags & kShootable)) {
    if (w_.look_for_players(actor, true)) return;
    w_.set_mobj_state(actor, actor->info->spawn);
    return;
  }

  // Never two attacks in a row (unless fast).
  if (actor->flags & kJustattacked) {
    actor->flags &= ~kJustattacked;
    if (!fast_monsters()) w_.new_chase_dir(actor);
    return;
  }

  if (actor->info->melee != StateId::kNull && w_.check_melee_range(actor)) {
    if (actor->info->attack_sound != Sound::kNone) w_.start_sound(actor, actor->info->attack_sound);
    w_.set_mobj_state(actor, actor->info->melee);
    return;
  }

  // Monsters shoot only between walks, except fast ones.
  if (actor->info->missile != StateId::kNull && (fast_monsters() || !actor->move_count) &&
      w_.check_missile_range(actor)) {
    w_.set_mobj_state(actor, actor->info->missile);
    actor->flags |= kJustattacked;
    return;
  }

  // In a netgame, a monster that lost sight of its target may pick another player.
  if (w_.options_.netgame && !actor->threshold && !w_.check_sight(actor, actor->target) &&
      w_.look_for_players(actor, true))
    return;

  if (--actor->move_count < 0 || !w_.move(actor)) w_.new_chase_dir(actor);

  if (actor->info->active_sound != Sound::kNone && roll() < 3) w_.start_sound(actor, actor->info->active_sound);
}

void ThingActions::face_target(Mobj* actor) {
  if (!actor->target) return;
  actor->flags &= ~kAmbush;
  actor->angle = point_to_angle(actor->x, actor->y, actor->target->x, actor->target->y);
  if (actor->target->flags & kShadow) actor->angle += spread(21);  // a blurred target is hard to face
}

// ---- hitscan attacks

void ThingActions::pistol_shot(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  Angle angle = actor->angle;
  const Fixed slope = w_.aim_line_attack(actor, angle, kMissileRange);
  w_.start_sound(actor, Sound::kPistol);
  angle += spread(20);
  const int damage = (roll() % 5 + 1) * 3;
  w_.line_attack(actor, angle, kMissileRange, slope, damage);
}

void ThingActions::shotgun_blast(Mobj* actor) {
  if (!actor->target) return;
  w_.start_sound(actor, Sound::kShotgn);
  face_target(actor);
  const Angle aim = actor->angle;
  const Fixed slope = w_.aim_line_attack(actor, aim, kMissileRange);
  for (int pellet = 0; pellet < 3; ++pellet) {
    const Angle angle = aim + spread(20);
    const int damage = (roll() % 5 + 1) * 3;
    w_.line_attack(actor, angle, kMissileRange, slope, damage);
  }
}

void ThingActions::chaingun_shot(Mobj* actor) {
  if (!actor->target) return;
  w_.start_sound(actor, Sound::kShotgn);
  face_target(actor);
  const Angle aim = actor->angle;
  const Fixed slope = w_.aim_line_attack(actor, aim, kMissileRange);
  const Angle angle = aim + spread(20);
  const int damage = (roll() % 5 + 1) * 3;
  w_.line_attack(actor, angle, kMissileRange, slope, damage);
}

// Keeps shooting unless a roll below `stop_below` says go on anyway, or the target
// is dead or out of sight.
void ThingActions::keep_firing(Mobj* actor, int stop_below) {
  face_target(actor);
  if (roll() < stop_below) return;
  if (!actor->target || actor->target->health <= 0 || !w_.check_sight(actor, actor->target))
    w_.set_mobj_state(actor, actor->info->see);
}

// ---- missiles and claws

void ThingActions::missile_at_target(Mobj* actor, ThingType missile) {
  if (!actor->target) return;
  face_target(actor);
  w_.spawn_missile(actor, actor->target, missile);
}

// A claw or bite within reach, else a missile (imps and cacodemons face their
// target first; barons do not).
void ThingActions::melee_or_missile(Mobj* actor, bool face, ThingType missile, Sound melee_sound, int damage_dice,
                                    int damage_scale) {
  if (!actor->target) return;
  if (face) face_target(actor);
  if (w_.check_melee_range(actor)) {
    if (melee_sound != Sound::kNone) w_.start_sound(actor, melee_sound);
    const int damage = (roll() % damage_dice + 1) * damage_scale;
    w_.damage_mobj(actor->target, actor, actor, damage);
    return;
  }
  w_.spawn_missile(actor, actor->target, missile);
}

void ThingActions::sergeant_bite(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  if (!w_.check_melee_range(actor)) return;
  const int damage = (roll() % 10 + 1) * 4;
  w_.damage_mobj(actor->target, actor, actor, damage);
}

// ---- the revenant

void ThingActions::revenant_missile(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  actor->z = wrap_add(actor->z, 16 * kFracUnit);  // the missile leaves from the shoulder
  Mobj* mo = w_.spawn_missile(actor, actor->target, ThingType::kTracer);
  actor->z = wrap_sub(actor->z, 16 * kFracUnit);
  // A step ahead, without relinking (as Doom did).
  mo->x = wrap_add(mo->x, mo->mom_x);
  mo->y = wrap_add(mo->y, mo->mom_y);
  mo->tracer = actor->target;
}

void ThingActions::steer_tracer(Mobj* actor) {
  // Every fourth tic of the game (Doom's gametic, which runs on through intermissions).
  if (w_.game_tic() & 3) return;

  w_.spawn_puff(actor->x, actor->y, actor->z);
  Mobj* smoke =
      w_.spawn_mobj(wrap_sub(actor->x, actor->mom_x), wrap_sub(actor->y, actor->mom_y), actor->z, ThingType::kSmoke);
  smoke->mom_z = kFracUnit;
  smoke->tics -= roll() & 3;
  if (smoke->tics < 1) smoke->tics = 1;

  Mobj* dest = actor->tracer;
  if (!dest || dest->health <= 0) return;

  // Turn toward the target by a fixed step, not past it.
  const Angle exact = point_to_angle(actor->x, actor->y, dest->x, dest->y);
  if (exact != actor->angle) {
    if (exact - actor->angle > kAngle180) {
      actor->angle -= kTracerTurn;
      if (exact - actor->angle < kAngle180) actor->angle = exact;
    } else {
      actor->angle += kTracerTurn;
      if (exact - actor->angle > kAngle180) actor->angle = exact;
    }
  }
  const int an = fine(actor->angle);
  actor->mom_x = fixed_mul(actor->info->speed, fine_cosine(an));
  actor->mom_y = fixed_mul(actor->info->speed, fine_sine(an));

  // Climb or dive toward the target's chest.
  Fixed dist = approx_distance(wrap_sub(dest->x, actor->x), wrap_sub(dest->y, actor->y)) / actor->info->speed;
  if (dist < 1) dist = 1;
  const Fixed slope = wrap_sub(wrap_add(dest->z, 40 * kFracUnit), actor->z) / dist;
  if (slope < actor->mom_z)
    actor->mom_z -= kFracUnit / 8;
  else
    actor->mom_z += kFracUnit / 8;
}

void ThingActions::revenant_swing(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  w_.start_sound(actor, Sound::kSkeswg);
}

void ThingActions::revenant_punch(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  if (w_.check_melee_range(actor)) {
    const int damage = (roll() % 10 + 1) * 6;
    w_.start_sound(actor, Sound::kSkepch);
    w_.damage_mobj(actor->target, actor, actor, damage);
  }
}

// ---- the Arch-vile

// Doom's PIT_VileCheck: false (stop, corpse_hit_ set) at a still corpse that can rise,
// touches the spot ahead, and would fit standing up (its height was quartered when it died).
bool ThingActions::keep_looking_for_corpse(Mobj* thing) {
  if (!(thing->flags & kCorpse)) return true;
  if (thing->tics != kInfiniteTics) return true;  // still falling
  if (thing->info->raise == StateId::kNull) return true;
  const Fixed max_dist = thing->info->radius + thing_info(ThingType::kVile).radius;
  if (wrapping_abs(wrap_sub(thing->x, w_.vile_try_x_)) > max_dist ||
      wrapping_abs(wrap_sub(thing->y, w_.vile_try_y_)) > max_dist)
    return true;
  w_.corpse_hit_ = thing;
  thing->mom_x = thing->mom_y = 0;
  thing->height <<= 2;
  const bool fits = w_.check_position(thing, thing->x, thing->y);
  thing->height >>= 2;
  return !fits;
}

void ThingActions::vile_chase(Mobj* actor) {
  if (unsigned(actor->move_dir) < 8) {  // Doom: not kNoDir
    w_.vile_try_x_ = wrap_add(actor->x, step(actor->info->speed, kStepX[size_t(actor->move_dir)]));
    w_.vile_try_y_ = wrap_add(actor->y, step(actor->info->speed, kStepY[size_t(actor->move_dir)]));
    const Blockmap& bm = w_.map_.blockmap;
    const int xl = wrap_sub(wrap_sub(w_.vile_try_x_, bm.origin_x), kMaxRadius * 2) >> kMapBlockShift;
    const int xh = wrap_add(wrap_sub(w_.vile_try_x_, bm.origin_x), kMaxRadius * 2) >> kMapBlockShift;
    const int yl = wrap_sub(wrap_sub(w_.vile_try_y_, bm.origin_y), kMaxRadius * 2) >> kMapBlockShift;
    const int yh = wrap_add(wrap_sub(w_.vile_try_y_, bm.origin_y), kMaxRadius * 2) >> kMapBlockShift;
    w_.vile_obj_ = actor;
    for (int bx = xl; bx <= xh; ++bx) {
      for (int by = yl; by <= yh; ++by) {
        if (w_.block_things(bx, by, [this](Mobj* thing) { return keep_looking_for_corpse(thing); })) continue;
        // Raise it: face it, then back to the target.
        Mobj* corpse = w_.corpse_hit_;
        Mobj* target = actor->target;
        actor->target = corpse;
        face_target(actor);
        actor->target = target;
        w_.set_mobj_state(actor, StateId::kVileHeal1);
        w_.start_sound(corpse, Sound::kSlop);
        const ThingInfo* info = corpse->info;
        w_.set_mobj_state(corpse, info->raise);
        corpse->height <<= 2;
        corpse->flags = info->flags;
        corpse->health = info->health;
        corpse->target = nullptr;
        return;
      }
    }
  }
  chase(actor);
}

// Doom's A_Fire: the flame stays in front of its victim while the Arch-vile sees it.
void ThingActions::keep_fire_ahead(Mobj* fire) {
  Mobj* dest = fire->tracer;
  if (!dest) return;
  if (!fire->target) return;  // Doom's stand-in at the origin would have crashed the sight check
  if (!w_.check_sight(fire->target, dest)) return;
  const int an = fine(dest->angle);
  w_.unset_thing_position(fire);
  fire->x = wrap_add(dest->x, fixed_mul(24 * kFracUnit, fine_cosine(an)));
  fire->y = wrap_add(dest->y, fixed_mul(24 * kFracUnit, fine_sine(an)));
  fire->z = dest->z;
  w_.set_thing_position(fire);
}

void ThingActions::vile_target(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  // Doom's slip, kept: the target's x for both coordinates (the flame moves at once).
  Mobj* fire = w_.spawn_mobj(actor->target->x, actor->target->x, actor->target->z, ThingType::kFire);
  actor->tracer = fire;
  fire->target = actor;
  fire->tracer = actor->target;
  keep_fire_ahead(fire);
}

void ThingActions::vile_attack(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  if (!w_.check_sight(actor, actor->target)) return;
  w_.start_sound(actor, Sound::kBarexp);
  w_.damage_mobj(actor->target, actor, actor, 20);
  actor->target->mom_z = 1000 * kFracUnit / actor->target->info->mass;
  const int an = fine(actor->angle);
  Mobj* fire = actor->tracer;
  if (!fire) return;
  // The blast goes off between the Arch-vile and its victim.
  fire->x = wrap_sub(actor->target->x, fixed_mul(24 * kFracUnit, fine_cosine(an)));
  fire->y = wrap_sub(actor->target->y, fixed_mul(24 * kFracUnit, fine_sine(an)));
  w_.radius_attack(fire, actor, 70);
}

// ---- the mancubus

void ThingActions::fat_raise(Mobj* actor) {
  face_target(actor);
  w_.start_sound(actor, Sound::kManatk);
}

// Two shots after the mancubus turns by actor_turn, each turned from its aim by its
// own turn. A turn of 0 leaves a shot as aimed: it is not even re-sped, which matters
// for a shot that burst at its spawn (Doom re-speeds only the shots it turns).
void ThingActions::fat_attack(Mobj* actor, Angle actor_turn, Angle first_turn, Angle second_turn) {
  face_target(actor);
  actor->angle += actor_turn;
  Mobj stand_in;  // Doom's P_SubstNullMobj: a target at the origin when there is none
  Mobj* target = actor->target ? actor->target : &stand_in;
  auto turn = [](Mobj* mo, Angle by) {
    mo->angle += by;
    const int an = fine(mo->angle);
    mo->mom_x = fixed_mul(mo->info->speed, fine_cosine(an));
    mo->mom_y = fixed_mul(mo->info->speed, fine_sine(an));
  };
  Mobj* first = w_.spawn_missile(actor, target, ThingType::kFatshot);
  if (first_turn) turn(first, first_turn);
  turn(w_.spawn_missile(actor, target, ThingType::kFatshot), second_turn);
}

// ---- lost souls and the pain elemental

void ThingActions::skull_charge(Mobj* actor) {
  if (!actor->target) return;
  Mobj* dest = actor->target;
  actor->flags |= kSkullfly;
  w_.start_sound(actor, actor->info->attack_sound);
  face_target(actor);
  const int an = fine(actor->angle);
  actor->mom_x = fixed_mul(kSkullSpeed, fine_cosine(an));
  actor->mom_y = fixed_mul(kSkullSpeed, fine_sine(an));
  Fixed dist = approx_distance(wrap_sub(dest->x, actor->x), wrap_sub(dest->y, actor->y)) / kSkullSpeed;
  if (dist < 1) dist = 1;
  actor->mom_z = wrap_sub(wrap_add(dest->z, dest->height >> 1), actor->z) / dist;
}

// Doom's A_PainShootSkull.
void ThingActions::shoot_skull(Mobj* actor, Angle angle) {
  int skulls = 0;
  for (const auto& t : w_.thinkers_)
    if (const Mobj* mo = live_mobj(t); mo && mo->type == ThingType::kSkull) ++skulls;
  if (skulls > kMaxSkulls) return;

  const int an = fine(angle);
  const Fixed prestep = 4 * kFracUnit + 3 * (actor->info->radius + thing_info(ThingType::kSkull).radius) / 2;
  const Fixed x = wrap_add(actor->x, fixed_mul(prestep, fine_cosine(an)));
  const Fixed y = wrap_add(actor->y, fixed_mul(prestep, fine_sine(an)));
  const Fixed z = wrap_add(actor->z, 8 * kFracUnit);
  Mobj* skull = w_.spawn_mobj(x, y, z, ThingType::kSkull);
  if (!w_.try_move(skull, skull->x, skull->y)) {
    w_.damage_mobj(skull, actor, actor, 10000);  // no room: it dies at once
    return;
  }
  skull->target = actor->target;
  skull_charge(skull);
}

void ThingActions::pain_attack(Mobj* actor) {
  if (!actor->target) return;
  face_target(actor);
  shoot_skull(actor, actor->angle);
}

void ThingActions::pain_die(Mobj* actor) {
  fall(actor);
  shoot_skull(actor, actor->angle + kAngle90);
  shoot_skull(actor, actor->angle + kAngle180);
  shoot_skull(actor, actor->angle + kAngle270);
}

// ---- sounds of pain and death

void ThingActions::scream(Mobj* actor) {
  Sound sound = actor->info->death_sound;
  if (sound == Sound::kNone) return;
  if (sound == Sound::kPodth1 || sound == Sound::kPodth2 || sound == Sound::kPodth3)
    sound = pick_sound(Sound::kPodth1, roll(), 3);
  else if (sound == Sound::kBgdth1 || sound == Sound::kBgdth2)
    sound = pick_sound(Sound::kBgdth1, roll(), 2);
  w_.start_sound(is_boss(actor) ? nullptr : actor, sound);
}

void ThingActions::pain(Mobj* actor) {
  if (actor->info->pain_sound != Sound::kNone) w_.start_sound(actor, actor->info->pain_sound);
}

void ThingActions::player_scream(Mobj* mo) {
  // Doom II's players scream louder when they die badly hurt but whole.
  const Sound sound = w_.options_.commercial && mo->health < -50 ? Sound::kPdiehi : Sound::kPldeth;
  w_.start_sound(mo, sound);
}

// ---- bosses

// Whether another thing of mo's type still lives.
bool ThingActions::another_alive(const Mobj* mo) const {
  for (const auto& t : w_.thinkers_)
    if (const Mobj* other = live_mobj(t); other && other != mo && other->type == mo->type && other->health > 0)
      return true;
  return false;
}

// Whether this map ends when every thing of this type is dead: Doom II's MAP07 for
// the mancubi and arachnotrons; Doom's episode ends (Ultimate Doom ties each to its
// boss; Doom 1.9 any boss on an eighth map, barons only in the first episode).
bool ThingActions::boss_death_counts(ThingType type) const {
  const GameOptions& o = w_.options_;
  if (o.commercial) return o.map == 7 && (type == ThingType::kFatso || type == ThingType::kBaby);
  if (!o.ultimate) return o.map == 8 && (type != ThingType::kBruiser || o.episode == 1);
  switch (o.episode) {
    case 1: return o.map == 8 && type == ThingType::kBruiser;
    case 2: return o.map == 8 && type == ThingType::kCyborg;
    case 3: return o.map == 8 && type == ThingType::kSpider;
    case 4: return (o.map == 6 && type == ThingType::kCyborg) || (o.map == 8 && type == ThingType::kSpider);
    default: return o.map == 8;
  }
}

void ThingActions::boss_death(Mobj* mo) {
  if (!boss_death_counts(mo->type)) return;
  bool someone_alive = false;  // to win
  for (int n = 0; n < kMaxPlayers; ++n) someone_alive |= w_.in_game(n) && w_.player(n).inv.health > 0;
  if (!someone_alive) return;
  if (another_alive(mo)) return;

  Line tagged;  // Doom's junk line: only its tag matters
  const GameOptions& o = w_.options_;
  if (o.commercial) {
    if (mo->type == ThingType::kFatso) {
      tagged.tag = 666;
      w_.do_floor(&tagged, Floor::Type::kLowerToLowest);
      return;
    }
    if (mo->type == ThingType::kBaby) {
      tagged.tag = 667;
      w_.do_floor(&tagged, Floor::Type::kRaiseToTexture);
      return;
    }
  } else if (o.episode == 1 || (o.episode == 4 && o.map == 8)) {
    tagged.tag = 666;
    w_.do_floor(&tagged, Floor::Type::kLowerToLowest);
    return;
  } else if (o.episode == 4 && o.map == 6) {
    tagged.tag = 666;
    w_.do_door(&tagged, Door::Type::kBlazeOpen);
    return;
  }
  w_.exit_level(false);
}

// Doom II's MAP32: the tag-666 doors open when the last Commander Keen dies.
void ThingActions::keen_die(Mobj* mo) {
  fall(mo);
  if (another_alive(mo)) return;
  Line tagged;
  tagged.tag = 666;
  w_.do_door(&tagged, Door::Type::kOpen);
}

// ---- the icon of sin

void ThingActions::brain_awake() {
  w_.brain_targets_.clear();
  w_.brain_target_on_ = 0;
  for (const auto& t : w_.thinkers_)
    if (Mobj* mo = live_mobj(t); mo && mo->type == ThingType::kBosstarget) w_.brain_targets_.push_back(mo);
  w_.start_sound(nullptr, Sound::kBossit);
}

// A rocket's explosion rising from (x, y, z), for the icon's death.
void ThingActions::brain_explosion(Fixed x, Fixed y, Fixed z) {
  Mobj* th = w_.spawn_mobj(x, y, z, ThingType::kRocket);
  th->mom_z = roll() * 512;
  w_.set_mobj_state(th, StateId::kBrainexplode1);
  th->tics -= roll() & 7;
  if (th->tics < 1) th->tics = 1;
}

void ThingActions::brain_scream(Mobj* mo) {
  for (Fixed x = wrap_sub(mo->x, 196 * kFracUnit); x < wrap_add(mo->x, 320 * kFracUnit);
       x = wrap_add(x, 8 * kFracUnit)) {
    const Fixed y = wrap_sub(mo->y, 320 * kFracUnit);
    const Fixed z = 128 + roll() * 2 * kFracUnit;
    brain_explosion(x, y, z);
  }
  w_.start_sound(nullptr, Sound::kBosdth);
}

void ThingActions::brain_explode(Mobj* mo) {
  const Fixed x = wrap_add(mo->x, w_.random_.play_difference() * 2048);
  const Fixed y = mo->y;
  const Fixed z = 128 + roll() * 2 * kFracUnit;
  brain_explosion(x, y, z);
}

void ThingActions::brain_spit(Mobj* mo) {
  // On the easy skills, every other time.
  w_.brain_easy_ = !w_.brain_easy_;
  if (w_.options_.skill <= 2 && !w_.brain_easy_) return;
  if (w_.brain_targets_.empty()) return;  // Doom stops with an error

  Mobj* target = w_.brain_targets_[w_.brain_target_on_];
  w_.brain_target_on_ = (w_.brain_target_on_ + 1) % w_.brain_targets_.size();
  Mobj* cube = w_.spawn_missile(mo, target, ThingType::kSpawnshot);
  cube->target = target;
  // It flies until it reaches the target's y (Doom divides by zero when it cannot).
  const int tics = state_info(cube->state).tics;
  if (cube->mom_y != 0 && tics != 0) cube->reaction_time = wrap_sub(target->y, mo->y) / cube->mom_y / tics;
  w_.start_sound(nullptr, Sound::kBospit);
}

// Doom's A_SpawnFly: when the cube arrives, a monster in a burst of fire.
void ThingActions::spawn_fly(Mobj* mo) {
  if (--mo->reaction_time) return;  // still flying

  Mobj stand_in;  // Doom's P_SubstNullMobj
  Mobj* target = mo->target ? mo->target : &stand_in;
  Mobj* fog = w_.spawn_mobj(target->x, target->y, target->z, ThingType::kSpawnfire);
  w_.start_sound(fog, Sound::kTelept);

  // Rarer monsters further down the table.
  static constexpr std::pair<int, ThingType> kChances[] = {
      {50, ThingType::kTroop},  {90, ThingType::kSergeant}, {120, ThingType::kShadows}, {130, ThingType::kPain},
      {160, ThingType::kHead},  {162, ThingType::kVile},    {172, ThingType::kUndead},  {192, ThingType::kBaby},
      {222, ThingType::kFatso}, {246, ThingType::kKnight},
  };
  const int r = roll();
  ThingType type = ThingType::kBruiser;
  for (const auto& [below, chance_type] : kChances) {
    if (r < below) {
      type = chance_type;
      break;
    }
  }
  Mobj* monster = w_.spawn_mobj(target->x, target->y, target->z, type);
  if (w_.look_for_players(monster, true)) w_.set_mobj_state(monster, monster->info->see);
  w_.teleport_move(monster, monster->x, monster->y);  // telefrags whatever stands there
  w_.remove_mobj(mo);
}

// ---- the dispatcher

void ThingActions::run(Mobj* mo, Action action) {
  switch (action) {
    case Action::kNone:
    case Action::kCount: return;
    // The weapons' actions run on psprites (weapons.cpp); Doom's tables never give them to things.
    case Action::kLight0:
    case Action::kWeaponReady:
    case Action::kLower:
    case Action::kRaise:
    case Action::kPunch:
    case Action::kReFire:
    case Action::kFirePistol:
    case Action::kLight1:
    case Action::kFireShotgun:
    case Action::kLight2:
    case Action::kFireShotgun2:
    case Action::kCheckReload:
    case Action::kOpenShotgun2:
    case Action::kLoadShotgun2:
    case Action::kCloseShotgun2:
    case Action::kFireCGun:
    case Action::kGunFlash:
    case Action::kFireMissile:
    case Action::kSaw:
    case Action::kFirePlasma:
    case Action::kBFGsound:
    case Action::kFireBFG: return;
    case Action::kBFGSpray: w_.bfg_spray(mo); return;
    case Action::kExplode: w_.radius_attack(mo, mo->target, 128); return;
    case Action::kPain: pain(mo); return;
    case Action::kPlayerScream: player_scream(mo); return;
    case Action::kFall: fall(mo); return;
    case Action::kXScream: w_.start_sound(mo, Sound::kSlop); return;
    case Action::kLook: look(mo); return;
    case Action::kChase: chase(mo); return;
    case Action::kFaceTarget: face_target(mo); return;
    case Action::kPosAttack: pistol_shot(mo); return;
    case Action::kScream: scream(mo); return;
    case Action::kSPosAttack: shotgun_blast(mo); return;
    case Action::kVileChase: vile_chase(mo); return;
    case Action::kVileStart: w_.start_sound(mo, Sound::kVilatk); return;
    case Action::kVileTarget: vile_target(mo); return;
    case Action::kVileAttack: vile_attack(mo); return;
    case Action::kStartFire:
      w_.start_sound(mo, Sound::kFlamst);
      keep_fire_ahead(mo);
      return;
    case Action::kFire: keep_fire_ahead(mo); return;
    case Action::kFireCrackle:
      w_.start_sound(mo, Sound::kFlame);
      keep_fire_ahead(mo);
      return;
    case Action::kTracer: steer_tracer(mo); return;
    case Action::kSkelWhoosh: revenant_swing(mo); return;
    case Action::kSkelFist: revenant_punch(mo); return;
    case Action::kSkelMissile: revenant_missile(mo); return;
    case Action::kFatRaise: fat_raise(mo); return;
    case Action::kFatAttack1: fat_attack(mo, kFatSpread, 0, kFatSpread); return;
    case Action::kFatAttack2: fat_attack(mo, Angle(0) - kFatSpread, 0, Angle(0) - kFatSpread * 2); return;
    case Action::kFatAttack3: fat_attack(mo, 0, Angle(0) - kFatSpread / 2, kFatSpread / 2); return;
    case Action::kBossDeath: boss_death(mo); return;
    case Action::kCPosAttack: chaingun_shot(mo); return;
    case Action::kCPosRefire: keep_firing(mo, 40); return;
    case Action::kTroopAttack: melee_or_missile(mo, true, ThingType::kTroopshot, Sound::kClaw, 8, 3); return;
    case Action::kSargAttack: sergeant_bite(mo); return;
    case Action::kHeadAttack: melee_or_missile(mo, true, ThingType::kHeadshot, Sound::kNone, 6, 10); return;
    case Action::kBruisAttack: melee_or_missile(mo, false, ThingType::kBruisershot, Sound::kClaw, 8, 10); return;
    case Action::kSkullAttack: skull_charge(mo); return;
    case Action::kMetal:
      w_.start_sound(mo, Sound::kMetal);
      chase(mo);
      return;
    case Action::kSpidRefire: keep_firing(mo, 10); return;
    case Action::kBabyMetal:
      w_.start_sound(mo, Sound::kBspwlk);
      chase(mo);
      return;
    case Action::kBspiAttack: missile_at_target(mo, ThingType::kArachplaz); return;
    case Action::kHoof:
      w_.start_sound(mo, Sound::kHoof);
      chase(mo);
      return;
    case Action::kCyberAttack: missile_at_target(mo, ThingType::kRocket); return;
    case Action::kPainAttack: pain_attack(mo); return;
    case Action::kPainDie: pain_die(mo); return;
    case Action::kKeenDie: keen_die(mo); return;
    case Action::kBrainPain: w_.start_sound(nullptr, Sound::kBospn); return;
    case Action::kBrainScream: brain_scream(mo); return;
    case Action::kBrainDie: w_.exit_level(false); return;
    case Action::kBrainAwake: brain_awake(); return;
    case Action::kBrainSpit: brain_spit(mo); return;
    case Action::kSpawnSound:
      w_.start_sound(mo, Sound::kBoscub);
      spawn_fly(mo);
      return;
    case Action::kSpawnFly: spawn_fly(mo); return;
    case Action::kBrainExplode: brain_explode(mo); return;
  }
}

// Doom's P_RecursiveSound: the noise floods through open two-sided lines; a second
// sound-blocking line stops it.
void spread_sound(World& w, Sector* sec, int sound_blocks) {
  if (sec->valid_count == w.valid_count_ && sec->sound_traversed <= sound_blocks + 1) return;  // flooded
  sec->valid_count = w.valid_count_;
  sec->sound_traversed = sound_blocks + 1;
  sec->sound_target = w.sound_target_;
  for (Line* check : sec->lines) {
    if (!(check->flags & kMlTwoSided)) continue;
    if (w.line_opening(*check).range <= 0) continue;  // no back, or a closed door
    Sector* other = w.map_.sides[size_t(check->side[0])].sector == sec ? w.map_.sides[size_t(check->side[1])].sector
                                                                       : w.map_.sides[size_t(check->side[0])].sector;
    if (check->flags & kMlSoundBlock) {
      if (!sound_blocks) spread_sound(w, other, 1);
    } else {
      spread_sound(w, other, sound_blocks);
    }
  }
}

}  // namespace

void World::act(Mobj* mo, Action action) { ThingActions(*this).run(mo, action); }

void World::noise_alert(Mobj* target, Mobj* emitter) {
  sound_target_ = target;
  ++valid_count_;
  spread_sound(*this, emitter->subsector->sector, 0);
}

bool World::check_melee_range(Mobj* actor) {
  Mobj* target = actor->target;
  if (!target) return false;
  const Fixed dist = approx_distance(wrap_sub(target->x, actor->x), wrap_sub(target->y, actor->y));
  if (dist >= kMeleeRange - 20 * kFracUnit + target->info->radius) return false;
  return check_sight(actor, target);
}

bool World::check_missile_range(Mobj* actor) {
  if (!check_sight(actor, actor->target)) return false;
  if (actor->flags & kJusthit) {  // it was just hit: fight back
    actor->flags &= ~kJusthit;
    return true;
  }
  if (actor->reaction_time) return false;

  // The nearer, the likelier it shoots.
  Fixed dist = wrap_sub(approx_distance(wrap_sub(actor->x, actor->target->x), wrap_sub(actor->y, actor->target->y)),
                        64 * kFracUnit);
  if (actor->info->melee == StateId::kNull) dist = wrap_sub(dist, 128 * kFracUnit);  // no claws: shoot more
  dist >>= kFracBits;
  if (actor->type == ThingType::kVile && dist > 14 * 64) return false;
  if (actor->type == ThingType::kUndead) {
    if (dist < 196) return false;  // near enough to punch
    dist >>= 1;
  }
  if (actor->type == ThingType::kCyborg || actor->type == ThingType::kSpider || actor->type == ThingType::kSkull)
    dist >>= 1;
  if (dist > 200) dist = 200;
  if (actor->type == ThingType::kCyborg && dist > 160) dist = 160;
  return random_.play() >= dist;
}

bool World::move(Mobj* actor) {
  if (actor->move_dir == kNoDir) return false;
  if (unsigned(actor->move_dir) >= 8) return false;  // Doom stops with an error
  const size_t dir = size_t(actor->move_dir);
  const Fixed try_x = wrap_add(actor->x, step(actor->info->speed, kStepX[dir]));
  const Fixed try_y = wrap_add(actor->y, step(actor->info->speed, kStepY[dir]));

  if (try_move(actor, try_x, try_y)) {
    actor->flags &= ~kInfloat;
    if (!(actor->flags & kFloat)) actor->z = actor->floor_z;
    return true;
  }
  if ((actor->flags & kFloat) && tm_.float_ok) {  // blocked by height: float toward the opening
    if (actor->z < tm_.floor_z)
      actor->z = wrap_add(actor->z, kFloatSpeed);
    else
      actor->z = wrap_sub(actor->z, kFloatSpeed);
    actor->flags |= kInfloat;
    return true;
  }
  if (tm_.special_hits.empty()) return false;

  // Blocked at special lines: try to open them (doors), the last touched first.
  actor->move_dir = kNoDir;
  bool good = false;
  const std::vector<Line*> hits = tm_.special_hits;
  for (size_t i = hits.size(); i-- > 0;)
    if (use_special_line(actor, hits[i], 0)) good = true;
  return good;
}

bool World::try_walk(Mobj* actor) {
  if (!move(actor)) return false;
  actor->move_count = random_.play() & 15;
  return true;
}

void World::new_chase_dir(Mobj* actor) {
  if (!actor->target) return;  // Doom stops with an error
  const int old_dir = actor->move_dir >= 0 && actor->move_dir <= kNoDir ? actor->move_dir : kNoDir;
  const int turnaround = kOpposite[size_t(old_dir)];
  const Fixed dx = wrap_sub(actor->target->x, actor->x);
  const Fixed dy = wrap_sub(actor->target->y, actor->y);
  int first = dx > 10 * kFracUnit ? kEast : dx < -10 * kFracUnit ? kWest : kNoDir;
  int second = dy < -10 * kFracUnit ? kSouth : dy > 10 * kFracUnit ? kNorth : kNoDir;

  // Straight at the target, diagonally.
  if (first != kNoDir && second != kNoDir) {
    actor->move_dir = kDiagonal[size_t(((dy < 0) << 1) + (dx > 0))];
    if (actor->move_dir != turnaround && try_walk(actor)) return;
  }

  // Along one axis, then the other: the longer leg first (or at random).
  if (random_.play() > 200 || wrapping_abs(dy) > wrapping_abs(dx)) std::swap(first, second);
  if (first == turnaround) first = kNoDir;
  if (second == turnaround) second = kNoDir;
  for (int dir : {first, second}) {
    if (dir == kNoDir) continue;
    actor->move_dir = dir;
    if (try_walk(actor)) return;
  }

  // No direct path: on as before, else any way but back, searched from a random end.
  if (old_dir != kNoDir) {
    actor->move_dir = old_dir;
    if (try_walk(actor)) return;
  }
  const bool counterclockwise = random_.play() & 1;
  for (int i = 0; i < 8; ++i) {
    const int dir = counterclockwise ? kEast + i : kSouthEast - i;
    if (dir == turnaround) continue;
    actor->move_dir = dir;
    if (try_walk(actor)) return;
  }
  if (turnaround != kNoDir) {
    actor->move_dir = turnaround;
    if (try_walk(actor)) return;
  }
  actor->move_dir = kNoDir;  // cannot move
}

bool World::look_for_players(Mobj* actor, bool all_around) {
  // Doom looks through its four player slots from the last one looked at, at most
  // two players a call.
  int looked = 0;
  const int stop = (actor->last_look - 1) & 3;
  for (;; actor->last_look = (actor->last_look + 1) & 3) {
    if (!in_game(actor->last_look)) continue;
    if (looked++ == 2 || actor->last_look == stop) return false;
    const Player& player = players_[size_t(actor->last_look)];
    if (player.inv.health <= 0 || !player.mo) continue;  // dead
    if (!check_sight(actor, player.mo)) continue;
    if (!all_around) {
      const Angle an = point_to_angle(actor->x, actor->y, player.mo->x, player.mo->y) - actor->angle;
      if (an > kAngle90 && an < kAngle270) {
        const Fixed dist = approx_distance(wrap_sub(player.mo->x, actor->x), wrap_sub(player.mo->y, actor->y));
        if (dist > kMeleeRange) continue;  // behind it, and not near enough to feel
      }
    }
    actor->target = player.mo;
    return true;
  }
}

}  // namespace p3d::play
