// The World's frame: a level set up as Doom's P_SetupLevel sets it (things spawned in
// THINGS order, then the sector specials), the tic as P_Ticker runs it, the thinker
// list, sounds and messages, and the level state the renderers draw.
#include "engine/play/world.h"

#include <algorithm>
#include <cstdio>

#include "engine/play/dehacked.h"
#include "engine/play/doom_demo.h"
#include "engine/util/doom.h"

namespace p3d::play {

namespace {

constexpr double kDegreesPerAngle = 360.0 / 4294967296.0;
constexpr int kTicRate = 35;

// Doom II's monsters, which Doom's own games do not spawn: Doom stops loading a map's
// things at the first of them.
bool doom2_only(int editor_number) {
  switch (editor_number) {
    case 68: case 64: case 88: case 89: case 69: case 67: case 71: case 65: case 66: case 84:
      return true;
    default:
      return false;
  }
}

}  // namespace

GameOptions game_options_for(const wad::Stack& wads, const std::string& map_name, int skill) {
  GameOptions o;
  o.skill = skill;
  int episode = 0, number = 0;
  o.commercial = std::sscanf(map_name.c_str(), "MAP%d", &number) == 1;
  if (!o.commercial && std::sscanf(map_name.c_str(), "E%dM%d", &episode, &number) == 2) o.episode = episode;
  o.map = number;
  o.ultimate = !o.commercial && wads.map("E4M1").has_value();
  o.texts = dehacked_texts(wads);
  return o;
}

void set_demo_game(GameOptions& o, const DoomDemo& d) {
  o.fast = d.fast;
  o.respawn = d.respawn;
  o.no_monsters = d.no_monsters;
  for (int p = 0; p < kMaxPlayers; ++p) o.in_game[size_t(p)] = d.players[size_t(p)];
  o.console_player = d.console_player;
  o.netgame = d.netgame();
  o.deathmatch = d.deathmatch == 0 ? Deathmatch::kNone : d.deathmatch == 2 ? Deathmatch::kAltdeath : Deathmatch::kDeathmatch;
}

World::World(Map map, const level::Level& level, const GameOptions& options, Random random,
             const std::array<Player, kMaxPlayers>* carried)
    : map_(std::move(map)), level_(level), options_(options), random_(random), game_tic_at_start_(options.game_tic) {
  states_.assign(std::begin(kStates), std::end(kStates));
  thing_info_.assign(std::begin(kThingTypes), std::end(kThingTypes));
  if (options_.fast || options_.skill == 5) {  // Doom's G_InitNew: faster demons and missiles
    for (size_t s = size_t(StateId::kSargRun1); s <= size_t(StateId::kSargPain2); ++s) states_[s].tics >>= 1;
    for (ThingType t : {ThingType::kBruisershot, ThingType::kHeadshot, ThingType::kTroopshot})
      thing_info_[size_t(t)].speed = 20 * kFracUnit;
  }
  respawn_monsters_ = options_.respawn || options_.skill == 5;
  block_links_.assign(size_t(map_.blockmap.width) * size_t(map_.blockmap.height), nullptr);
  index_walls();
  index_sprite_frames();
  index_static_things();
  for (int n = 0; n < kMaxPlayers; ++n) {
    if (carried && in_game(n)) players_[size_t(n)] = (*carried)[size_t(n)];
    players_[size_t(n)].number = n;
  }
  player().view_z = 1;
  for (const MapThing& mt : map_.things) {
    if (!options_.commercial && doom2_only(mt.type)) break;
    spawn_map_thing(mt);
  }
  if (options_.deathmatch != Deathmatch::kNone)  // P_SetupLevel: each player at a random deathmatch start
    for (int n = 0; n < kMaxPlayers; ++n)
      if (in_game(n)) {
        players_[size_t(n)].mo = nullptr;
        deathmatch_spawn_player(n);
      }
  item_queue_head_ = item_queue_tail_ = 0;
  spawn_specials();
  if (options_.time_limit > 0 && options_.deathmatch != Deathmatch::kNone)
    level_timer_ = options_.time_limit * 60 * kTicRate;
  state_ = level::start_state(level_, options_.skill);
  for (size_t l = 0; l < map_.lines.size(); ++l) show_line(l);
}

World::~World() = default;

std::array<Player, kMaxPlayers> World::players_for_next_level() const {
  std::array<Player, kMaxPlayers> next = players_;
  for (Player& p : next) {
    p.mo = p.attacker = nullptr;
    if (p.state == PlayerState::kDead) p.state = PlayerState::kReborn;
    p.inv.powers = {};
    p.cards = 0;
    p.extra_light = p.fixed_colormap = 0;
    p.inv.damage_count = p.inv.bonus_count = 0;
    p.frags = {};
    p.kill_count = p.secret_count = p.inv.items = 0;
  }
  return next;
}

Fixed World::eye_z() const {
  const Player& p = player();
  const Mobj* mo = p.mo;
  if (level_time_ > 0 || !mo) return p.view_z;
  return std::min(wrap_add(mo->z, p.view_height), wrap_sub(mo->ceiling_z, 4 * kFracUnit));  // as calc_height
}

int frag_total(const Player& player) {
  int total = 0;
  for (int n = 0; n < kMaxPlayers; ++n) total += n == player.number ? -player.frags[size_t(n)] : player.frags[size_t(n)];
  return total;
}

void World::tick(const TicCmd& cmd) {
  std::array<TicCmd, kMaxPlayers> cmds{};
  cmds[size_t(options_.console_player)] = cmd;
  tick_players(cmds);
}

void World::tick_players(const std::array<TicCmd, kMaxPlayers>& cmds) {
  sounds_.clear();
  messages_.clear();
  console_spawned_ = false;
  if (options_.netgame)  // G_Ticker: the dead who pressed use come back first
    for (int n = 0; n < kMaxPlayers; ++n)
      if (in_game(n) && players_[size_t(n)].state == PlayerState::kReborn && players_[size_t(n)].mo)
        reborn_in_netgame(n);
  for (int n = 0; n < kMaxPlayers; ++n) {  // G_Ticker's consistency check, before anyone moves
    const Mobj* mo = players_[size_t(n)].mo;
    tic_start_x_[size_t(n)] = in_game(n) && mo ? std::optional<Fixed>(mo->x) : std::nullopt;
  }
  for (int n = 0; n < kMaxPlayers; ++n) {  // P_Ticker: each player thinks, in order
    if (!in_game(n)) continue;
    Player& p = players_[size_t(n)];
    p.cmd = cmds[size_t(n)];
    if (p.mo) player_think(p);
  }
  run_thinkers();
  update_specials();
  if (level_timer_ && !--level_timer_) exit_level(false);  // P_UpdateSpecials: a deathmatch's time is up
  respawn_specials();
  ++level_time_;
  stale_ = true;
}

void World::add_thinker(std::unique_ptr<Thinker> t) { thinkers_.push_back(std::move(t)); }

void World::run_thinkers() {
  // By index: thinkers added while the list runs (missiles, puffs) run this tic too.
  for (size_t i = 0; i < thinkers_.size(); ++i) {
    Thinker* t = thinkers_[i].get();
    if (t->removed || !t->active) continue;
    switch (t->kind) {
      case Thinker::Kind::kMobj: mobj_thinker(static_cast<Mobj*>(t)); break;
      case Thinker::Kind::kDoor: think_door(static_cast<Door*>(t)); break;
      case Thinker::Kind::kFloor: think_floor(static_cast<Floor*>(t)); break;
      case Thinker::Kind::kPlat: think_plat(static_cast<Plat*>(t)); break;
      case Thinker::Kind::kCeiling: think_ceiling(static_cast<Ceiling*>(t)); break;
      case Thinker::Kind::kLightFlash: think_light_flash(static_cast<LightFlash*>(t)); break;
      case Thinker::Kind::kStrobe: think_strobe(static_cast<Strobe*>(t)); break;
      case Thinker::Kind::kGlow: think_glow(static_cast<Glow*>(t)); break;
      case Thinker::Kind::kFireFlicker: think_fire_flicker(static_cast<FireFlicker*>(t)); break;
    }
  }
  // Removed thinkers leave the list; things among them stay allocated, since others may
  // still point at them (Doom's freed memory kept its contents too).
  if (!removed_since_pass_) return;
  removed_since_pass_ = 0;
  auto kept = std::stable_partition(thinkers_.begin(), thinkers_.end(), [](const auto& t) { return !t->removed; });
  for (auto it = kept; it != thinkers_.end(); ++it) graveyard_.push_back(std::move(*it));
  thinkers_.erase(kept, thinkers_.end());
}

std::vector<const Mobj*> World::things() const {
  std::vector<const Mobj*> out;
  for (const auto& t : thinkers_)
    if (t->kind == Thinker::Kind::kMobj && !t->removed) out.push_back(static_cast<const Mobj*>(t.get()));
  return out;
}

const Mobj* World::thing(uint32_t id) const {
  for (const auto& t : thinkers_)
    if (t->kind == Thinker::Kind::kMobj && static_cast<const Mobj&>(*t).id == id) return t->removed ? nullptr : &static_cast<const Mobj&>(*t);
  return nullptr;
}

size_t World::thinker_count() const {
  return size_t(std::count_if(thinkers_.begin(), thinkers_.end(), [](const auto& t) { return !t->removed; }));
}

// ---- sounds, messages, exits -----------------------------------------------------

void World::start_sound(const Mobj* origin, Sound sound) {
  if (sound == Sound::kNone) return;
  sounds_.push_back(origin ? SoundEvent{sound, origin->id, origin->x, origin->y} : SoundEvent{sound, 0, 0, 0});
}

void World::start_sector_sound(const Sector* sector, Sound sound) {
  if (sound == Sound::kNone) return;
  sounds_.push_back({sound, kSectorOrigin + uint64_t(sector->index), sector->sound_x, sector->sound_y});
}

void World::stop_sound(const Mobj*) {}  // sounds are the listener's business

void World::say(std::string message) { say(player(), std::move(message)); }

void World::say(Player& player, std::string message) {
  if (const auto it = options_.texts.find(message); it != options_.texts.end()) message = it->second;
  player.message = message;
  if (is_console(player)) messages_.push_back(std::move(message));
}

void World::player_left(int n) {
  if (n < 0 || n >= kMaxPlayers || !in_game(n)) return;
  options_.in_game[size_t(n)] = false;  // its body stays where it stood, thinking no more
  std::string message = "Player 1 left the game";
  if (const auto it = options_.texts.find(message); it != options_.texts.end()) message = it->second;
  if (message.size() > 7) message[7] = char(message[7] + n);  // Doom's exitmsg[7] += player_num
  player().message = std::move(message);
}

void World::exit_level(bool secret) { exit_ = secret ? ExitKind::kSecret : ExitKind::kNormal; }

// ---- what the renderers see ------------------------------------------------------

// Which of the level's walls draw each line: WAD levels name their line as the wall's
// source; levels built from walls have a line per wall.
void World::index_walls() {
  line_walls_.assign(map_.lines.size(), {});
  for (uint32_t w = 0; w < level_.walls.size(); ++w) {
    const int line = map_.wall_lines.empty() ? level_.walls[w].source : map_.wall_lines[w];
    if (line >= 0 && size_t(line) < line_walls_.size()) line_walls_[size_t(line)].push_back(w);
  }
  start_offsets_.resize(map_.sides.size());
  for (size_t i = 0; i < map_.sides.size(); ++i) start_offsets_[i] = map_.sides[i].texture_offset;
  side_lines_.assign(map_.sides.size(), {});
  for (const Line& line : map_.lines)
    for (int k : {0, 1})
      if (line.side[size_t(k)] >= 0) side_lines_[size_t(line.side[size_t(k)])].push_back(line.index);
}

// The level's sprite frame for each of Doom's sprites and frames, bright or not.
void World::index_sprite_frames() {
  sprite_frames_.assign(size_t(Sprite::kCount), std::vector<int32_t>(64, level::kNone));
  for (size_t s = 0; s < size_t(Sprite::kCount); ++s) {
    const std::string name = kSpriteNames[s];
    for (size_t f = 0; f < level_.sprite_frames.size(); ++f) {
      const level::SpriteFrame& frame = level_.sprite_frames[f];
      if (frame.name.size() != 5 || frame.name.compare(0, 4, name) != 0) continue;
      const int letter = frame.name[4] - 'A';
      if (letter < 0 || letter >= 32) continue;
      int32_t& slot = sprite_frames_[s][size_t(letter + (frame.bright ? 32 : 0))];
      if (slot == level::kNone) slot = int32_t(f);
    }
  }
}

int32_t World::level_frame(const Mobj& mo) const {
  const int letter = mo.frame & kFrameMask;
  if (size_t(mo.sprite) >= sprite_frames_.size() || letter >= 32) return level::kNone;
  const std::vector<int32_t>& frames = sprite_frames_[size_t(mo.sprite)];
  const bool bright = mo.frame & kFullBright;
  const int32_t exact = frames[size_t(letter + (bright ? 32 : 0))];
  return exact != level::kNone ? exact : frames[size_t(letter + (bright ? 0 : 32))];
}

void World::index_static_things() {
  for (size_t i = 0; i < level_.things.size(); ++i) {
    const level::Thing& t = level_.things[i];
    if (t.sprite == level::kNone || thing_type_for_editor_number(t.type) != ThingType::kCount) continue;
    if (!(t.flags & doom::skill_bit(options_.skill)) || (t.flags & doom::kThingNotSingle)) continue;
    static_things_.push_back(int32_t(i));
  }
}

int World::wake_monsters() {
  int woken = 0;
  for (size_t i = 0; i < thinkers_.size(); ++i) {
    if (thinkers_[i]->kind != Thinker::Kind::kMobj || thinkers_[i]->removed) continue;
    Mobj* mo = static_cast<Mobj*>(thinkers_[i].get());
    if (!(mo->flags & kCountkill) || mo->health <= 0 || mo->info->see == StateId::kNull || !player().mo) continue;
    mo->target = player().mo;
    set_mobj_state(mo, mo->info->see);
    ++woken;
  }
  return woken;
}

void World::place_player(Fixed x, Fixed y, Angle angle) {
  Player& p = player();
  Mobj* mo = p.mo;
  if (!mo) return;
  unset_thing_position(mo);
  mo->x = x;
  mo->y = y;
  set_thing_position(mo);
  mo->floor_z = mo->subsector->sector->floor_height;
  mo->ceiling_z = mo->subsector->sector->ceiling_height;
  mo->z = mo->floor_z;
  mo->angle = angle;
  p.view_z = wrap_add(mo->z, p.view_height);
  stale_ = true;
}

void World::apply_cheats(uint8_t cheats) {
  Player& p = player();
  if (cheats & 1) {  // idclip
    p.cheats ^= kCheatNoclip;
    say(p.cheats & kCheatNoclip ? "No Clipping Mode ON" : "No Clipping Mode OFF");
  }
  if (cheats & 2) {  // iddqd
    p.cheats ^= kCheatGodMode;
    if (p.cheats & kCheatGodMode) {
      p.inv.health = 100;
      if (p.mo) p.mo->health = 100;
    }
    say(p.cheats & kCheatGodMode ? "Degreelessness Mode On" : "Degreelessness Mode Off");
  }
  if (cheats & 4) {  // idkfa
    p.inv.armor = 200;
    p.inv.armor_type = 2;
    for (size_t w = 0; w < p.inv.weapons.size(); ++w)
      p.inv.weapons[w] = options_.commercial || Weapon(w) != Weapon::kSuperShotgun;
    p.inv.ammo = p.inv.max_ammo;
    p.cards = 63;
    say("Very Happy Ammo Added");
  }
}

// The line's special and its sides' textures into the walls drawn for it.
void World::show_line(size_t l) const {
  const Line& line = map_.lines[l];
  for (uint32_t w : line_walls_[l]) {
    state_.specials[w] = line.special;
    for (int k = 0; k < 2; ++k) {
      if (line.side[k] < 0 || level_.walls[w].sides[k].sector == level::kNone) continue;
      const Side& side = map_.sides[size_t(line.side[k])];
      state_.texture(w, k, level::kUpperPart) = side.top;
      state_.texture(w, k, level::kMiddlePart) = side.middle;
      state_.texture(w, k, level::kLowerPart) = side.bottom;
    }
  }
}

void World::show() const {
  stale_ = false;
  state_.fixed_light_map = player().fixed_colormap ? player().fixed_colormap : level::kNone;
  for (size_t i = 0; i < map_.sectors.size() && i < state_.sectors.size(); ++i) {
    const Sector& s = map_.sectors[i];
    level::SectorState& out = state_.sectors[i];
    out.floor = to_double(s.floor_height);
    out.ceiling = to_double(s.ceiling_height);
    out.light = s.light;
    out.floor_texture = s.floor_pic;
    out.ceiling_texture = s.ceiling_pic;
    out.special = s.special;
  }
  for (int l : changed_lines_) {
    show_line(size_t(l));
    for (int k : {0, 1})  // a side shared with other lines changes them too
      if (const int side = map_.lines[size_t(l)].side[size_t(k)]; side >= 0)
        for (int other : side_lines_[size_t(side)])
          if (other != l) show_line(size_t(other));
  }
  changed_lines_.clear();
  for (const Line* line : scrolling_lines_) {
    const Fixed scrolled = wrap_sub(map_.sides[size_t(line->side[0])].texture_offset, start_offsets_[size_t(line->side[0])]);
    if (scrolled && state_.scrolled.empty()) state_.scrolled.assign(level_.walls.size(), 0);
    if (!state_.scrolled.empty())
      for (uint32_t w : line_walls_[size_t(line->index)]) state_.scrolled[w] = to_double(scrolled);
  }
  // Textures animate by the level time of the last tic's P_UpdateSpecials.
  if (level_time_ > 0) level::animate_textures(level_, state_, uint64_t(level_time_ - 1));
  state_.things.clear();
  for (const auto& t : thinkers_) {
    if (t->kind != Thinker::Kind::kMobj || t->removed) continue;
    const Mobj& mo = static_cast<const Mobj&>(*t);
    if (&mo == player().mo) continue;  // the view's own body
    if (mo.flags & kNosector) continue;  // in no sector's list: Doom never draws it (teleport destinations)
    level::ShownThing shown;
    shown.pos = {to_double(mo.x), to_double(mo.y)};
    shown.angle = double(mo.angle) * kDegreesPerAngle;
    shown.frame = level_frame(mo);
    shown.placed = mo.spawn_point.placed;
    if (shown.frame == level::kNone && shown.placed != level::kNone)  // a picture of the level's own
      shown.frame = level_.things[size_t(shown.placed)].sprite;
    if (shown.frame == level::kNone) continue;
    shown.sector = mo.subsector->sector->index;
    // A hanging picture hangs from the ceiling as it stands now; anything else stands at its z.
    shown.z = level_.sprite_frames[size_t(shown.frame)].hanging ? level::resting_z(level_, state_, shown.frame, shown.sector)
                                                               : to_double(mo.z);
    shown.flags = uint8_t(((mo.flags & kShadow) ? level::kShownShadow : 0) |
                          (((mo.flags & kTranslation) >> kTranslationShift) << level::kShownTranslationShift));
    state_.things.push_back(shown);
  }
  for (int32_t i : static_things_) {
    const level::Thing& t = level_.things[size_t(i)];
    level::ShownThing shown;
    shown.pos = t.pos;
    shown.angle = t.angle;
    shown.frame = t.sprite;
    shown.sector = t.sector;
    shown.z = level::resting_z(level_, state_, shown.frame, shown.sector);
    shown.placed = i;
    state_.things.push_back(shown);
  }
}

}  // namespace p3d::play
