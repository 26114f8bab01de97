#include "game/session.h"

#include <cmath>
#include <cstdio>

#include "engine/bsp/load.h"
#include "engine/front/game_mode.h"
#include "engine/play/savegame.h"
#include "engine/util/doom.h"
#include "engine/util/error.h"
#include "game/sound_mixer.h"

namespace p3d::game {

namespace {

constexpr double kDegreesPerAngle = 360.0 / 4294967296.0;

play::Angle binary_angle(double degrees) {
  return play::Angle(uint64_t(std::llround(std::fmod(degrees, 360.0) / 360.0 * 4294967296.0 + 4294967296.0)));
}

play::Fixed to_fixed_units(double units) { return play::Fixed(std::llround(units * play::kFracUnit)); }

// The view into its window of the frame.
void blit_view(const render::Frame& view, render::Frame& frame, const front::ViewWindow& w) {
  for (int y = 0; y < std::min(w.height, view.height); ++y)
    std::copy_n(view.pixels.begin() + ptrdiff_t(y) * view.width, w.width, &frame.at(w.x, w.y + y));
}

// Doom's low detail: each pair of columns shows its left one.
void double_columns(render::Frame& view) {
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x + 1 < view.width; x += 2) view.at(x + 1, y) = view.at(x, y);
}

}  // namespace

const std::vector<std::string>& key_renderers() {
  static const std::vector<std::string> names = {"bsp", "painter", "dda", "sphere", "reference"};
  return names;
}

Session::Session(const bsp::LevelSource& source, int skill, GameFlags flags)
    : source_(source), skill_(skill), flags_(flags) {
  load();
  select_renderer("bsp", false);
}

void Session::load(const std::array<play::Player, play::kMaxPlayers>* carried) {
  bsp::OpenedLevel opened = bsp::open_level(source_);
  name_ = opened.name;
  level_ = std::make_unique<level::Level>(std::move(opened.level));
  automap_view_.set_level(*level_);
  status_art_.reset();
  back_screen_.reset();
  hud_font_.reset();
  weapon_art_.reset();
  palettes_.clear();
  if (source_.is_wad()) {
    const wad::Stack wads = bsp::read_wads(source_.wads);
    status_art_ = play::StatusBarArt::load(wads);
    back_screen_ = front::BackScreen::load(wads, front::game_mode(wads) == front::GameMode::kCommercial);
    hud_font_ = play::HudFont::load(wads);
    palettes_ = wad::Art(wads).palettes();
    weapon_art_ = std::make_unique<play::WeaponArt>(wads);
  }
  start_world(carried);
}

// Doom's G_DoLoadLevel: the World on the level, Doom's options for its map, the play
// stream going on from the last level.
void Session::start_world(const std::array<play::Player, play::kMaxPlayers>* carried) {
  play::GameOptions o;
  o.skill = skill_;
  o.map = 0;  // a hand-made level is no boss's map
  std::optional<play::Map> map;
  if (source_.is_wad()) {
    const wad::Stack wads = bsp::read_wads(source_.wads);
    const std::string map_name = bsp::resolve_map_name(wads, source_.map);
    o = play::game_options_for(wads, map_name, skill_);
    map = play::map_from_wads(wads, map_name, *level_);
    choose_music(map_name);
  } else {
    map = play::map_from_level(*level_);
    choose_music("");
  }
  o.fast = flags_.fast;
  o.respawn = flags_.respawn;
  o.no_monsters = flags_.no_monsters;
  o.deathmatch = flags_.deathmatch == 0   ? play::Deathmatch::kNone
                 : flags_.deathmatch == 2 ? play::Deathmatch::kAltdeath
                                          : play::Deathmatch::kDeathmatch;
  o.time_limit = flags_.time_limit;
  o.in_game = flags_.players;
  o.console_player = flags_.console_player;
  o.netgame = flags_.players[1];  // Doom's test for a demo's netgame
  o.game_tic = world_ ? world_->game_tic() : 0;  // the last level's clock goes on
  world_ = std::make_unique<play::World>(std::move(*map), *level_, o, random_, carried);
  if (all_keys_) set_keys(63);
  tics_ = 0;
  pose_ = previous_ = pose_now();
  face_.start_level(play::face_input(player()));
  message_tics_ = 0;  // Doom's HU_Start as its player spawns: the last level's message is gone
}

