// Doom's play simulation: a level played by Doom's rules, in Doom's 16.16 fixed
// point with its angle tables, random table and order of calls, so that a Doom demo
// plays as Doom played it. Things (Doom's mobjs) and sector movers are thinkers, run
// in the order they were made, 35 tics a second.
//
// The World is Doom's p_*.c as one class whose members live in files by concern:
//   world.cpp     construction (P_SetupLevel's play part), the tic (P_Ticker), what the renderers see
//   maputl.cpp    geometry and the blockmap: line sides, openings, thing links, path traversal
//   move.cpp      movement and collision (P_CheckPosition, P_TryMove, sliding), hitscans, use, blasts, crushing
//   mobj.cpp      things: spawning, states, momentum, gravity, missiles, removal
//   sight.cpp     line of sight (P_CheckSight: reject table, then the node tree)
//   player.cpp    the player's thrust, view height, death and powers (p_user.c)
//   enemy.cpp     monsters' thinking and every thing action (p_enemy.c)
//   weapons.cpp   the player's weapons (p_pspr.c)
//   interact.cpp  pickups, damage and death (p_inter.c)
//   specials.cpp  lines walked, used and shot, sector specials, animations (p_spec.c, p_switch.c, p_telept.c)
//   movers.cpp    doors, lifts, floors, stairs, ceilings and crushers (p_doors.c, p_plats.c, p_floor.c, p_ceilng.c)
//   lights.cpp    flickering, strobing and glowing sectors (p_lights.c)
//   multiplayer.cpp  netgames: spawn spots, deathmatch starts, respawning, altdeath's items (g_game.c)
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/level/level.h"
#include "engine/play/angle.h"
#include "engine/play/fixed.h"
#include "engine/play/info.h"
#include "engine/play/inventory.h"
#include "engine/play/map.h"
#include "engine/play/random.h"

