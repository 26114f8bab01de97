#include "game/front_end.h"

#include <algorithm>
#include <cstdio>

#include "engine/front/keys.h"
#include "engine/front/texts.h"
#include "engine/play/dehacked.h"
#include "engine/util/doom.h"
#include "engine/util/error.h"
#include "engine/util/file.h"
#include "engine/wad/art.h"

namespace p3d::game {

namespace {

constexpr int kQuitSoundTics = 53;  // Doom waits 105 VBLs (1.5 s) for the quit sound

// The description at the start of a save file (Doom's M_ReadSaveStrings reads its
// first 24 bytes), or nullopt when the file is missing or shorter.
std::optional<std::string> slot_description(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  try {
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    if (bytes.size() < size_t(front::kSaveStringSize)) return std::nullopt;
    std::string text(bytes.begin(), bytes.begin() + front::kSaveStringSize);
    return text.substr(0, text.find('\0'));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

FrontEnd::FrontEnd(const bsp::LevelSource& wads, Settings& settings, FrontEndOptions options)
    : settings_(settings), options_(std::move(options)) {
  start(wads);
  if (!start_title()) new_game(1, 1, level::kDefaultSkill);  // no title art: straight into the first map
}

FrontEnd::FrontEnd(std::unique_ptr<Session> session, Settings& settings, FrontEndOptions options)
    : settings_(settings), options_(std::move(options)), session_(std::move(session)) {
  if (session_->source().is_wad()) {
    start(session_->source());
    wads_->map.clear();
  }
  state_ = State::kLevel;
  user_game_ = !options_.watching;
  apply_settings();
  level_music();
}

FrontEnd::~FrontEnd() = default;

// The WADs' art, palette, sounds and texts, and Doom's menus on them.
void FrontEnd::start(const bsp::LevelSource& wads) {
  wads_ = wads;
  stack_ = std::make_unique<wad::Stack>(bsp::read_wads(wads.wads));
  art_ = std::make_unique<front::MenuArt>(*stack_);
  sounds_ = std::make_unique<SoundBank>(wads.wads);
  const wad::Art art(*stack_);
  if (!art.palettes().empty()) palette_ = art.palettes().front();
  mode_ = front::game_mode(*stack_);
  if (!has_menus() || palette_.empty()) return;
  auto texts = std::make_shared<std::map<std::string, std::string>>(play::dehacked_texts(*stack_));
  menu_.emplace(mode_, settings_.menu, [this] { return read_slots(); },
                [texts](const std::string& english) {
                  const auto it = texts->find(english);
                  return it != texts->end() ? it->second : english;
                });
  menu_->text_width = [this](const std::string& s) { return art_->text_width(s); };
  loop_.emplace(mode_);
}

bool FrontEnd::playing() const { return state_ == State::kLevel && session_ && user_game_; }

// A netgame goes on under the menu, as Doom's; its pause is every node's (Session::paused).
bool FrontEnd::waiting() const { return paused_ || (menu_active() && playing() && !netgame()); }

bool FrontEnd::netgame() const { return session_ && session_->world().options().netgame && !options_.watching; }

front::MenuContext FrontEnd::menu_context() const {
  front::MenuContext c;
  c.mode = mode_;
  c.user_game = user_game_;
  c.in_level = state_ == State::kLevel && session_ && !session_->in_intermission();
  c.netgame = netgame();
  c.automap = session_ && session_->show_automap;
  c.game_tic = game_tic_;
  return c;
}

// ---- the title loop (D_StartTitle, D_DoAdvanceDemo, D_PageTicker)

bool FrontEnd::start_title() {
  if (!loop_) return false;
  loop_->restart();
  user_game_ = paused_ = false;
  advance_demo();
  return true;
}

void FrontEnd::advance_demo() {
  for (int tries = 0; tries < 7; ++tries) {
    const front::DemoStep step = loop_->advance();
    if (step.kind == front::DemoStep::Kind::kDemo) {
      if (start_demo(step.lump)) return;
      continue;  // a demo the WADs lack or we cannot play: on to the next step
    }
    auto show_page = [&] {
      state_ = State::kPage;
      session_.reset();
      page_ = step.lump;
      page_tics_ = step.tics;
    };
    if (state_ == State::kPage) show_page();  // one page after another: the same screen state, no melt
    else change_screen(show_page);
    if (step.music.music != play::Music::kNone) play_music(step.music);
    return;
  }
}

// Doom's G_DoPlayDemo in the title loop: the demo's game, its console player's tics.
bool FrontEnd::start_demo(const std::string& lump) {
  const wad::Lump* found = stack_->find(lump);
  if (!found) return false;
  try {
    const play::DoomDemo d = play::decode_doom_demo(found->bytes, lump);
    bsp::LevelSource source = *wads_;
    source.map = d.map_name(mode_ == front::GameMode::kCommercial);
    auto session = std::make_unique<Session>(source, d.skill, flags_of(d));
    demo_ = play::demo_from_doom(d, session->level()).tics;
    if (d.player_count() > 1) session->play_other_players(d);  // a netgame's demo: every player
    change_screen([&] {
      session_ = std::move(session);
      demo_tic_ = 0;
      state_ = State::kDemo;
    });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pseudo3d: %s: not played in the title loop (%s)\n", lump.c_str(), e.what());
    return false;
  }
  apply_settings();
  level_music();
  return true;
}

// ---- games, saves and loads

void FrontEnd::new_game(int episode, int map, int skill) {
  const std::string name = doom::map_name(mode_ == front::GameMode::kCommercial, episode, map);
  bsp::LevelSource source = *wads_;
  source.map = name;
  std::unique_ptr<Session> session;
  try {
    session = std::make_unique<Session>(source, skill, options_.flags);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pseudo3d: cannot start %s: %s\n", name.c_str(), e.what());
    if (!session_ && !start_title()) quit_ = true;
    return;
  }
  change_screen([&] {
    session_ = std::move(session);
    state_ = State::kLevel;
    user_game_ = true;
    paused_ = false;
  });
  apply_settings();
  if (!settings_.renderer.empty()) session_->select_renderer(settings_.renderer, false);
  level_music();
}

std::filesystem::path FrontEnd::slot_path(int slot) const {
  return options_.save_dir / ("doomsav" + std::to_string(slot) + ".dsg");
}

std::array<std::optional<std::string>, front::kSaveSlots> FrontEnd::read_slots() const {
  std::array<std::optional<std::string>, front::kSaveSlots> slots;
  if (options_.save_dir.empty()) return slots;
  for (int i = 0; i < front::kSaveSlots; ++i) slots[size_t(i)] = slot_description(slot_path(i));
  return slots;
}

bool FrontEnd::save_slot(int slot, const std::string& description) {
  if (!session_ || options_.save_dir.empty()) return false;
  try {
    const std::vector<uint8_t> bytes = session_->save_game(description);
    std::filesystem::create_directories(options_.save_dir);
    write_file_atomically(slot_path(slot), bytes);
  } catch (const std::exception& e) {
    say(std::string("not saved: ") + e.what());
    std::fprintf(stderr, "pseudo3d: not saved: %s\n", e.what());
    return false;
  }
  say(menu_ ? menu_->doom_text(front::kGameSaved) : "game saved.");
  return true;
}

bool FrontEnd::load_slot(int slot) {
  const std::filesystem::path path = slot_path(slot);
  std::unique_ptr<Session> fresh;  // a game of its own when none is played (a page, a demo)
  try {
    const std::vector<uint8_t> bytes = read_file_bytes(path);
    Session* game = playing() ? session_.get() : nullptr;
    if (!game) {
      fresh = std::make_unique<Session>(bsp::LevelSource(*wads_), level::kDefaultSkill, options_.flags);
      game = fresh.get();
    }
    game->load_game(bytes, path.string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pseudo3d: not loaded: %s\n", e.what());
    say(std::string("not loaded: ") + e.what());  // the game goes on as it was
    return false;
  }
  change_screen([&] {
    if (fresh) session_ = std::move(fresh);
    state_ = State::kLevel;
    user_game_ = true;
    paused_ = false;
  });
  apply_settings();
  level_music();
  return true;
}

// ---- keys

void FrontEnd::key_down(int key) {
  if (chat_key(key)) return;  // a chat line takes the keys, which then move nothing
  held_.insert(key);
  if (menu_) {
    const int ch = key > ' ' && key < 0x7f ? key : 0;
    const bool taken = menu_->key(key, ch, menu_context());
    for (const front::MenuRequest& r : menu_->take_requests()) carry_out(r);
    for (play::Sound s : menu_->take_sounds()) menu_sounds_.push_back({s, 0, std::nullopt});
    if (taken) return;
  } else if (text_menu_.is_open()) {
    text_menu_key(key);
    return;
  } else if (key == front::kKeyEscape) {
    text_menu_.open();
    return;
  }
  if (state_ == State::kPage || state_ == State::kDemo || options_.watching) {  // any other key pops up the menu in demos
    if (menu_) menu_->open();
    return;
  }
  if (key == front::kKeyPause) {
    if (netgame()) send_pause_ = true;  // every node pauses at the tic our command says so
    else paused_ = !paused_;
    return;
  }
  if (state_ == State::kLevel) game_key(key);
}

void FrontEnd::key_up(int key) { held_.erase(key); }

play::TicCmd FrontEnd::command() {
  play::TicCmd cmd = command_from_keys().cmd;
  if (session_) cmd.chatchar = session_->chat().next_char();  // G_BuildTiccmd's HU_dequeueChatChar
  if (std::exchange(send_pause_, false)) cmd.buttons = play::kBtSpecial | play::kBtsPause;
  if (net_save_) cmd.buttons = uint8_t(play::kBtSpecial | play::kBtsSaveGame | (*std::exchange(net_save_, std::nullopt) << play::kBtsSaveShift));
  return cmd;
}

void FrontEnd::text_menu_key(int key) {
  if (key == front::kKeyEscape) text_menu_.close();
  if (key == front::kKeyUp || key == 'w') text_menu_.up();
  if (key == front::kKeyDown || key == 's') text_menu_.down();
  if (key == front::kKeyF10) quit_ = true;
  if (key != front::kKeyEnter && key != front::kKeySpace) return;
  switch (text_menu_.selected()) {
    case Menu::Item::kResume: text_menu_.close(); break;
    case Menu::Item::kKeys:
      if (session_) session_->show_help = !session_->show_help;
      break;
    case Menu::Item::kQuit: quit_ = true; break;
  }
}

// Doom's HU_Responder in a netgame: T starts a line to everyone, G, I, B or R to one
// player (with three or more); while a line is typed every key is the chat's.
bool FrontEnd::chat_key(int key) {
  if (!session_ || state_ != State::kLevel || !netgame() || menu_active()) return false;
  play::Chat& chat = session_->chat();
  if (chat.typing()) {
    const int ch = key == front::kKeyEnter ? play::Chat::kEnter
                   : key == front::kKeyBackspace ? play::Chat::kBackspace
                   : key == front::kKeyEscape ? play::Chat::kEscape
                                             : key;
    std::optional<std::string> sent;
    chat.key(ch, &sent);  // a key the line has no use for reaches the game no more than the rest
    if (sent) say(*sent);  // Doom shows our own line as our message
    return true;
  }
  if (session_->show_automap) return false;
  if (key == 't') {
    chat.start(play::Chat::kToEveryone);
    return true;
  }
  const std::string colours = "gibr";  // green, indigo, brown, red
  const size_t to = key > 0 && key < 0x80 ? colours.find(char(key)) : std::string::npos;
  const play::World& w = session_->world();
  const int players = int(std::count(w.options().in_game.begin(), w.options().in_game.end(), true));
  if (to == std::string::npos || players <= 2) return false;
  if (int(to) == w.options().console_player) {
    say("You mumble to yourself");
    return true;
  }
  if (!w.in_game(int(to))) return false;
  chat.start(uint8_t(to + 1));
  return true;
}

// Keys in a level that Doom's menus did not take: the map's, the weapons, typed
// cheats, and our own (renderers, the heads-up text, screenshots).
void FrontEnd::game_key(int key) {
  Session& s = *session_;
  if (key >= 'a' && key <= 'z') cheats_typed_ |= cheats_.type(char(key));
  if (key >= '1' && key <= '7') weapon_key_ = key - '0';
  if (std::find(settings_.keys[size_t(Action::kAutomap)].begin(), settings_.keys[size_t(Action::kAutomap)].end(), key) !=
      settings_.keys[size_t(Action::kAutomap)].end())
    s.show_automap = !s.show_automap;
  if (s.show_automap) {
    if (key == 'o') s.automap.overlay = !s.automap.overlay;
    if (key == 'b') s.automap.splitters = !s.automap.splitters;
    if (key == 't') s.automap.things = !s.automap.things;
    if (key == front::kKeyEquals) s.automap.scale = std::min(8.0, s.automap.scale * 1.25);
    if (key == front::kKeyMinus) s.automap.scale = std::max(0.01, s.automap.scale / 1.25);
  }
  if (key == '`') s.show_hud = !s.show_hud;
  if (key == front::kKeyF1 && !menu_) s.show_help = !s.show_help;  // Doom's menus have their own help
  if (key == front::kKeyF12 || key == front::kKeyPrintScreen) screenshot_ = true;
  if (key == '[' || key == ']') {  // the renderers, round and round
    const auto& names = key_renderers();
    const auto at = std::find(names.begin(), names.end(), s.renderer_name());
    const size_t i = at == names.end() ? 0 : size_t(at - names.begin());
    const size_t next = (i + (key == ']' ? 1 : names.size() - 1)) % names.size();
    if (s.select_renderer(names[next])) {
      settings_.renderer = names[next];
      settings_changed_ = true;
    }
  }
}

void FrontEnd::mouse_motion(int dx) { mouse_dx_ += dx; }
void FrontEnd::mouse_button(int button, bool down) {
  if (button == 1) mouse_fire_ = down;
}

void FrontEnd::carry_out(const front::MenuRequest& r) {
  using Kind = front::MenuRequest::Kind;
  switch (r.kind) {
    case Kind::kNewGame:
    case Kind::kLoadGame:
    case Kind::kEndGame: game_action_ = r; break;  // at the next tic, as Doom's gameaction
    case Kind::kSaveGame:
      if (netgame()) {  // Doom's G_SaveGame: every node saves when our command with it runs
        net_save_ = r.slot;
        net_save_description_ = r.text;
      } else {
        save_slot(r.slot, r.text);
      }
      break;
    case Kind::kQuit:
      quit_ = true;
      quit_delay_ = kQuitSoundTics;
      break;
    case Kind::kMessage: say(r.text); break;
    case Kind::kScreenshot: screenshot_ = true; break;
    case Kind::kSettings:
      apply_settings();
      settings_changed_ = true;
      break;
  }
}

void FrontEnd::say(const std::string& text) {
  if (session_) session_->say(text);
}

void FrontEnd::apply_settings() {
  if (!session_) return;
  session_->screen_blocks = settings_.menu.screen_blocks;
  session_->low_detail = settings_.menu.low_detail;
  session_->show_messages = settings_.menu.show_messages;
}

// ---- screen changes (Doom's wipe)

// Runs a change of screen (a new game, a demo, the tally, the title...) and melts the
// last screen shown into the new one, as Doom does when its game state changes. The
// melt draws from the new game's M_Random (Doom clears it as a game starts).
void FrontEnd::change_screen(const std::function<void()>& change) {
  const image::Image before = last_frame_;
  change();
  if (before.pixels.empty() || !has_menus()) return;
  wipe_start_ = before;
  wipe_pending_ = true;  // the melt starts at the next frame drawn, after this tic
}

// ---- tics

play::DemoTic FrontEnd::command_from_keys() {
  auto held = [&](Action a) {
    for (int k : settings_.keys[size_t(a)])
      if (held_.count(k)) return true;
    return false;
  };
  Controls c;
  c.forward = held(Action::kForward);
  c.back = held(Action::kBack);
  c.turn_left = held(Action::kTurnLeft);
  c.turn_right = held(Action::kTurnRight);
  c.strafe_left = held(Action::kStrafeLeft);
  c.strafe_right = held(Action::kStrafeRight);
  c.use = held(Action::kUse);
  c.attack = held(Action::kFire) || mouse_fire_;
  c.strafe_modifier = held(Action::kStrafe);
  c.run = held(Action::kRun);
  c.mouse_dx = std::exchange(mouse_dx_, 0);
  c.cheats = std::exchange(cheats_typed_, 0);
  c.weapon = std::exchange(weapon_key_, 0);
  turn_held_ = c.turn_left || c.turn_right ? turn_held_ + 1 : 0;
  InputSettings input;
  input.mouse_sensitivity =
      options_.mouse_turn > 0 ? options_.mouse_turn : mouse_turn_per_pixel(settings_.menu.mouse_sensitivity);
  return make_command(c, turn_held_, input);
}

void FrontEnd::tic() { tic(command_from_keys()); }

void FrontEnd::tic(const play::DemoTic& player) {
  if (melt_ && !melt_->done()) {  // the world waits while the screen melts
    melt_->tic();
    if (!netgame()) return;  // a netgame's tic is every player's: it runs under the melt
  } else {
    melt_.reset();
  }
  ++game_tic_;
  if (menu_) menu_->tic();
  if (quit_ && quit_delay_ > 0) --quit_delay_;
  if (session_ && netgame())  // a save some player asked for at the last tic (Doom's ga_savegame)
    if (const std::optional<int> slot = session_->take_save_request()) {
      save_slot(*slot, net_save_description_.empty() ? "NET GAME" : net_save_description_);
      net_save_description_.clear();
    }
  if (const std::optional<front::MenuRequest> action = std::exchange(game_action_, std::nullopt)) {
    using Kind = front::MenuRequest::Kind;  // Doom's G_Ticker: the game action first, then the tic
    if (action->kind == Kind::kNewGame) new_game(action->episode, 1, action->skill);
    if (action->kind == Kind::kLoadGame) load_slot(action->slot);
    if (action->kind == Kind::kEndGame) start_title();
  }
  switch (state_) {
    case State::kPage:
      if (--page_tics_ < 0) advance_demo();
      break;
    case State::kDemo:
      if (demo_tic_ >= demo_.size() || session_->exited() != play::ExitKind::kNone) {
        advance_demo();
        break;
      }
      session_->tic(demo_[demo_tic_++]);
      break;
    case State::kLevel: level_tic(player); break;
    case State::kFinale: finale_tic(player); break;
  }
}

// Doom's G_Ticker for the player's game: the world waits while paused or while the
// menu is open; an exit leads to the tally, counted until the players hurry it on,
// then the next map, or back to the title after the last.
void FrontEnd::level_tic(const play::DemoTic& player) {
  if (!session_) return;
  Session& s = *session_;
  if (s.in_intermission()) {  // WI_Ticker: any player's press hurries it on
    s.tic(player);
    if (s.intermission_over()) next_map();
    return;
  }
  if (waiting()) {
    s.idle_tic();
    return;
  }
  if (s.player().state == play::PlayerState::kReborn)
    change_screen([&] { s.tic(player); });  // the level from its start melts in (Doom's G_DoReborn)
  else
    s.tic(player);
  if (s.exited() == play::ExitKind::kNone || !(user_game_ || options_.plays_demo)) return;
  if (mode_ != front::GameMode::kCommercial && start_finale()) return;  // Doom's eighth maps: no tally
  bool tally = false;
  change_screen([&] { tally = s.start_intermission(); });
  if (tally) play_music(s.music());
  else next_map();
}

// Doom's G_WorldDone after the tally: Doom II's finale between clusters, or the next
// map; after the last, the title.
void FrontEnd::next_map() {
  if (mode_ == front::GameMode::kCommercial && start_finale()) return;
  if (loop_ && session_->next_map_name().empty() && !netgame()) {
    start_title();  // the end of the episode or the game (a netgame's players play on: the map again)
    return;
  }
  change_screen([&] { session_->enter_next_map(); });
  apply_settings();
  level_music();
}

// F_StartFinale where Doom has one after the map just left; false where it has none.
bool FrontEnd::start_finale() {
  int episode = 0, map = 0;
  if (!menu_ || !session_->doom_map_numbers(episode, map)) return false;
  if (!front::has_finale(mode_, episode, map, session_->exited() == play::ExitKind::kSecret)) return false;
  change_screen([&] {
    finale_.emplace(mode_, episode, map, [this](const std::string& m) { return menu_->doom_text(m); });
    state_ = State::kFinale;
  });
  play_music(finale_->music());
  return true;
}

// F_Ticker: Doom II's text gives way at a button (to the next map, or after MAP30 the
// end); Doom's turns into its episode's last picture.
void FrontEnd::finale_tic(const play::DemoTic& player) {
  session_->tic(player);  // the level is over: this takes every player's command
  const front::Finale::Next next = finale_->tic(session_->any_button());
  for (play::Sound s : finale_->take_sounds()) menu_sounds_.push_back({s, 0, std::nullopt});
  if (finale_->screen_changed()) change_screen([] {});
  play_music(finale_->music());
  if (next == front::Finale::Next::kStay) return;
  finale_.reset();
  if ((next == front::Finale::Next::kEnd || session_->next_map_name().empty()) && !netgame()) {
    start_title();
    return;
  }
  change_screen([&] {
    session_->enter_next_map();
    state_ = State::kLevel;
  });
  apply_settings();
  level_music();
}

// ---- music

void FrontEnd::level_music() {
  if (session_) play_music(session_->music());
}

std::optional<wad::MidiSong> FrontEnd::music_song(play::Music music) const {
  if (!stack_ || music == play::Music::kNone) return std::nullopt;
  try {
    std::vector<std::string> warnings;
    wad::MidiSong song = play::read_song(*stack_, music, &warnings);
    for (const std::string& w : warnings) std::fprintf(stderr, "pseudo3d: %s\n", w.c_str());
    return song;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pseudo3d: %s (no music)\n", e.what());
    return std::nullopt;
  }
}

// ---- the screen

std::vector<Session::PlacedSound> FrontEnd::take_sounds() {
  std::vector<Session::PlacedSound> out = std::exchange(menu_sounds_, {});
  if (session_) {
    std::vector<Session::PlacedSound> game = session_->take_sounds();
    out.insert(out.end(), game.begin(), game.end());
  }
  return out;
}

// Doom's D_Display: the page, the game or its tally (melting in over the last screen
// after a change), then the pause sign and the menu over everything.
void FrontEnd::draw(render::Frame& frame, double alpha, const FrameTimes& times) {
  if (std::exchange(wipe_pending_, false)) melt_.emplace(session_ ? session_->screen_random() : m_random_);
  if (melt_ && wipe_start_.width == frame.width && wipe_start_.height == frame.height) {
    if (scratch_.width != frame.width || scratch_.height != frame.height) scratch_ = render::Frame(frame.width, frame.height);
    draw_state(scratch_, alpha, times);
    melt_->draw(wipe_start_, scratch_, frame);
  } else {
    melt_.reset();
    draw_state(frame, alpha, times);
  }
  draw_menus(frame);
  last_frame_.width = frame.width, last_frame_.height = frame.height;
  last_frame_.pixels.assign(frame.pixels.begin(), frame.pixels.end());
}

void FrontEnd::draw_state(render::Frame& frame, double alpha, const FrameTimes& times) {
  if (state_ == State::kFinale) {
    finale_->draw(*art_, *stack_, frame, palette_);
  } else if (state_ == State::kPage) {
    std::fill(frame.pixels.begin(), frame.pixels.end(), palette_.empty() ? 0xFF000000u : palette_[0]);
    art_->draw_page(page_, frame, palette_);
  } else if (session_) {
    session_->menu_over_border = menu_active();
    session_->render(frame, alpha);
    session_->draw_overlays(frame, times, alpha);
  }
}

void FrontEnd::draw_menus(render::Frame& frame) const {
  if (!menu_) {
    if (text_menu_.is_open()) draw_text_menu(frame);
    return;
  }
  if (paused() && state_ == State::kLevel) {
    // M_PAUSE across the view window's top, in Doom's screen (at the top with the map).
    const int blocks = std::min(settings_.menu.screen_blocks, 10);
    const int width = blocks * 32, height = (blocks * 168 / 10) & ~7;
    const bool automap = session_ && session_->show_automap;
    art_->draw_pause((play::kScreenWidth - width) / 2, width, automap ? 0 : (168 - height) / 2, frame, palette_);
  }
  art_->draw(*menu_, frame, palette_);
}

void FrontEnd::draw_text_menu(render::Frame& frame) const {
  const int scale = frame.width >= 1280 ? 2 : 1;
  const auto lines = text_menu_.lines();
  draw_panel(frame, frame.width / 2 - 60 * scale, frame.height / 2 - int(lines.size()) * 4 * scale, lines, scale);
}

}  // namespace p3d::game