Session::Pose Session::pose_now() const {
  const play::Player& p = player();
  if (!p.mo) return pose_;
  return {{play::to_double(p.mo->x), play::to_double(p.mo->y)}, play::to_double(p.mo->z), play::to_double(world_->eye_z()),
          double(p.mo->angle) * kDegreesPerAngle};
}

std::string Session::title() const {
  return level_->title.empty() ? std::filesystem::path(name_).filename().string() : level_->title;
}

std::string Session::map_name() const {
  return source_.is_wad() ? bsp::resolve_map_name(bsp::read_wads(source_.wads), source_.map) : std::string();
}

std::vector<std::filesystem::path> Session::files() const {
  if (source_.is_wad()) return source_.wads;
  return {source_.file};
}

void Session::spawn(geom::Vec2 pos, double angle) {
  world_->place_player(to_fixed_units(pos.x), to_fixed_units(pos.y), binary_angle(angle));
  pose_ = previous_ = pose_now();
  tics_ = 0;
}

GameFlags flags_of(const play::DoomDemo& d) {
  GameFlags f{d.fast, d.respawn, d.no_monsters};
  f.deathmatch = d.deathmatch;
  for (int p = 0; p < play::kMaxPlayers; ++p) f.players[size_t(p)] = d.players[size_t(p)];
  f.console_player = d.console_player;
  return f;
}

void Session::play_other_players(const play::DoomDemo& demo) {
  others_.clear();  // the console player's entry is replaced by tic()'s command
  for (size_t t = 0; t < demo.tic_count(); ++t) others_.push_back(play::players_tic(demo, t));
  others_at_ = 0;
}

void Session::player_left(int player) {
  if (!world_->in_game(player)) return;
  world_->player_left(player);
  if (show_messages) say(world_->player().message);
  recording_on_ = false;  // Doom's G_CheckDemoStatus
}

std::array<play::TicCmd, play::kMaxPlayers> Session::take_commands(const play::TicCmd& console) {
  std::array<play::TicCmd, play::kMaxPlayers> cmds{};
  if (others_at_ < others_.size()) cmds = others_[others_at_++];
  cmds[size_t(world_->options().console_player)] = console;
  return cmds;
}

void Session::tic(const play::DemoTic& tic) {
  const bool netgame = world_->options().netgame;
  play::DemoTic played = tic;
  if (recording_on_ && doom_turns_) played.cmd.turn = play::doom_demo_turn(tic.cmd.turn);
  const bool several = netgame || !others_.empty();
  last_commands_ = take_commands(played.cmd);
  if (recording_on_) {  // Doom's G_WriteDemoTiccmd: every tic, whatever the screen
    if (several) recorded_others_.push_back(last_commands_);
    recording_.tics.push_back(played);
  }
  special_buttons();
  if (tally_count_) return tally_tic(last_commands_);
  if (world_->exit() != play::ExitKind::kNone) return;  // the level is over: waiting for the next one
  if (paused_) {  // Doom's P_Ticker waits; the status bar and the chat do not
    idle_tic();
    hear_chat();
    return;
  }
  if (!netgame && player().state == play::PlayerState::kReborn) {  // Doom's G_DoReborn: the level from its start
    random_ = world_->random();
    start_world(nullptr);
  }
  previous_ = pose_;
  if (played.cheats) world_->apply_cheats(played.cheats);
  if (several)
    world_->tick_players(last_commands_);
  else
    world_->tick(played.cmd);
  ++tics_;
  after_tic();
}

// HU_Ticker's part for the chat: the other players' characters of this tic.
void Session::hear_chat() {
  const play::GameOptions& o = world_->options();
  const auto line = chat_.receive(last_commands_, o.in_game, o.console_player);
  if (!line) return;
  const std::string name = play::kChatNames[size_t(line->player)];
  const auto reworded = o.texts.find(name);  // the WAD's DEHACKED name (Freedoom's "g:")
  // Shown whatever the messages setting, as Doom's message_nottobefuckedwith.
  say((reworded != o.texts.end() ? reworded->second : name) + line->text);
  if (listening_) sounds_.push_back({map_name().rfind("MAP", 0) == 0 ? play::Sound::kRadio : play::Sound::kTink, 0, std::nullopt});
}