namespace p3d::play {

constexpr Fixed kGravity = kFracUnit;
constexpr Fixed kMaxMove = 30 * kFracUnit;
constexpr Fixed kFloatSpeed = 4 * kFracUnit;
constexpr Fixed kFloorSpeed = kFracUnit;      // Doom's FLOORSPEED: floors and stairs, a unit a tic
constexpr int kFastDark = 15, kSlowDark = 35;  // strobes' dark tics (Doom's FASTDARK, SLOWDARK)
constexpr Fixed kPlayerRadius = 16 * kFracUnit;
constexpr Fixed kMaxRadius = 32 * kFracUnit;
constexpr Fixed kViewHeight = 41 * kFracUnit;
constexpr Fixed kUseRange = 64 * kFracUnit;
constexpr Fixed kMeleeRange = 64 * kFracUnit;
constexpr Fixed kMissileRange = 32 * 64 * kFracUnit;
constexpr int kBaseThreshold = 100;
constexpr Fixed kOnFloorZ = std::numeric_limits<Fixed>::min();
constexpr Fixed kOnCeilingZ = std::numeric_limits<Fixed>::max();
constexpr int kFullBright = 0x8000;  // a frame's bright bit (Doom's FF_FULLBRIGHT)
constexpr int kFrameMask = 0x7fff;
constexpr int kMtfAmbush = 8;  // a placed thing's deaf flag (Doom's MTF_AMBUSH)
constexpr int kMaxPlayers = 4;  // Doom's MAXPLAYERS

// Doom's multiplayer modes: deathmatch 0 (co-op, or one player), 1 (-deathmatch) or 2
// (-altdeath: items come back 30 seconds after they were taken).
enum class Deathmatch : uint8_t { kNone, kDeathmatch, kAltdeath };

// The game being played (Doom's gameskill, gamemode and the -fast, -respawn and
// -nomonsters options).
struct GameOptions {
  int skill = 3;            // 1..5, as -skill
  bool fast = false, respawn = false, no_monsters = false;
  bool commercial = true;   // Doom II's rules (MAPxx); else Doom's (ExMy)
  bool ultimate = true;     // the fourth episode's rules (Ultimate Doom, Freedoom Phase 1)
  int episode = 1, map = 1;
  // Doom's gametic as the level begins: it counts on through a level started again
  // after the player's death (and A_Tracer steers by it).
  int game_tic = 0;
  // Who plays: Doom's playeringame[], consoleplayer (whose view is shown, whose sounds
  // are heard) and netgame (several players: weapons stay, keys stay, monsters look
  // for others; a dead player respawns in the level rather than the level restarting).
  std::array<bool, kMaxPlayers> in_game{true, false, false, false};
  int console_player = 0;
  bool netgame = false;
  Deathmatch deathmatch = Deathmatch::kNone;
  int time_limit = 0;  // minutes, in deathmatch: the level ends when they have passed (-timer, -avg's 20)
  std::map<std::string, std::string> texts;  // Doom's messages as the WAD rewords them (play/dehacked.h)
};

// One tic of input, Doom's ticcmd_t.
struct TicCmd {
  int8_t forward = 0;  // walk 25, run 50
  int8_t side = 0;     // > 0 to the right
  int16_t turn = 0;    // 1/65536 of a turn, > 0 to the left
  uint8_t buttons = 0;  // Doom's: attack 1, use 2, change weapon 4 with the weapon in bits 3..5, special 128
  uint8_t chatchar = 0;  // a netgame's chat, a character a tic (engine/play/chat.h); no demo holds it
  friend bool operator==(const TicCmd&, const TicCmd&) = default;
};
enum TicButton : uint8_t {
  kBtAttack = 1,
  kBtUse = 2,
  kBtChange = 4,
  kBtWeaponShift = 3,
  kBtWeaponMask = 7 << 3,
  kBtSpecial = 128,
  // With kBtSpecial (Doom's BT_SPECIALMASK 3): what every node does at that tic.
  kBtsPause = 1,
  kBtsSaveGame = 2,
  kBtsSaveShift = 2,         // the save's slot, 0..5
  kBtsSaveMask = 7 << 2,
};

// Everything that thinks: things and the sectors' movers and lights.
struct Thinker {
  enum class Kind : uint8_t { kMobj, kDoor, kFloor, kPlat, kCeiling, kLightFlash, kStrobe, kGlow, kFireFlicker };
  explicit Thinker(Kind k) : kind(k) {}
  virtual ~Thinker() = default;
  Kind kind;
  bool removed = false;  // Doom's function -1: taken out of the list on the next pass
  bool active = true;    // Doom's function NULL: in the list, doing nothing (stopped lifts and crushers)
};

struct Player;

// (What a collision check reads of the things in a cell comes first: one cache line.)
struct Mobj : Thinker {
  Mobj() : Thinker(Kind::kMobj) {}
  Fixed x = 0, y = 0, z = 0;
  uint32_t flags = 0;  // ThingFlag
  Fixed radius = 0, height = 0;
  Mobj *bnext = nullptr, *bprev = nullptr;  // the blockmap cell's list of things
  Mobj *snext = nullptr, *sprev = nullptr;  // the sector's list of things
  Angle angle = 0;
  Sprite sprite = Sprite::kTroo;
  int frame = 0;  // with kFullBright
  Subsector* subsector = nullptr;
  Fixed floor_z = 0, ceiling_z = 0;
  Fixed mom_x = 0, mom_y = 0, mom_z = 0;
  int valid_count = 0;
  ThingType type = ThingType::kPlayer;
  const ThingInfo* info = nullptr;
  int tics = 0;
  StateId state = StateId::kNull;
  int health = 0;
  int move_dir = 0;    // 0..7, or 8 for none (Doom's DI_NODIR)
  int move_count = 0;  // steps before choosing a new direction
  Mobj* target = nullptr;  // what it chases or attacks; a missile's shooter
  int reaction_time = 0;   // tics before it may attack (or move, for a player after a teleport)
  int threshold = 0;       // tics it keeps chasing its attacker before looking for the player again
  Player* player = nullptr;
  int last_look = 0;       // the player it looked at last
  MapThing spawn_point;   // where the map placed it (spawn_point.placed: its level thing), for respawning
  Mobj* tracer = nullptr;  // what a homing missile homes on
  uint32_t id = 0;         // 1, 2, 3... in spawn order: names it as a sound's origin
};

enum class PlayerState : uint8_t { kLive, kDead, kReborn };

// A weapon sprite (Doom's pspdef_t): the weapon, or its flash.
struct Psprite {
  StateId state = StateId::kNull;  // kNull: not shown
  int tics = 0;
  Fixed sx = 0, sy = 0;
};
enum PspriteLayer { kPsWeapon, kPsFlash, kPsCount };

struct Player {
  Mobj* mo = nullptr;
  PlayerState state = PlayerState::kReborn;
  TicCmd cmd;
  Fixed view_z = 0, view_height = 0, delta_view_height = 0, bob = 0;
  Inventory inv;        // health, armor, ammo, weapons (ready and pending), powers, flashes, items
  uint8_t cards = 0;    // the six keys: blue, yellow, red card, blue, yellow, red skull
  bool attack_down = false, use_down = false;
  int cheats = 0;       // kCheatNoclip...
  int refire = 0;       // shots fired in a row (the chaingun and pistol's spread)
  int kill_count = 0, secret_count = 0;  // items: inv.items
  std::string message;  // Doom's message for the player, shown then cleared by the screen
  Mobj* attacker = nullptr;  // who hurt it last (the face looks there)
  int extra_light = 0;       // the gun's flash lights the view
  int fixed_colormap = 0;    // the light amplification visor and invulnerability
  std::array<Psprite, kPsCount> psprites{};
  bool did_secret = false;
  std::array<int, kMaxPlayers> frags{};  // players this one killed (its own entry: deaths by its own hand or the world's)
  int number = 0;                         // 0..3: which player (the colour: green, indigo, brown, red)
};
// The frag count the status bar shows: kills of others minus deaths by one's own hand.
int frag_total(const Player& player);
enum Cheat : int { kCheatNoclip = 1, kCheatGodMode = 2 };

// ---- sector movers (p_spec.h)
struct Door : Thinker {
  enum class Type : uint8_t { kNormal, kClose30ThenOpen, kClose, kOpen, kRaiseIn5Mins, kBlazeRaise, kBlazeOpen, kBlazeClose };
  Door() : Thinker(Kind::kDoor) {}
  Type type = Type::kNormal;
  Sector* sector = nullptr;
  Fixed top_height = 0, speed = 0;
  int direction = 0;  // 1 up, 0 waiting, -1 down, 2 initial wait
  int top_wait = 0, top_countdown = 0;
};
struct Floor : Thinker {
  enum class Type : uint8_t {
    kLower, kLowerToLowest, kTurboLower, kRaise, kRaiseToNearest, kRaiseToTexture, kLowerAndChange,
    kRaise24, kRaise24AndChange, kRaiseCrush, kRaiseTurbo, kDonutRaise, kRaise512,
  };
  Floor() : Thinker(Kind::kFloor) {}
  Type type = Type::kLower;
  bool crush = false;
  Sector* sector = nullptr;
  int direction = 0;
  int new_special = 0;
  int texture = level::kNone;
  Fixed destination = 0, speed = 0;
};
struct Plat : Thinker {
  enum class Status : uint8_t { kUp, kDown, kWaiting, kInStasis };
  enum class Type : uint8_t { kPerpetualRaise, kDownWaitUpStay, kRaiseAndChange, kRaiseToNearestAndChange, kBlazeDwus };
  Plat() : Thinker(Kind::kPlat) {}
  Sector* sector = nullptr;
  Fixed speed = 0, low = 0, high = 0;
  int wait = 0, count = 0;
  Status status = Status::kUp, old_status = Status::kUp;
  bool crush = false;
  int tag = 0;
  Type type = Type::kPerpetualRaise;
};
struct Ceiling : Thinker {
  enum class Type : uint8_t { kLowerToFloor, kRaiseToHighest, kLowerAndCrush, kCrushAndRaise, kFastCrushAndRaise, kSilentCrushAndRaise };
  Ceiling() : Thinker(Kind::kCeiling) {}
  Type type = Type::kLowerToFloor;
  Sector* sector = nullptr;
  Fixed bottom_height = 0, top_height = 0, speed = 0;
  bool crush = false;
  int direction = 0, tag = 0, old_direction = 0;
};
struct LightFlash : Thinker {
  LightFlash() : Thinker(Kind::kLightFlash) {}
  Sector* sector = nullptr;
  int count = 0, max_light = 0, min_light = 0, max_time = 0, min_time = 0;
};
struct Strobe : Thinker {
  Strobe() : Thinker(Kind::kStrobe) {}
  Sector* sector = nullptr;
  int count = 0, min_light = 0, max_light = 0, dark_time = 0, bright_time = 0;
};
struct Glow : Thinker {
  Glow() : Thinker(Kind::kGlow) {}
  Sector* sector = nullptr;
  int min_light = 0, max_light = 0, direction = 0;
};
struct FireFlicker : Thinker {
  FireFlicker() : Thinker(Kind::kFireFlicker) {}
  Sector* sector = nullptr;
  int count = 0, max_light = 0, min_light = 0;
};

// A sound a tic started: from a thing or a sector's sound origin (origin names which,
// so that a new sound from it replaces the old), or from nowhere (origin 0: the
// player's own pickups, heard at full volume).
struct SoundEvent {
  Sound sound = Sound::kNone;
  uint64_t origin = 0;
  Fixed x = 0, y = 0;
  friend bool operator==(const SoundEvent&, const SoundEvent&) = default;
};
// Origins of sector sounds are kSectorOrigin + the sector's index; things' are their id.
constexpr uint64_t kSectorOrigin = uint64_t(1) << 40;

enum class ExitKind : uint8_t { kNone, kNormal, kSecret };

// Who plays a demo and how (its players, console player, netgame and deathmatch, and
// -fast, -respawn, -nomonsters), set on the game's options.
struct DoomDemo;
void set_demo_game(GameOptions& options, const DoomDemo& demo);

// Doom's game for a map of a WAD stack: Doom II's rules for MAPxx, Doom's (with the
// fourth episode's when the WADs have E4M1) for ExMy, the map's numbers, the IWAD's
// DEHACKED wording of the messages.
GameOptions game_options_for(const wad::Stack& wads, const std::string& map_name, int skill);

class World {
 public:
  // The level at its start (Doom's P_SetupLevel): things spawned in THINGS order,
  // then the sector specials, drawing from `random` as Doom does (the stream goes on
  // from level to level). `carried`: the players as they come from the last level
  // (players_for_next_level); nullptr: new players, as Doom's G_PlayerReborn makes them.
  World(Map map, const level::Level& level, const GameOptions& options, Random random,
        const std::array<Player, kMaxPlayers>* carried = nullptr);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // One tic (Doom's P_Ticker): the player thinks, every thinker runs, the specials
  // update. Then state() shows the level as it stands.
  void tick(const TicCmd& cmd);
  // One tic with each player's command (the entries of players not in the game are
  // ignored). In a netgame, a player who asked to be reborn comes back first (Doom's
  // G_DoReborn in G_Ticker); in a single-player game the caller starts the level again.
  void tick_players(const std::array<TicCmd, kMaxPlayers>& cmds);

