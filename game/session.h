// One game: the level (compiled on the fly from a source if need be), Doom's play
// simulation on it, the player's view at this tic and the previous one (for
// interpolation), the renderers, what Doom draws around the view (status bar,
// weapon, messages, tally), sounds, and demo recording. Shared by the window and the
// headless replay; no SDL here.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/bsp/load.h"
#include "engine/front/back_screen.h"
#include "engine/level/level.h"
#include "engine/play/demo.h"
#include "engine/play/hud_font.h"
#include "engine/play/chat.h"
#include "engine/play/intermission.h"
#include "engine/play/tally_count.h"
#include "engine/play/music.h"
#include "engine/play/sound.h"
#include "engine/play/status_bar.h"
#include "engine/play/weapon_view.h"
#include "engine/play/world.h"
#include "engine/render/renderer.h"
#include "engine/wad/art.h"
#include "engine/wad/wad.h"
#include "game/automap.h"
#include "game/file_watch.h"
#include "game/hud.h"
#include "game/menu.h"
#include "game/sound_bank.h"

namespace p3d::game {

constexpr int kTicRate = 35;

// The renderers on keys F5 to F9.
const std::vector<std::string>& key_renderers();

// Doom's -fast, -respawn and -nomonsters; -deathmatch (1) or -altdeath (2) with
// -timer's minutes (-avg: 20); who plays (a demo's players and console player; a
// game played here has player 1 alone).
struct GameFlags {
  bool fast = false, respawn = false, no_monsters = false;
  int deathmatch = 0, time_limit = 0;
  std::array<bool, play::kMaxPlayers> players{true, false, false, false};
  int console_player = 0;
};
// The game a Doom demo was recorded in.
GameFlags flags_of(const play::DoomDemo& demo);

class Session {
 public:
  static constexpr int kCompactWidth = 480;  // narrower frames get a one-line heads-up text

  explicit Session(const bsp::LevelSource& source, int skill = level::kDefaultSkill, GameFlags flags = {});
  explicit Session(const std::filesystem::path& map_path) : Session(bsp::LevelSource{map_path, {}, {}}) {}

  const level::Level& level() const { return *level_; }
  const level::State& state() const { return world_->state(); }
  const play::World& world() const { return *world_; }
  // The level's name for messages: its file, or "<wad>:<map>".
  const std::string& name() const { return name_; }
  std::string title() const;
  // The files a reload reads: the source, or the WADs.
  std::vector<std::filesystem::path> files() const;
  int skill() const { return skill_; }
  const bsp::LevelSource& source() const { return source_; }
  // The WAD map played ("MAP01", "E1M1"), or empty for a level that is no WAD's map.
  std::string map_name() const;
  const GameFlags& flags() const { return flags_; }

  // ---- simulation
  // The player moved to another start than the map's (a demo's or a route's).
  void spawn(geom::Vec2 pos, double angle);
  // One tic; what happened shows as messages. After an exit, exited() tells which.
  void tic(const play::DemoTic& tic);
  void tic(const play::TicCmd& cmd) { tic(play::DemoTic{cmd, 0}); }
  play::ExitKind exited() const { return world_->exit(); }
  // The level ends here as if its exit were taken (Doom's G_ExitLevel), for tests and
  // scripts that need the finale or the tally without walking there.
  void end_level(bool secret) { world_->exit_level(secret); }
  // Doom's M_Random, which the status bar's face and the screen's melt draw from.
  play::Random& screen_random() { return other_random_; }
  // A netgame's chat: what our player types (its characters go out in our commands),
  // and the other players' lines, shown on the message line as their tics arrive.
  play::Chat& chat() { return chat_; }
  const play::Chat& chat() const { return chat_; }
  // A netgame's pause and saves travel in the commands (Doom's BT_SPECIAL): each node
  // pauses its world, or saves, at the tic one arrives, whoever sent it. The slot a
  // save was asked for, once: the caller saves it before the next tic (Doom's
  // ga_savegame).
  bool paused() const { return paused_; }
  std::optional<int> take_save_request() { return std::exchange(save_request_, std::nullopt); }
  // The message line now ("" when it has faded).
  std::string message() const { return message_tics_ > 0 ? message_ : std::string(); }
  // A tic in which the world waits (a menu open, or paused): what Doom's status bar
  // and message line do every tic still happens (the face glances, messages fade).
  void idle_tic();
  // Loads the map the exit leads to in Doom's order, the player at its start with what
  // it carried (Doom's G_PlayerFinishLevel). When there is none (a hand-made level, the
  // end of an episode or game, a map missing from the WADs), starts this level again
  // and returns false.
  bool enter_next_map();
  // The map an exit leads to in Doom's order, or empty (with the reason in `why`).
  std::string next_map_name(std::string* why = nullptr) const;
  // Doom's intermission after an exit: the tally of the level just finished, counted
  // up by the tics that follow (engine/play/tally_count.h: every player's presses
  // hurry it) and drawn by render() in place of the view, until intermission_over()
  // says the next map is due. False (nothing shown) where the WADs have no
  // intermission art.
  bool start_intermission();
  bool in_intermission() const { return tally_count_.has_value(); }
  bool intermission_over() const { return tally_count_ && tally_count_->over(); }
  // Kills, items and secrets of the level so far, and its time.
  play::Tally tally() const;
  // Every key at every start (--all-keys).
  void give_all_keys(bool all) {
    all_keys_ = all;
    set_keys(all ? 63 : 0);
  }
  void set_keys(uint8_t keys) { world_->player().cards = keys; }
  const play::Player& player() const { return world_->player(); }
  // The player's eye and feet as the shells see them: map units, degrees.
  struct Pose {
    geom::Vec2 pos;
    double z = 0, view_z = 0, angle = 0;
  };
  Pose pose() const { return pose_; }
  uint64_t tics() const { return tics_; }
  // A netgame demo's other players: each tic() plays their next commands beside the
  // console player's.
  void play_other_players(const play::DoomDemo& demo);
  // A netgame's other players: the next tic() plays these commands beside ours.
  void queue_other_players(const std::array<play::TicCmd, play::kMaxPlayers>& cmds) { others_.push_back(cmds); }
  // The last tic's command of every player: tic() takes each tic's whatever the screen
  // (the level, the tally, a finale waiting), the console player's given and the others'
  // queued, as Doom's G_Ticker reads every player's every tic.
  const std::array<play::TicCmd, play::kMaxPlayers>& last_commands() const { return last_commands_; }
  // Whether any player in the game pressed a button this tic (what Doom's F_Ticker asks).
  bool any_button() const;
  // The episode (0 for Doom II's MAPxx) and number of the WAD map played; false for a
  // level that is no Doom map.
  bool doom_map_numbers(int& episode, int& number) const;
  // A netgame's player left (Doom's PlayerQuitGame, before the tic): a recording ends there.
  void player_left(int player);
  // The camera between the previous tic (alpha 0) and this one (alpha 1).
  render::Camera camera(double alpha) const;