// G_Ticker's special buttons, of every player in the game, whatever the screen.
void Session::special_buttons() {
  for (int i = 0; i < play::kMaxPlayers; ++i) {
    const uint8_t b = last_commands_[size_t(i)].buttons;
    if (!world_->in_game(i) || !(b & play::kBtSpecial)) continue;
    if ((b & 3) == play::kBtsPause) paused_ = !paused_;
    if ((b & 3) == play::kBtsSaveGame) save_request_ = (b & play::kBtsSaveMask) >> play::kBtsSaveShift;
  }
}

// Doom's WI_Ticker: the count goes on (no other ticker runs), its sounds heard.
void Session::tally_tic(const std::array<play::TicCmd, play::kMaxPlayers>& cmds) {
  tally_count_->tic(*world_, cmds);
  for (const play::Sound s : tally_count_->take_sounds())
    if (listening_) sounds_.push_back({s, 0, std::nullopt});
  ++tics_;
}

// What Doom's tickers do after the play: the messages, the face, sounds, the view.
void Session::after_tic() {
  if (world_->console_player_spawned()) {  // Doom's ST_Start and HU_Start, before their tickers
    face_.start_level(play::face_input(player()));
    message_tics_ = 0;
  }
  advance_message();
  hear_chat();
  face_.tic(other_random_, play::face_input(player()));
  if (show_messages)
    for (const std::string& m : world_->messages()) say(m);
  if (listening_) keep_sounds();
  pose_ = pose_now();
  if (world_->exit() != play::ExitKind::kNone) {
    // Our own demo holds one level: it ends at its exit. A Doom demo goes on through
    // the tally into the next level, as Doom's.
    if (!doom_demo_) recording_on_ = false;
    // Doom's tally says it; a level that is no Doom map has none, so the message line does.
    if (!source_.is_wad()) say(world_->exit() == play::ExitKind::kSecret ? "secret exit" : "exit");
  }
}

void Session::idle_tic() {
  advance_message();
  face_.tic(other_random_, play::face_input(player()));
}

std::string Session::next_map_name(std::string* why) const {
  std::string next, reason;
  if (source_.is_wad()) {
    const wad::Stack wads = bsp::read_wads(source_.wads);
    const std::string current = bsp::resolve_map_name(wads, source_.map);
    next = doom::next_map(current, world_->exit() == play::ExitKind::kSecret,
                          [&](const std::string& name) { return wads.map(name).has_value(); });
    if (next.empty()) reason = "no map after " + current;
  } else {
    reason = "a hand-made level has no next map";
  }
  if (why) *why = reason;
  return next;
}

bool Session::enter_next_map() {
  std::string why;
  const std::string next = next_map_name(&why);
  if (!next.empty()) source_.map = next;
  intermission_.reset();
  tally_count_.reset();
  // Doom's G_PlayerFinishLevel: health, armor, ammo and weapons go on to the next
  // map, and the cheats; keys, powers and the flashes stay behind.
  const std::array<play::Player, play::kMaxPlayers> carried = world_->players_for_next_level();
  random_ = world_->random();
  load(&carried);
  if (!select_renderer(renderer_name_, false)) select_renderer("bsp", false);
  if (next.empty()) say(why + ": starting it again");  // Doom says nothing of a new map
  return !next.empty();
}

render::Camera Session::camera(double alpha) const {
  alpha = std::clamp(alpha, 0.0, 1.0);
  double turn = pose_.angle - previous_.angle;  // the short way round
  if (turn > 180) turn -= 360;
  if (turn < -180) turn += 360;
  return render::Camera{previous_.pos + (pose_.pos - previous_.pos) * alpha,
                        previous_.view_z + (pose_.view_z - previous_.view_z) * alpha, previous_.angle + turn * alpha,
                        fov};
}