  // The level as it stands, for the renderers: brought up to date when asked (ticks
  // that nobody draws cost nothing here).
  const level::State& state() const {
    if (stale_) show();
    return state_;
  }
  // The console player (the one whose view is shown).
  const Player& player() const { return players_[size_t(options_.console_player)]; }
  Player& player() { return players_[size_t(options_.console_player)]; }
  const Player& player(int n) const { return players_[size_t(n)]; }
  Player& player(int n) { return players_[size_t(n)]; }
  // Every player as Doom's next level takes them: G_PlayerFinishLevel (powers, keys and
  // flashes left behind), G_DoLoadLevel (frags cleared, the dead to be reborn) and
  // P_SetupLevel (counts cleared); health, armor, weapons, ammo, the buttons held and
  // the cheats go on. None of this level's things.
  std::array<Player, kMaxPlayers> players_for_next_level() const;
  bool in_game(int n) const { return options_.in_game[size_t(n)]; }
  // The deathmatch starts Doom keeps (the first ten of the map's: vanilla's array).
  const std::vector<MapThing>& deathmatch_starts() const { return deathmatch_starts_; }
  // Tics left before a deathmatch's time limit ends the level (0: no limit).
  int time_left() const { return level_timer_; }
  // The height of the player's eye, for drawing. Doom draws only after a tic (the
  // first one computes view_z, until then 0 for a new player, 1 for one carried over);
  // a frame drawn before it sees from where that tic puts a player at rest.
  Fixed eye_z() const;
  const Map& map() const { return map_; }
  const GameOptions& options() const { return options_; }
  const Random& random() const { return random_; }
  int level_time() const { return level_time_; }
  // Doom's gametic: the tics of the game so far, not of this level alone.
  int game_tic() const { return int(uint32_t(game_tic_at_start_) + uint32_t(level_time_)); }
  // Set once the player takes an exit (Doom's G_ExitLevel, G_SecretExitLevel).
  ExitKind exit() const { return exit_; }
  // The level's totals, for the tally.
  int total_kills() const { return total_kills_; }
  int total_items() const { return total_items_; }
  int total_secrets() const { return total_secrets_; }
  // The sounds started and the messages given during the last tic, in order.
  const std::vector<SoundEvent>& sounds() const { return sounds_; }
  const std::vector<std::string>& messages() const { return messages_; }
  // Whether the console player came back into the level during the last tic (a
  // netgame's reborn): Doom's P_SpawnPlayer then starts its status bar and message
  // line afresh (ST_Start, HU_Start).
  bool console_player_spawned() const { return console_spawned_; }
  // Empty, or what this level did first that Chocolate Doom leaves undefined (vanilla
  // overran its memory further than Chocolate emulates): a replay beside Chocolate may
  // part from that tic on, and no port can say which is right.
  const std::string& beyond_chocolate() const { return beyond_chocolate_; }
  // Each player's x as the last tic began (after the dead came back, before anyone
  // moved), or nullopt without a body: what a netgame's commands carry 128 tics later
  // for G_Ticker's consistency check.
  const std::array<std::optional<Fixed>, kMaxPlayers>& tic_start_x() const { return tic_start_x_; }
  // A netgame's player n left (Doom's PlayerQuitGame): no longer in the game, its body
  // left standing, "Player N left the game" said to the console player.
  void player_left(int n);
  // Puts the player at (x, y) facing `angle` (a start other than the map's), on the floor there.
  void place_player(Fixed x, Fixed y, Angle angle);
  // Our cheats (play/demo.h's DemoCheat bits): noclip, god mode, every weapon, ammo and key.
  void apply_cheats(uint8_t cheats);
  // Every monster at once hunting the player, as if it had seen it (A_Look's waking:
  // the target set, the see state entered); for benchmarks and tests. Returns how many.
  int wake_monsters();
  // The thing of this id (SoundEvent::origin), or nullptr once it is removed.
  const Mobj* thing(uint32_t id) const;
  // Every thing, in thinker order (removed ones left out).
  std::vector<const Mobj*> things() const;
  size_t thinker_count() const;

