// Sectors whose light changes: flickering, flashing, strobing, glowing, and lines
// that turn lights on or off (Doom's p_lights.c). The light thinkers do not mark
// their sector busy: a sector may light up and move at once.
#include "engine/play/world.h"

namespace p3d::play {

namespace {

constexpr int kGlowSpeed = 8;     // light units a tic
constexpr int kStrobeBright = 5;  // tics a strobe stays bright

}  // namespace

// T_FireFlicker: every 4 tics, up to 48 below the brightest, never below the darkest.
void World::think_fire_flicker(FireFlicker* flicker) {
  if (--flicker->count) return;
  const int amount = (random_.play() & 3) * 16;
  Sector* sector = flicker->sector;
  sector->light = sector->light - amount < flicker->min_light ? flicker->min_light : flicker->max_light - amount;
  flicker->count = 4;
}

// Sector special 17: between its own light and 16 above its darkest neighbour.
void World::spawn_fire_flicker(Sector* sector) {
  sector->special = 0;
  FireFlicker* flicker = make_thinker<FireFlicker>();
  flicker->sector = sector;
  flicker->max_light = sector->light;
  flicker->min_light = find_min_surrounding_light(sector, sector->light) + 16;
  flicker->count = 4;
}

// T_LightFlash: dark for 1..8 tics at random, bright for 1 or 65 (Doom masks the
// random number with 64).
void World::think_light_flash(LightFlash* flash) {
  if (--flash->count) return;
  Sector* sector = flash->sector;
  if (sector->light == flash->max_light) {
    sector->light = flash->min_light;
    flash->count = (random_.play() & flash->min_time) + 1;
  } else {
    sector->light = flash->max_light;
    flash->count = (random_.play() & flash->max_time) + 1;
  }
}

// Sector special 1.
void World::spawn_light_flash(Sector* sector) {
  sector->special = 0;
  LightFlash* flash = make_thinker<LightFlash>();
  flash->sector = sector;
  flash->max_light = sector->light;
  flash->min_light = find_min_surrounding_light(sector, sector->light);
  flash->max_time = 64;
  flash->min_time = 7;
  flash->count = (random_.play() & flash->max_time) + 1;
}

// T_StrobeFlash: dark for dark_time tics, bright for bright_time, in turn.
void World::think_strobe(Strobe* strobe) {
  if (--strobe->count) return;
  Sector* sector = strobe->sector;
  if (sector->light == strobe->min_light) {
    sector->light = strobe->max_light;
    strobe->count = strobe->bright_time;
  } else {
    sector->light = strobe->min_light;
    strobe->count = strobe->dark_time;
  }
}

// Sector specials 2, 3, 4, 12, 13 and line special 17: strobing between the sector's
// light and its darkest neighbour's (or black, if none is darker). Strobes in sync
// all start together; the others at random within 8 tics.
void World::spawn_strobe_flash(Sector* sector, int fast_or_slow, bool in_sync) {
  Strobe* strobe = make_thinker<Strobe>();
  strobe->sector = sector;
  strobe->dark_time = fast_or_slow;
  strobe->bright_time = kStrobeBright;
  strobe->max_light = sector->light;
  strobe->min_light = find_min_surrounding_light(sector, sector->light);
  if (strobe->min_light == strobe->max_light) strobe->min_light = 0;
  sector->special = 0;
  strobe->count = in_sync ? 1 : (random_.play() & 7) + 1;
}

// T_Glow: down to the darkest neighbour and back up to its own light.
void World::think_glow(Glow* glow) {
  Sector* sector = glow->sector;
  switch (glow->direction) {
    case -1:
      sector->light -= kGlowSpeed;
      if (sector->light <= glow->min_light) {
        sector->light += kGlowSpeed;
        glow->direction = 1;
      }
      break;
    case 1:
      sector->light += kGlowSpeed;
      if (sector->light >= glow->max_light) {
        sector->light -= kGlowSpeed;
        glow->direction = -1;
      }
      break;
    default: break;
  }
}

// Sector special 8.
void World::spawn_glowing_light(Sector* sector) {
  Glow* glow = make_thinker<Glow>();
  glow->sector = sector;
  glow->min_light = find_min_surrounding_light(sector, sector->light);
  glow->max_light = sector->light;
  glow->direction = -1;
  sector->special = 0;
}

// EV_StartLightStrobing: slow strobes in the tagged sectors that are not moving.
void World::start_light_strobing(Line* line) {
  for (int secnum = -1; (secnum = find_sector_from_line_tag(line, secnum)) >= 0;) {
    Sector* sec = &map_.sectors[size_t(secnum)];
    if (sec->special_data) continue;
    spawn_strobe_flash(sec, kSlowDark, false);
  }
}

// EV_TurnTagLightsOff: each tagged sector takes its darkest neighbour's light.
void World::turn_tag_lights_off(Line* line) {
  for (Sector& sector : map_.sectors) {
    if (sector.tag != line->tag) continue;
    int min = sector.light;
    for (Line* l : sector.lines) {
      const Sector* other = get_next_sector(l, &sector);
      if (other && other->light < min) min = other->light;
    }
    sector.light = min;
  }
}

// EV_LightTurnOn: the tagged sectors take light `bright`, or for 0 the brightest
// neighbour's light. Doom keeps what it found for the first such sector as `bright`
// for all the next ones.
void World::light_turn_on(Line* line, int bright) {
  for (Sector& sector : map_.sectors) {
    if (sector.tag != line->tag) continue;
    if (!bright) {
      for (Line* l : sector.lines) {
        const Sector* other = get_next_sector(l, &sector);
        if (other && other->light > bright) bright = other->light;
      }
    }
    sector.light = bright;
  }
}

}  // namespace p3d::play