bool Session::select_renderer(const std::string& name, bool announce) {
  auto r = render::make_renderer(name, renderer_options);
  if (!r) {
    say("no renderer '" + name + "'");
    return false;
  }
  if (!r->supports(*level_)) {
    say(name + " cannot draw this level (it needs " + std::string(r->needs()) + ")");
    return false;
  }
  r->prepare(*level_);
  renderer_ = std::move(r);
  renderer_name_ = name;
  if (announce) say("renderer: " + name);
  return true;
}

const render::RenderStats& Session::render(render::Frame& frame, double alpha) {
  if (intermission_) {  // the tally in place of the view
    intermission_->draw(final_tally_, tally_count_->shown(), frame, palettes_.front());
    stats_ = {};
    return stats_;
  }
  probe_.want_order = show_automap;
  const int bar = status_bar_rows(frame);
  const int scale = play::ScreenPlace::scale_for(frame.width, frame.height);
  // Doom's view window: the whole area above the bar, or smaller inside a border.
  const front::ViewWindow window =
      back_screen_ && !frame.keep_indices ? front::view_window(frame.width, frame.height - bar, screen_blocks, scale)
                                          : front::ViewWindow{0, 0, frame.width, frame.height - bar};
  const bool whole = window == front::ViewWindow{0, 0, frame.width, frame.height};
  if (!whole && (view_frame_.width != window.width || view_frame_.height != window.height))
    view_frame_ = render::Frame(window.width, window.height);
  render::Frame& view = whole ? frame : view_frame_;
  view.doom_screen_width = frame.width;  // a smaller view keeps the rules of its screen's width
  const int flash = frame.keep_indices ? 0 : flash_palette();
  if (flash) view.keep_indices = true;  // drawn in palette indices, then seen through the flash's palette
  stats_ = renderer_->render(*level_, world_->state(), camera(alpha), view, &probe_);
  const bool full_width = window.width == frame.width;  // the weapon stands on the bar, as in Doom's 320x168
  if (weapon_art_ && !show_automap) play::draw_weapon(player(), *weapon_art_, *level_, view, full_width ? bar : 0);
  if (flash) {
    view.keep_indices = false;
    if (view.indexed()) {
      view.palette = palettes_[size_t(flash)];
      view.resolve_colours();
      view.indices.clear();
    }
  }
  if (low_detail) double_columns(view);
  const std::vector<uint32_t>& palette = flash ? palettes_[size_t(flash)] : level_->palette;
  if (!whole) {
    if (!full_width || window.height < frame.height - bar) back_screen_->draw(frame, frame.height - bar, window, scale, palette);
    blit_view(view_frame_, frame, window);
  }
  if (bar > 0) {
    const play::Player& p = player();
    play::StatusValues values = p.inv.status(p.cards, face_.index());
    const play::GameOptions& o = world_->options();
    if (o.netgame) values.face_background = o.console_player;  // Doom's STFB: the player's colour
    values.deathmatch = o.deathmatch != play::Deathmatch::kNone;
    values.frags = play::frag_total(p);
    status_art_->draw(values, frame, palette);
  }
  // Doom's message line, top left, in its own font; over a smaller view's border Doom
  // redraws the border after it while a menu is open (D_Display's R_DrawViewBorder).
  const bool border_hides = menu_over_border && window.height < frame.height - bar;
  if (doom_messages(frame) && !border_hides) {
    const int doom_scale = play::ScreenPlace::scale_for(frame.width, frame.height);
    if (message_tics_ > 0) hud_font_->draw(frame, message_, 0, 0, doom_scale, 0, 0, palettes_[size_t(flash)]);
    if (chat_.typing())  // Doom's w_chat, the line below the message's, with its cursor
      hud_font_->draw(frame, chat_.line() + "_", 0, hud_font_->height() + 1, doom_scale, 0, 0, palettes_[size_t(flash)]);
  }
  if (!show_automap) probe_.order.clear();
  return stats_;
}

bool Session::doom_messages(const render::Frame& frame) const {
  return hud_font_ && frame.width >= 320 && !palettes_.empty() && !frame.keep_indices;
}

int Session::flash_palette() const {
  const int p = play::flash_palette(player().inv);  // red while hurt, gold, the suit's green
  return size_t(p) < palettes_.size() ? p : 0;
}