  // ---- world.cpp
  void run_thinkers();
  void add_thinker(std::unique_ptr<Thinker> t);
  template <typename T>
  T* make_thinker() {
    auto t = std::make_unique<T>();
    T* raw = t.get();
    add_thinker(std::move(t));
    return raw;
  }
  void remove_thinker(Thinker* t) {
    t->removed = true;
    ++removed_since_pass_;
  }
  void show() const;  // state_ from the map and the things
  void start_sound(const Mobj* origin, Sound sound);
  void start_sector_sound(const Sector* sector, Sound sound);
  void stop_sound(const Mobj* origin);  // Doom's S_StopSound (a no-op for play)
  void say(std::string message);        // the console player's message
  void say(Player& player, std::string message);  // a player's (only the console player's is heard and shown)
  bool is_console(const Player& player) const { return &player == &players_[size_t(options_.console_player)]; }
  void exit_level(bool secret);
  void index_walls();          // line_walls_ and the sides' starting offsets
  void index_sprite_frames();  // sprite_frames_
  int32_t level_frame(const Mobj& mo) const;  // the level's sprite frame a thing shows, or kNone
  // A line whose special or side textures may change this tic: show() draws it anew (and
  // every line sharing a side with it).
  void mark_line(const Line* line) { changed_lines_.push_back(line->index); }
  void show_line(size_t line) const;
  void index_static_things();  // static_things_

