// Doom's front end around the game (d_main.c's loop, g_game.c's game actions): the
// title loop of pages and the WAD's demos, Doom's menus over everything, new games
// at an episode and skill, saves and loads in six slots, the intermission, pause
// and Doom's function keys. It runs one 35 Hz tic at a time from Doom's key codes
// and the player's commands, and composes the frame: page or game, then the menu.
// No SDL: the window feeds it keys and presents its frames; a headless run feeds it
// a key script (game/key_script.h).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "engine/front/demo_loop.h"
#include "engine/front/finale.h"
#include "engine/front/menu.h"
#include "engine/front/menu_art.h"
#include "engine/front/wipe.h"
#include "engine/play/music.h"
#include "game/input.h"
#include "game/session.h"
#include "game/settings.h"
#include "game/sound_bank.h"

namespace p3d::game {

struct FrontEndOptions {
  GameFlags flags;                 // -fast, -respawn, -nomonsters for the games it starts
  std::filesystem::path save_dir;  // the six slots' files (doomsav0.dsg..doomsav5.dsg); empty: no saving
  bool watching = false;           // the session given is a demo or a route to watch, not the player's game
  bool plays_demo = false;         // watching a demo: it goes on across levels as Doom's do (a route holds one)
  double mouse_turn = 0;           // turn units per pixel of mouse; 0: from the menu's sensitivity
};

// The turn (1/65536 of a turn) a pixel of mouse motion gives at Doom's sensitivity
// 0..9: Doom's (sensitivity + 5) / 10 scaling, 24 units at its default of 5.
constexpr double mouse_turn_per_pixel(int sensitivity) { return 24.0 * (sensitivity + 5) / 10; }

class FrontEnd {
 public:
  // Doom's start on these WADs: the title loop (D_StartTitle).
  FrontEnd(const bsp::LevelSource& wads, Settings& settings, FrontEndOptions options);
  // Straight into a game already set up (a map named on the command line, or a demo
  // to watch): Doom's menus over it where the WADs have them, else a text menu.
  FrontEnd(std::unique_ptr<Session> session, Settings& settings, FrontEndOptions options);
  ~FrontEnd();

  // A key pressed or let go (Doom's key codes, front/keys.h). Keys go to the menu
  // first, then to the game (in a title loop any key opens the menu). The keys held
  // make the player's command, as the settings bind them.
  void key_down(int key);
  void key_up(int key);
  void mouse_motion(int dx);
  void mouse_button(int button, bool down);  // 1: the left button fires
  // One tic: the menu's, then the page's or the demo's or the game's, the player's
  // command made from the keys held.
  void tic();
  // The same with the player's command given (an autopilot's, a demo's).
  void tic(const play::DemoTic& player);
  // The screen: page, game or tally, then the pause sign and the menu.
  void draw(render::Frame& frame, double alpha, const FrameTimes& times);

  // The game being played or watched (nullptr on a title page).
  Session* session() { return session_.get(); }
  const Session* session() const { return session_.get(); }
  // The player plays (not a page, a demo of the title loop or the tally).
  bool playing() const;
  // A level is on screen (the player's, or a demo being watched).
  bool in_level() const { return state_ == State::kLevel && session_; }
  // A game goes on: a level, its tally or Doom's text after it (each tic takes a command).
  bool in_game() const { return (state_ == State::kLevel || state_ == State::kFinale) && session_; }
  // The screen melts: the game waits, and takes no command (a demo's tics wait too).
  bool melting() const { return melt_ && !melt_->done(); }
  // The game waits (menu open in a game, or paused): the window stops its tic clock.
  bool waiting() const;
  bool paused() const { return paused_ || (session_ && session_->paused()); }
  bool netgame() const;  // several players: the game never waits for this one's menu
  // The command the keys held make (what tic() plays), for a netgame to send first,
  // with the chat's next character.
  play::TicCmd command();
  bool quit_requested() const { return quit_ && quit_delay_ == 0; }
  bool screenshot_requested() { return std::exchange(screenshot_, false); }
  // The settings changed since the last call (the window applies and saves them).
  bool settings_changed() { return std::exchange(settings_changed_, false); }
  // Sounds to play: the menu's (from nowhere) and the game's, placed.
  std::vector<Session::PlacedSound> take_sounds();
  const play::SoundClip* sound_clip(play::Sound sound) { return sounds_ ? sounds_->clip(sound) : nullptr; }
  // The music Doom plays now (engine/play/music.h): the title's, the map's, the tally's;
  // a player starts it when it changes (Doom's S_ChangeMusic). Its song from the WADs,
  // or nullopt (a lump missing or broken, said on stderr).
  const play::Track& music() const { return music_; }
  std::optional<wad::MidiSong> music_song(play::Music music) const;
  uint64_t game_tic() const { return game_tic_; }
  bool has_menus() const { return art_ && art_->complete(); }
  bool menu_active() const { return menu_ ? menu_->active() : text_menu_.is_open(); }
  // A line on the game's message line (shown whatever the messages setting).
  void say(const std::string& text);
  // The text menu of levels without Doom's art (Resume, Keys, Quit).
  Menu& text_menu() { return text_menu_; }