int Session::status_bar_rows(const render::Frame& frame) const {
  if (!status_art_ || !show_status_bar || screen_blocks > 10 || frame.keep_indices) return 0;
  // Doom's bar needs Doom's screen at least: a smaller frame shows the view alone.
  if (frame.width < 320 || frame.height < 200) return 0;
  return play::StatusBarArt::height_in(frame.width, frame.height);
}

void Session::draw_overlays(render::Frame& frame, const FrameTimes& times, double alpha) const {
  const int scale = frame.width >= 1280 ? 2 : 1;
  const int margin = 4 * scale;
  if (show_automap) automap_view_.draw(frame, *level_, world_->state(), camera(alpha), probe_.order, automap);
  int y = margin;
  if (show_hud) {
    std::vector<std::string> lines;
    const std::string progress = progress_line(player().cards, player().secret_count, world_->total_secrets(), player().cheats & play::kCheatNoclip);
    if (frame.width < kCompactWidth) {  // a low resolution: one short line
      char fps[32];
      std::snprintf(fps, sizeof fps, "%.0f fps  ", times.fps);
      lines = {fps + progress};
    } else {
      lines = hud_lines(title(), renderer_name_, stats_, times, pose_.pos, pose_.z, pose_.angle);
      lines.push_back(progress);
    }
    y += draw_panel(frame, margin, y, lines, scale) + margin;
  }
  if (message_tics_ > 0 && !doom_messages(frame)) draw_panel(frame, margin, y, {message_}, scale);
  if (show_help) {
    const auto lines = help_lines();
    draw_panel(frame, margin, std::max(margin, frame.height / 2 - int(lines.size()) * 4 * scale), lines, scale);
  }
  if (menu.is_open() && !show_help) {  // the menu's Keys shows the help in its place
    const auto lines = menu.lines();
    draw_panel(frame, frame.width / 2 - 60 * scale, frame.height / 2 - int(lines.size()) * 4 * scale, lines, scale);
  }
}

void Session::keep_sounds() {
  const play::Mobj* own = player().mo;
  for (const play::SoundEvent& e : world_->sounds()) {
    // The player's own sounds and those from nowhere are heard at full volume.
    if (e.origin == 0 || (own && e.origin == own->id))
      sounds_.push_back({e.sound, e.origin, std::nullopt});
    else
      sounds_.push_back({e.sound, e.origin, geom::Vec2(play::to_double(e.x), play::to_double(e.y))});
  }
}

// Doom's S_Start and WI_Ticker: the map's track; the tally's, Doom II's (D_DM2INT)
// after its MAPxx maps, else Doom's (D_INTER).
void Session::choose_music(const std::string& map_name) {
  map_music_ = play::map_track(map_name);
  tally_music_ = map_music_.music == play::Music::kNone ? play::Track{}
                                                          : play::intermission_track(map_name.rfind("MAP", 0) == 0);
}

const play::SoundClip* Session::sound_clip(play::Sound sound) {
  if (!sound_bank_) sound_bank_ = std::make_unique<SoundBank>(source_.is_wad() ? source_.wads : std::vector<std::filesystem::path>{});
  return sound_bank_->clip(sound);
}

play::Listener Session::listener() const { return listener_at(pose_.pos, pose_.angle); }

std::optional<geom::Vec2> Session::sound_origin(uint64_t origin) const {
  if (origin >= play::kSectorOrigin) {
    const size_t sector = size_t(origin - play::kSectorOrigin);
    if (sector >= world_->map().sectors.size()) return std::nullopt;
    const play::Sector& s = world_->map().sectors[sector];
    return geom::Vec2(play::to_double(s.sound_x), play::to_double(s.sound_y));
  }
  if (const play::Mobj* mo = world_->thing(uint32_t(origin))) return geom::Vec2(play::to_double(mo->x), play::to_double(mo->y));
  return std::nullopt;
}

void Session::say(const std::string& text) {
  message_ = text;
  message_tics_ = 4 * kTicRate;  // Doom's HU_MSGTIMEOUT
}

void Session::advance_message() {
  if (message_tics_ > 0) --message_tics_;
}