  // ---- maputl.cpp
  struct DivLine {
    Fixed x = 0, y = 0, dx = 0, dy = 0;
  };
  struct Intercept {
    Fixed frac = 0;
    bool is_line = false;
    Mobj* thing = nullptr;
    Line* line = nullptr;
  };
  struct Opening {
    Fixed top = 0, bottom = 0, range = 0, low_floor = 0;
  };
  static int point_on_line_side(Fixed x, Fixed y, const Line& line);
  static int box_on_line_side(const Box& box, const Line& line);
  static int point_on_divline_side(Fixed x, Fixed y, const DivLine& line);
  static DivLine make_divline(const Line& line);
  static Fixed intercept_vector(const DivLine& v2, const DivLine& v1);
  // Doom's P_LineOpening: the gap between the line's two sectors. Doom keeps it in
  // globals, and a line flagged two-sided without a back side leaves top, bottom and
  // low floor as the last line left them (range 0), where shots and aims then look.
  const Opening& line_opening(const Line& line);
  void unset_thing_position(Mobj* thing);
  void set_thing_position(Mobj* thing);
  // Doom's P_BlockLinesIterator and P_BlockThingsIterator: f returns false to stop;
  // so do they.
  template <typename F>
  bool block_lines(int bx, int by, F&& f);
  template <typename F>
  bool block_things(int bx, int by, F&& f);
  enum PathFlags { kAddLines = 1, kAddThings = 2, kEarlyOut = 4 };
  // Doom's P_PathTraverse: the lines and things the trace meets, nearest first; trav
  // returns false to stop. `trace_` holds the trace meanwhile.
  bool path_traverse(Fixed x1, Fixed y1, Fixed x2, Fixed y2, int flags, const std::function<bool(Intercept&)>& trav);
  int block_x(Fixed x) const { return wrap_sub(x, map_.blockmap.origin_x) >> kMapBlockShift; }
  int block_y(Fixed y) const { return wrap_sub(y, map_.blockmap.origin_y) >> kMapBlockShift; }
  // Cell (bx, by)'s number as Doom computes it (x + y * width), or kOffTheMap.
  static constexpr size_t kOffTheMap = SIZE_MAX;
  size_t block_cell(int bx, int by) const;
  // The cell's list of things (Doom's blocklinks[cell]), or nullptr off the map.
  Mobj** block_link(int bx, int by);
  // Vanilla Doom's intercepts overrun, as Chocolate Doom emulates it: intercept `index`
  // past the 128 that vanilla held, written over the globals that followed the array.
  void overrun_intercepts(size_t index);
  void overrun_write(int location, int32_t value);
  void note_beyond_chocolate(const std::string& what);