  // ---- sound
  // A sound the last tics started: from a point (map units) or from the player
  // (nullopt); origin tells sound makers apart.
  struct PlacedSound {
    play::Sound sound;
    uint64_t origin;
    std::optional<geom::Vec2> at;
  };
  // From now on, keep the sounds the tics start for take_sounds (the window's audio
  // listens; headless runs do not, and keep none).
  void listen() { listening_ = true; }
  // The sounds started since the last call, in order.
  std::vector<PlacedSound> take_sounds() { return std::exchange(sounds_, {}); }
  // A sound's samples from the level's WADs; nullptr for levels without WADs, or a
  // lump missing or broken (said once on stderr).
  const play::SoundClip* sound_clip(play::Sound sound);
  // Where the player hears from.
  play::Listener listener() const;
  // Where a sound's maker stands now (a sector's sound origin, or a thing), or nullopt
  // once the thing is gone.
  std::optional<geom::Vec2> sound_origin(uint64_t origin) const;

  // ---- music (the window's MusicPlayer plays it)
  // What Doom plays now (engine/play/music.h): the map's track, or the intermission's
  // during the tally; kNone for a level that is no Doom map.
  play::Track music() const { return in_intermission() ? tally_music_ : map_music_; }

  // ---- rendering
  // Switches renderer; false (with a message) if it cannot draw this level. `announce`:
  // say which renderer now draws (a key pressed), not at the start.
  bool select_renderer(const std::string& name, bool announce = true);
  render::RendererOptions renderer_options;  // for the renderers select_renderer makes
  const std::string& renderer_name() const { return renderer_name_; }
  const render::RenderStats& render(render::Frame& frame, double alpha);
  // The rows Doom's status bar takes at the bottom of such a frame (0: none shown).
  int status_bar_rows(const render::Frame& frame) const;
  // Which of the WAD's palettes the screen shows now: 0, or Doom's flash (red when
  // hurt or berserk, gold after a pickup, green in the radiation suit).
  int flash_palette() const;
  void draw_overlays(render::Frame& frame, const FrameTimes& times, double alpha) const;

  // ---- what the keys toggle
  bool show_automap = false, show_hud = false, show_help = false;
  bool show_status_bar = true;  // Doom's, along the bottom, on levels whose WADs have its art
  int screen_blocks = 10;       // Doom's screen size: 3..9 a smaller view in a border, 11 no status bar
  bool low_detail = false;      // Doom's low detail: columns twice as wide (each pair shows its left one)
  bool show_messages = true;    // the rules' messages (pickups...); say() always shows
  bool menu_over_border = false;  // a menu is open: Doom's border, redrawn, hides the message line
  AutomapSettings automap;
  Menu menu;
  double fov = 90;
  void say(const std::string& text);  // a message shown on screen for a few seconds
  void advance_message();             // once per tic