// The episode (0 for Doom II's MAPxx) and map number of the WAD map played; false
// for levels that are not a Doom map.
bool Session::any_button() const {
  for (int i = 0; i < play::kMaxPlayers; ++i)
    if (world_->in_game(i) && last_commands_[size_t(i)].buttons) return true;
  return false;
}

bool Session::doom_map_numbers(int& episode, int& number) const {
  if (!source_.is_wad()) return false;
  const std::string map = bsp::resolve_map_name(bsp::read_wads(source_.wads), source_.map);
  episode = 0;
  return std::sscanf(map.c_str(), "MAP%d", &number) == 1 || std::sscanf(map.c_str(), "E%dM%d", &episode, &number) == 2;
}

std::vector<uint8_t> Session::encode_recording(const std::filesystem::path& path) const {
  if (path.extension() != ".lmp") return play::encode_demo(recording_);
  const auto [episode, number] = recording_map_;  // where it started: a Doom demo goes on across levels
  if (number == 0)
    throw Error(path.string() + ": a Doom demo (.lmp) records a WAD's MAPxx or ExMy map, not " + name_);
  play::DoomDemo demo = play::doom_from_demo(recording_, std::max(episode, 1), number, long_tics_);
  demo.deathmatch = flags_.deathmatch;  // a game of one (-deathmatch alone) plays as deathmatch in Doom too
  if (!recorded_others_.empty()) {  // a netgame: every player's command, each tic, in player order
    for (int p = 0; p < play::kMaxPlayers; ++p) demo.players[size_t(p)] = flags_.players[size_t(p)];
    demo.console_player = flags_.console_player;
    const std::vector<play::DoomTic> console = std::move(demo.commands);
    demo.commands.clear();
    for (size_t t = 0; t < console.size() && t < recorded_others_.size(); ++t)
      for (int p = 0; p < play::kMaxPlayers; ++p) {
        if (!flags_.players[size_t(p)]) continue;
        const play::TicCmd& c = recorded_others_[t][size_t(p)];
        demo.commands.push_back(p == flags_.console_player
                                    ? console[t]
                                    : play::DoomTic{c.forward, c.side, long_tics_ ? c.turn : play::doom_demo_turn(c.turn),
                                                    c.buttons});
      }
  }
  return play::encode_doom_demo(demo);
}

bool Session::start_intermission() {
  int episode = 0, number = 0;
  if (!doom_map_numbers(episode, number) || palettes_.empty()) return false;
  final_tally_ = tally();
  const play::Tally& t = final_tally_;
  intermission_ = play::IntermissionArt::load(bsp::read_wads(source_.wads), episode, number, t.next_map);
  if (!intermission_) return false;
  tally_count_.emplace(t, episode == 0, netgame_tally_frags_);
  if (t.netgame && !t.deathmatch) netgame_tally_frags_ = tally_count_->shown().show_frags;
  return true;
}

play::Tally Session::tally() const {
  play::Tally t;
  const play::Player& p = player();
  t.total_kills = world_->total_kills();
  t.total_items = world_->total_items();
  t.total_secrets = world_->total_secrets();
  t.seconds = world_->level_time() / kTicRate;
  const play::GameOptions& o = world_->options();
  t.deathmatch = o.deathmatch != play::Deathmatch::kNone;
  t.me = o.console_player;
  for (int i = 0; i < play::kMaxPlayers; ++i) {
    t.in_game[size_t(i)] = o.in_game[size_t(i)];
    t.frags[size_t(i)] = world_->player(i).frags;
    t.player_kills[size_t(i)] = world_->player(i).kill_count;
    t.player_items[size_t(i)] = world_->player(i).inv.items;
    t.player_secrets[size_t(i)] = world_->player(i).secret_count;
  }
  t.netgame = o.netgame;
  int episode = 0;
  if (doom_map_numbers(episode, t.map)) {
    t.par = play::par_seconds(episode, t.map);
    t.show_par = episode != 4;
    t.did_secret = p.did_secret || (episode != 0 && t.map == 9);  // G_DoCompleted: leaving ExM9 counts
    const std::string next = world_->exit() != play::ExitKind::kNone ? next_map_name() : std::string();
    int next_episode = 0;
    if (!next.empty() && std::sscanf(next.c_str(), "MAP%d", &t.next_map) != 1)
      std::sscanf(next.c_str(), "E%dM%d", &next_episode, &t.next_map);
  }
  return t;
}