  // ---- move.cpp (p_map.c)
  void start_position_check(Mobj* thing, Fixed x, Fixed y);
  bool check_position(Mobj* thing, Fixed x, Fixed y);
  bool try_move(Mobj* thing, Fixed x, Fixed y);
  bool teleport_move(Mobj* thing, Fixed x, Fixed y);
  void slide_move(Mobj* mo);
  bool thing_height_clip(Mobj* thing);
  Fixed aim_line_attack(Mobj* shooter, Angle angle, Fixed distance);  // sets line_target_
  void line_attack(Mobj* shooter, Angle angle, Fixed distance, Fixed slope, int damage);
  void use_lines(Player& player);
  void radius_attack(Mobj* spot, Mobj* source, int damage);
  bool change_sector(Sector* sector, bool crunch);

  // ---- mobj.cpp (p_mobj.c)
  // The game's state table and thing types (Doom's states[] and mobjinfo[], which -fast
  // and nightmare change: faster demons and imp, baron and cacodemon missiles).
  const StateInfo& state_of(StateId s) const { return states_[size_t(s)]; }
  const ThingInfo& info_of(ThingType t) const { return thing_info_[size_t(t)]; }
  bool set_mobj_state(Mobj* mo, StateId state);
  void explode_missile(Mobj* mo);
  void xy_movement(Mobj* mo);
  void z_movement(Mobj* mo);
  void nightmare_respawn(Mobj* mo);
  void mobj_thinker(Mobj* mo);
  Mobj* spawn_mobj(Fixed x, Fixed y, Fixed z, ThingType type);
  void remove_mobj(Mobj* mo);
  // An item taken (not one a monster dropped, nor the invulnerability and invisibility
  // spheres) queues its spot for altdeath's respawning; the 129th loses the oldest.
  void queue_item_respawn(const Mobj& mo);
  void spawn_player(const MapThing& start);
  // g_game.c's spawning of players in a netgame: G_CheckSpot, G_DeathMatchSpawnPlayer, G_DoReborn.
  bool check_spot(int player, const MapThing& spot);
  void deathmatch_spawn_player(int player);
  void reborn_in_netgame(int player);
  void respawn_specials();  // P_RespawnSpecials: altdeath's items come back
  void spawn_map_thing(const MapThing& mt);
  void spawn_puff(Fixed x, Fixed y, Fixed z);
  void spawn_blood(Fixed x, Fixed y, Fixed z, int damage);
  void check_missile_spawn(Mobj* th);
  Mobj* spawn_missile(Mobj* source, Mobj* dest, ThingType type);
  void spawn_player_missile(Mobj* source, ThingType type);

  // ---- sight.cpp
  bool check_sight(Mobj* t1, Mobj* t2);

  // ---- player.cpp (p_user.c)
  void thrust(Player& player, Angle angle, Fixed move);
  void calc_height(Player& player);
  void move_player(Player& player);
  void death_think(Player& player);
  void player_think(Player& player);
  void reborn_player(Player& player);  // Doom's G_PlayerReborn: a fresh player, keeping the level's counts and frags
  void choose_weapon(Player& player, Weapon weapon);  // the weapon keys
  void run_down_powers(Player& player);

  // ---- enemy.cpp (p_enemy.c): monsters, and the action of every thing state
  void act(Mobj* mo, Action action);  // a state's action, on entering it
  void noise_alert(Mobj* target, Mobj* emitter);
  bool check_melee_range(Mobj* actor);
  bool check_missile_range(Mobj* actor);
  bool move(Mobj* actor);
  bool try_walk(Mobj* actor);
  void new_chase_dir(Mobj* actor);
  bool look_for_players(Mobj* actor, bool all_around);

  // ---- weapons.cpp (p_pspr.c)
  void act_weapon(Player& player, Psprite& psp, Action action);  // a weapon state's action
  void set_psprite(Player& player, int layer, StateId state);
  void bring_up_weapon(Player& player);
  bool check_ammo(Player& player);
  void fire_weapon(Player& player);
  void drop_weapon(Player& player);
  void setup_psprites(Player& player);
  void move_psprites(Player& player);
  void bfg_spray(Mobj* mo);  // the BFG ball's A_BFGSpray (a thing action)

  // ---- interact.cpp (p_inter.c)
  void touch_special_thing(Mobj* special, Mobj* toucher);
  void kill_mobj(Mobj* source, Mobj* target);
  void damage_mobj(Mobj* target, Mobj* inflictor, Mobj* source, int damage);