  // ---- savegames: Doom's format (Chocolate Doom's layout) with our extension, which
  // makes a loaded save go on exactly as the game it was saved from (engine/play/savegame.h)
  // The game as a savegame's bytes. Throws Error when Doom's format cannot hold it (a
  // level that is no WAD's MAPxx or ExMy) or the level is over.
  std::vector<uint8_t> save_game(const std::string& description) const;
  // Replaces the game by the save's (its map from the session's WADs, its skill), as
  // Doom's G_DoLoadGame does, then puts back what our extension keeps unless doom_only
  // (Chocolate Doom's load). Throws Error("<what>: byte N: ...") and leaves the game as
  // it was for a save it cannot load.
  void load_game(std::span<const uint8_t> bytes, const std::string& what, bool doom_only = false);
  // A save's description, for a load menu's slots; nullopt when the bytes are no Doom save.
  static std::optional<std::string> save_description(std::span<const uint8_t> bytes);

  // ---- demos and reloading
  // Records every tic from now. With doom_turns, turns are rounded as a Doom demo
  // keeps them, before they are played, so a Doom demo of the recording replays it;
  // with long_tics they stay whole, and a .lmp is written with Doom v1.91's long tics.
  void start_recording(bool doom_turns = false, bool long_tics = false);
  const play::Demo& recording() const { return recording_; }
  // The recording in the format the file's name asks for: Doom v1.9 (or v1.91's long
  // tics, as recorded) for .lmp (of a
  // WAD map), ours otherwise. Throws Error for a .lmp of a level that is no Doom map.
  std::vector<uint8_t> encode_recording(const std::filesystem::path& path) const;
  // Recompiles the map from disk and starts it again, keeping the player where it
  // stands if that point is still inside the level (else at the new start). False
  // (and a message, the old level kept) if the new map does not compile. Both
  // outcomes are also said on stderr.
  bool reload();
  // --map-reload: watch the level's files; reload_if_saved, called every frame with a
  // monotonic clock, reloads once an editor has finished saving them.
  void watch_files() { watch_ = FileWatch(files()); }
  bool reload_if_saved(double now_seconds) { return watch_ && watch_->changed(now_seconds) && reload(); }

 private:
  // Opens the level and starts a World on it: `carried` is the players as they come
  // from the last map (World::players_for_next_level; nullptr: new players).
  void load(const std::array<play::Player, play::kMaxPlayers>* carried = nullptr);
  void start_world(const std::array<play::Player, play::kMaxPlayers>* carried);
  void after_tic();
  void tally_tic(const std::array<play::TicCmd, play::kMaxPlayers>& cmds);
  void special_buttons();
  void hear_chat();
  std::array<play::TicCmd, play::kMaxPlayers> take_commands(const play::TicCmd& console);
  void keep_sounds();  // the tic's, placed
  void choose_music(const std::string& map_name);  // "" for a level that is no Doom map
  bool doom_messages(const render::Frame& frame) const;  // drawn in Doom's font as part of its screen
  Pose pose_now() const;

  bsp::LevelSource source_;
  std::string name_;
  int skill_;
  GameFlags flags_;
  bool all_keys_ = false;
  std::unique_ptr<level::Level> level_;
  std::unique_ptr<play::World> world_;
  play::Random random_;  // Doom's play stream, carried from level to level
  Pose pose_, previous_;
  uint64_t tics_ = 0;
  std::string renderer_name_;
  std::unique_ptr<render::Renderer> renderer_;
  render::Probe probe_;
  render::RenderStats stats_;
  Automap automap_view_;
  std::string message_;
  int message_tics_ = 0;
  std::optional<play::StatusBarArt> status_art_;
  std::optional<play::HudFont> hud_font_;
  std::optional<play::IntermissionArt> intermission_;
  std::optional<play::TallyCount> tally_count_;
  play::Tally final_tally_;           // the level's, as it ended
  bool netgame_tally_frags_ = false;  // Doom's dofrags, which its next netgame tally starts from
  std::unique_ptr<play::WeaponArt> weapon_art_;
  std::vector<std::vector<uint32_t>> palettes_;  // PLAYPAL's, for the flashes
  play::Face face_;
  play::Random other_random_;  // Doom's M_Random: the face's glances, never the play
  render::Frame view_frame_;   // the 3D view, when it is not the whole frame
  std::optional<front::BackScreen> back_screen_;  // around a smaller view
  std::vector<PlacedSound> sounds_;
  bool listening_ = false;
  std::unique_ptr<SoundBank> sound_bank_;
  play::Track map_music_, tally_music_;  // the map's (S_Start) and its intermission's (WI_Ticker)
  bool recording_on_ = false, doom_turns_ = false, long_tics_ = false;
  bool doom_demo_ = false;  // recording a Doom demo (.lmp), which goes on across levels
  std::pair<int, int> recording_map_{0, 0};  // the (episode, map) it started on; map 0: none of a WAD's
  play::Demo recording_;
  std::optional<FileWatch> watch_;
  std::vector<std::array<play::TicCmd, play::kMaxPlayers>> others_;  // play_other_players'
  size_t others_at_ = 0;
  std::array<play::TicCmd, play::kMaxPlayers> last_commands_{};
  play::Chat chat_;
  bool paused_ = false;               // by a special button (a netgame's pause)
  std::optional<int> save_request_;   // by a special button: the slot
  std::vector<std::array<play::TicCmd, play::kMaxPlayers>> recorded_others_;  // while recording a netgame
};

}  // namespace p3d::game