void Session::start_recording(bool doom_turns, bool long_tics) {
  recording_on_ = true;
  recording_map_ = {0, 0};
  doom_map_numbers(recording_map_.first, recording_map_.second);
  doom_demo_ = doom_turns || long_tics;
  doom_turns_ = doom_turns && !long_tics;
  long_tics_ = long_tics;
  recording_ = {};
  recorded_others_.clear();
  recording_.level_fingerprint = play::fingerprint(*level_);
  recording_.skill = skill_;
  recording_.fast = flags_.fast;
  recording_.respawn = flags_.respawn;
  recording_.no_monsters = flags_.no_monsters;
  recording_.keys = player().cards;
  // A start other than the map's own is kept (a route's first point).
  const geom::Vec2 map_start = level_->player_start;
  if (std::fabs(pose_.pos.x - map_start.x) > 1.0 / 65536 || std::fabs(pose_.pos.y - map_start.y) > 1.0 / 65536 ||
      std::fabs(pose_.angle - std::fmod(level_->player_angle + 360.0, 360.0)) > 1e-6) {
    recording_.custom_start = true;
    recording_.start = pose_.pos;
    recording_.angle = pose_.angle;
  }
}

// ---- savegames ------------------------------------------------------------------

std::vector<uint8_t> Session::save_game(const std::string& description) const {
  if (!source_.is_wad())
    throw Error("cannot save " + name_ + ": Doom's savegames hold a WAD's MAPxx or ExMy, not a hand-made level");
  if (world_->exit() != play::ExitKind::kNone || intermission_)
    throw Error("cannot save " + name_ + ": the level is over (Doom saves only while a level is played)");
  const wad::Stack wads = bsp::read_wads(source_.wads);
  play::SaveExtras extras;
  extras.tics = tics_;
  extras.message = message_;
  extras.message_tics = message_tics_;
  extras.other_random = other_random_.other_index();
  extras.face = face_.memory();
  extras.previous_pose = {previous_.pos.x, previous_.pos.y, previous_.z, previous_.view_z, previous_.angle};
  std::vector<std::string> warnings;
  std::vector<uint8_t> bytes = play::write_save(*world_, play::DoomNumbers(wads, *level_), description, extras, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "pseudo3d: saving %s: %s\n", name_.c_str(), w.c_str());
  return bytes;
}

std::optional<std::string> Session::save_description(std::span<const uint8_t> bytes) {
  return play::save_description(bytes);
}