  // ---- specials.cpp (p_spec.c, p_switch.c, p_telept.c)
  Side* get_side(int sector, int line, int side);
  Sector* get_sector(int sector, int line, int side);
  bool two_sided(int sector, int line);
  Sector* get_next_sector(Line* line, Sector* sector);
  Fixed find_lowest_floor_surrounding(Sector* sec);
  Fixed find_highest_floor_surrounding(Sector* sec);
  Fixed find_next_highest_floor(Sector* sec, Fixed current);
  Fixed find_lowest_ceiling_surrounding(Sector* sec);
  Fixed find_highest_ceiling_surrounding(Sector* sec);
  int find_sector_from_line_tag(const Line* line, int start);
  int find_min_surrounding_light(Sector* sector, int max);
  void cross_special_line(int line, int side, Mobj* thing);
  void shoot_special_line(Mobj* thing, Line* line);
  bool use_special_line(Mobj* thing, Line* line, int side);
  void player_in_special_sector(Player& player);
  void update_specials();
  void spawn_specials();
  bool do_donut(Line* line);
  void change_switch_texture(Line* line, bool use_again);
  bool teleport(Line* line, int side, Mobj* thing);

  // ---- movers.cpp (p_doors.c, p_plats.c, p_floor.c, p_ceilng.c)
  enum class MoveResult : uint8_t { kOk, kCrushed, kPastDest };
  MoveResult move_plane(Sector* sector, Fixed speed, Fixed dest, bool crush, int floor_or_ceiling, int direction);
  void think_door(Door* door);
  bool do_door(Line* line, Door::Type type);
  bool do_locked_door(Line* line, Door::Type type, Mobj* thing);
  void vertical_door(Line* line, Mobj* thing);
  void spawn_door_close_in_30(Sector* sec);
  void spawn_door_raise_in_5_mins(Sector* sec);
  void think_plat(Plat* plat);
  bool do_plat(Line* line, Plat::Type type, int amount);
  void activate_in_stasis(int tag);
  void stop_plat(Line* line);
  void think_floor(Floor* floor);
  bool do_floor(Line* line, Floor::Type type);
  bool build_stairs(Line* line, bool turbo);
  void think_ceiling(Ceiling* ceiling);
  bool do_ceiling(Line* line, Ceiling::Type type);
  bool ceiling_crush_stop(Line* line);
  void activate_in_stasis_ceiling(Line* line);

  // ---- lights.cpp (p_lights.c)
  void think_light_flash(LightFlash* flash);
  void think_strobe(Strobe* strobe);
  void think_glow(Glow* glow);
  void think_fire_flicker(FireFlicker* flicker);
  void spawn_fire_flicker(Sector* sector);
  void spawn_light_flash(Sector* sector);
  void spawn_strobe_flash(Sector* sector, int fast_or_slow, bool in_sync);
  void spawn_glowing_light(Sector* sector);
  void start_light_strobing(Line* line);
  void turn_tag_lights_off(Line* line);
  void light_turn_on(Line* line, int bright);