  // Starts Doom's game at this episode (1 for Doom II), map and skill (G_InitNew).
  void new_game(int episode, int map, int skill);
  // Back to the title loop (D_StartTitle); false when the WADs have no title art.
  bool start_title();
  // Saves the game in a slot (0..5) with a description; false (and a message) when
  // it cannot. Loads a slot; false (and a message) when the file is missing or bad.
  bool save_slot(int slot, const std::string& description);
  bool load_slot(int slot);
  std::filesystem::path slot_path(int slot) const;

 private:
  enum class State : uint8_t { kPage, kDemo, kLevel, kFinale };
  void start(const bsp::LevelSource& wads);
  void advance_demo();
  bool start_demo(const std::string& lump);
  void carry_out(const front::MenuRequest& r);
  void game_key(int key);
  bool chat_key(int key);
  void text_menu_key(int key);
  play::DemoTic command_from_keys();
  void level_tic(const play::DemoTic& player);
  void next_map();
  bool start_finale();
  void finale_tic(const play::DemoTic& player);
  void change_screen(const std::function<void()>& change);
  void draw_state(render::Frame& frame, double alpha, const FrameTimes& times);
  void draw_menus(render::Frame& frame) const;
  void draw_text_menu(render::Frame& frame) const;
  void level_music();
  void play_music(const play::Track& track) { music_ = track; }
  void apply_settings();
  front::MenuContext menu_context() const;
  std::array<std::optional<std::string>, front::kSaveSlots> read_slots() const;

  Settings& settings_;
  FrontEndOptions options_;
  std::optional<bsp::LevelSource> wads_;  // the WADs the title loop and new games use
  std::unique_ptr<wad::Stack> stack_;
  std::unique_ptr<front::MenuArt> art_;
  std::optional<front::Menu> menu_;
  std::optional<front::DemoLoop> loop_;
  std::optional<front::Finale> finale_;
  std::unique_ptr<SoundBank> sounds_;
  std::vector<uint32_t> palette_;
  front::GameMode mode_ = front::GameMode::kCommercial;

  State state_ = State::kLevel;
  std::unique_ptr<Session> session_;
  bool user_game_ = false;  // Doom's usergame: the player's own game, which saves and ends
  bool paused_ = false;
  // A netgame's pause and save go out in our next command (Doom's sendpause, sendsave).
  bool send_pause_ = false;
  std::optional<int> net_save_;
  std::string net_save_description_;  // ours, for the save when it comes back (Doom's savedescription)
  std::string page_;
  int page_tics_ = 0;
  std::vector<play::DemoTic> demo_;  // the title loop's demo being shown
  size_t demo_tic_ = 0;
  std::set<int> held_;  // keys down now
  int mouse_dx_ = 0, turn_held_ = 0, weapon_key_ = 0;
  bool mouse_fire_ = false;
  Cheats cheats_;
  uint8_t cheats_typed_ = 0;
  uint64_t game_tic_ = 0;
  bool quit_ = false;
  int quit_delay_ = 0;  // tics the quit sound plays before the game goes
  bool screenshot_ = false, settings_changed_ = false;
  std::vector<Session::PlacedSound> menu_sounds_;
  play::Track music_{play::Music::kNone, false};
  Menu text_menu_;
  // Doom's melt from the last screen shown to the next (front/wipe.h).
  image::Image last_frame_, wipe_start_;
  render::Frame scratch_;
  std::optional<front::Melt> melt_;
  bool wipe_pending_ = false;
  std::optional<front::MenuRequest> game_action_;  // a new game, a load, the end: done at the next tic
  play::Random m_random_;  // Doom's M_Random where no game keeps one (the title's pages)
};

}  // namespace p3d::game