// Doom's G_DoLoadGame: the save's game started anew (G_InitNew: the random index
// cleared, the map set up), then the save's player, world and thinkers in place of the
// new ones; then what our extension keeps. Everything is built aside and swapped in
// only when the whole save has been read.
void Session::load_game(std::span<const uint8_t> bytes, const std::string& what, bool doom_only) {
  const play::SaveHeader header = play::read_save_header(bytes, what);
  if (!source_.is_wad()) throw Error(what + ": a Doom savegame loads a WAD's map, and " + name_ + " is none");
  const wad::Stack wads = bsp::read_wads(source_.wads);
  const std::vector<std::string> maps = wads.map_names();
  const bool commercial = std::any_of(maps.begin(), maps.end(), [](const std::string& n) { return n.rfind("MAP", 0) == 0; });
  const std::string map_name = header.map_name(commercial);
  if (!wads.map(map_name))
    throw Error(what + ": byte 41: the save is of " + map_name + ", which these WADs lack (" +
                (commercial ? "a Doom save on Doom II?" : "a Doom II save on Doom?") + ")");
  // The level: this one if the save is of the map played, else the save's map compiled.
  std::unique_ptr<level::Level> new_level;
  std::string new_name = name_;
  if (map_name != bsp::resolve_map_name(wads, source_.map)) {
    bsp::LevelSource source = source_;
    source.map = map_name;
    bsp::OpenedLevel opened = bsp::open_level(source);
    new_level = std::make_unique<level::Level>(std::move(opened.level));
    new_name = opened.name;
  }
  const level::Level& level = new_level ? *new_level : *level_;
  play::GameOptions o = play::game_options_for(wads, map_name, header.skill);
  o.fast = flags_.fast;
  o.respawn = flags_.respawn;
  o.no_monsters = flags_.no_monsters;
  // The save's players (Doom's playeringame); the rest of the game (netgame, deathmatch,
  // the console player) stays this one's, as Doom's load keeps its globals.
  const play::GameOptions& now = world_->options();
  o.in_game = header.in_game;
  o.console_player = now.console_player, o.netgame = now.netgame;
  o.deathmatch = now.deathmatch, o.time_limit = now.time_limit;
  if (!o.in_game[size_t(o.console_player)])
    throw Error(what + ": byte 43: the save has no player " + std::to_string(o.console_player + 1) + ", whose view this game shows");
  auto world = std::make_unique<play::World>(play::map_from_wads(wads, map_name, level), level, o, play::Random{}, nullptr);
  play::carry_over(*world, *world_, header);
  const play::FaceInput fresh_face = play::face_input(world->player());  // ST_Start sees the new player
  const play::LoadedSave loaded = play::read_save(*world, bytes, what, play::DoomNumbers(wads, level), doom_only);
  for (const std::string& w : loaded.warnings) std::fprintf(stderr, "pseudo3d: %s\n", w.c_str());

  // The swap: nothing below throws.
  world_ = std::move(world);
  if (new_level) {
    level_ = std::move(new_level);
    name_ = new_name;
    source_.map = map_name;
    automap_view_.set_level(*level_);
    if (!select_renderer(renderer_name_, false)) select_renderer("bsp", false);
  }
  skill_ = header.skill;
  intermission_.reset();
  tally_count_.reset();
  recording_on_ = false;  // a demo holds one level from its start
  pose_ = pose_now();
  if (loaded.extended) {
    const play::SaveExtras& x = loaded.extras;
    tics_ = x.tics;
    message_ = x.message;
    message_tics_ = x.message_tics;
    other_random_ = play::Random::at(0, x.other_random);
    face_.restore(x.face);
    previous_ = {{x.previous_pose[0], x.previous_pose[1]}, x.previous_pose[2], x.previous_pose[3], x.previous_pose[4]};
  } else {  // as Doom: the messages cleared (HU_Start), M_Random cleared, the face started anew (ST_Start)
    tics_ = uint64_t(world_->level_time());
    message_.clear();
    message_tics_ = 0;
    other_random_ = play::Random{};
    face_.start_level(fresh_face);
    previous_ = pose_;
  }
}

bool Session::reload() {
  const Pose keep = pose_;
  const uint8_t cards = player().cards;
  std::array<play::Player, play::kMaxPlayers> carried = world_->players_for_next_level();
  carried[size_t(world_->options().console_player)].inv = player().inv;  // all of it: the powers too
  const std::string file_name = std::filesystem::path(name_).filename().string();
  std::unique_ptr<level::Level> old_level = std::move(level_);
  std::unique_ptr<play::World> old_world = std::move(world_);
  random_ = old_world->random();
  try {
    load(&carried);
  } catch (const std::exception& e) {
    level_ = std::move(old_level);
    world_ = std::move(old_world);
    automap_view_.set_level(*level_);
    say("not reloaded: " + std::string(e.what()));
    std::fprintf(stderr, "pseudo3d: %s not reloaded, the old level kept: %s\n", file_name.c_str(), e.what());
    return false;
  }
  set_keys(cards);
  // Inside a sector still (Doom's rule would give even the void its leaf's sector); else the ground is gone: the start.
  if (level::sector_at_brute_force(*level_, keep.pos) != level::kNone) spawn(keep.pos, keep.angle);
  if (watch_) watch_->rebase();
  if (!select_renderer(renderer_name_, false)) select_renderer("bsp", false);
  say("reloaded " + file_name);
  std::fprintf(stderr, "pseudo3d: reloaded %s\n", file_name.c_str());
  return true;
}

}  // namespace p3d::game