  // ---- state shared by the files above, as Doom's globals were
  Map map_;
  const level::Level& level_;
  GameOptions options_;
  Random random_;
  std::array<Player, kMaxPlayers> players_;
  // Netgames (g_game.c, p_mobj.c): the map's starts, the corpses left by respawning
  // players, the items taken (for altdeath), the deathmatch's clock.
  std::array<MapThing, kMaxPlayers> player_starts_{};
  std::vector<MapThing> deathmatch_starts_;
  static constexpr size_t kDeathmatchStarts = 10;  // Doom's array: later starts are not used
  std::vector<Mobj*> body_queue_;  // Doom's bodyque: the last kBodyQueueSize corpses
  size_t body_queue_slot_ = 0;
  static constexpr size_t kBodyQueueSize = 32;  // Doom's BODYQUESIZE: the 33rd corpse removes the first
  // Doom's itemrespawnque: a ring of kItemQueueSize spots; when full, the oldest is lost
  // (Doom's rule, kept for sync).
  static constexpr size_t kItemQueueSize = 128;
  std::array<MapThing, kItemQueueSize> item_queue_{};
  std::array<int, kItemQueueSize> item_queue_time_{};
  size_t item_queue_head_ = 0, item_queue_tail_ = 0;
  int level_timer_ = 0;  // tics left, or 0 (Doom's levelTimer and levelTimeCount)
  std::vector<StateInfo> states_;
  std::vector<ThingInfo> thing_info_;
  bool respawn_monsters_ = false;  // nightmare or -respawn
  bool on_ground_ = false;  // player.cpp: the player stood on the floor when it last moved (Doom's onground)
  int level_time_ = 0;
  int valid_count_ = 1;
  std::vector<Mobj*> block_links_;  // per blockmap cell: its things (Doom's blocklinks)
  // move.cpp's P_CheckPosition results (Doom's tm* globals)
  struct MoveCheck {
    Mobj* thing = nullptr;
    uint32_t flags = 0;
    Fixed x = 0, y = 0;
    Box bbox{};
    Fixed floor_z = 0, ceiling_z = 0, dropoff_z = 0;
    bool float_ok = false;
    Line* ceiling_line = nullptr;
    std::vector<Line*> special_hits;  // lines with specials touched (Doom's spechit)
  } tm_;
  std::string beyond_chocolate_;  // what the first tic beyond Chocolate Doom's emulation did
  std::array<std::optional<Fixed>, kMaxPlayers> tic_start_x_{};
  Opening opening_;  // the last line_opening (Doom's opentop, openbottom, openrange, lowfloor)
  // Hitscans (P_AimLineAttack, P_LineAttack)
  Mobj* line_target_ = nullptr;
  Mobj* shoot_thing_ = nullptr;
  Fixed shoot_z_ = 0, attack_range_ = 0, aim_slope_ = 0, top_slope_ = 0, bottom_slope_ = 0;
  int la_damage_ = 0;
  // Sliding (P_SlideMove)
  Fixed best_slide_frac_ = 0, second_slide_frac_ = 0;
  Line *best_slide_line_ = nullptr, *second_slide_line_ = nullptr;
  Mobj* slide_mo_ = nullptr;
  Fixed tm_xmove_ = 0, tm_ymove_ = 0;
  // Blasts and crushing
  Mobj *bomb_source_ = nullptr, *bomb_spot_ = nullptr;
  int bomb_damage_ = 0;
  bool crush_change_ = false, no_fit_ = false;
  // Path traversal
  DivLine trace_;
  std::vector<Intercept> intercepts_;
  // Monsters
  Mobj* sound_target_ = nullptr;  // P_NoiseAlert's
  std::vector<Mobj*> brain_targets_;  // the icon of sin's spawn spots
  size_t brain_target_on_ = 0;
  bool brain_easy_ = false;
  int game_tic_at_start_ = 0;  // Doom's gametic when this level began (A_Tracer goes by gametic, not leveltime)
  Mobj* corpse_hit_ = nullptr;  // the Arch-vile's
  Fixed vile_try_x_ = 0, vile_try_y_ = 0;
  Mobj* vile_obj_ = nullptr;
  Fixed bullet_slope_ = 0;  // weapons.cpp
  // Specials
  std::vector<Line*> scrolling_lines_;  // special 48
  struct Button {
    Line* line = nullptr;
    int where = 0;  // 0 top, 1 middle, 2 bottom
    int texture = level::kNone;
    int timer = 0;
    const Sector* sound_sector = nullptr;
  };
  std::vector<Button> buttons_;
  std::vector<int> switch_partner_;  // per level texture: its switch pair, or kNone
  std::vector<Plat*> active_plats_;
  std::vector<Ceiling*> active_ceilings_;
  std::vector<std::vector<uint32_t>> line_walls_;  // per line: the level's walls drawn for it
  std::vector<Fixed> start_offsets_;                // per side: its texture offset at the start (scrolling)
  std::vector<std::vector<int>> side_lines_;        // per side: the lines it is a side of
  mutable std::vector<int> changed_lines_;          // mark_line's, since the last show()
  int total_kills_ = 0, total_items_ = 0, total_secrets_ = 0;
  ExitKind exit_ = ExitKind::kNone;
  uint32_t next_id_ = 1;
  std::vector<std::unique_ptr<Thinker>> thinkers_;  // in run order; removed ones kept until the level ends
  std::vector<std::unique_ptr<Thinker>> graveyard_;  // removed things others may still point at
  size_t removed_since_pass_ = 0;
  std::vector<SoundEvent> sounds_;
  std::vector<std::string> messages_;
  bool console_spawned_ = false;
  mutable level::State state_;
  mutable bool stale_ = true;  // state_ is behind the map
  // Placed things Doom does not know (a .map level's own types) that have a picture:
  // shown where they stand, never acting.
  std::vector<int32_t> static_things_;
  std::vector<std::vector<int32_t>> sprite_frames_;  // per Sprite: per frame (bright in the top half) the level's frame, or kNone
};

// ---- the templates of maputl.cpp

template <typename F>
bool World::block_lines(int bx, int by, F&& f) {
  const size_t cell = block_cell(bx, by);
  if (cell == kOffTheMap) return true;
  if (cell >= map_.blockmap.offsets.size()) {
    note_beyond_chocolate("lines of blockmap cell " + std::to_string(cell) + ", past the blockmap's offsets");
    return true;
  }
  for (const uint32_t* at = map_.blockmap.list(cell); *at != Blockmap::kEnd; ++at) {
    int& mark = map_.line_marks[*at];
    if (mark == valid_count_) continue;  // already checked in another cell
    mark = valid_count_;
    if (!f(&map_.lines[*at])) return false;
  }
  return true;
}

template <typename F>
bool World::block_things(int bx, int by, F&& f) {
  Mobj** link = block_link(bx, by);
  if (!link) return true;
  for (Mobj* mo = *link; mo; mo = mo->bnext)
    if (!f(mo)) return false;
  return true;
}

}  // namespace p3d::play
