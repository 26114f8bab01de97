#include "game/session.h"

#include <cmath>
#include <cstdio>

#include "engine/bsp/load.h"
#include "engine/util/doom.h"
#include "engine/util/error.h"
#include "game/sound_mixer.h"

namespace p3d::game {

const std::vector<std::string>& key_renderers() {
  static const std::vector<std::string> names = {"bsp", "painter", "dda", "sphere", "reference"};
  return names;
}

Session::Session(const bsp::LevelSource& source, int skill) : source_(source), skill_(skill) {
  load();
  player_ = previous_ = world_->spawn();
  select_renderer("bsp");
  message_tics_ = 0;  // nothing to say at the start
}

void Session::load() {
  bsp::OpenedLevel opened = bsp::open_level(source_);
  name_ = opened.name;
  level_ = std::make_unique<level::Level>(std::move(opened.level));
  world_ = std::make_unique<sim::World>(*level_, skill_);
  automap_view_.set_level(*level_);
  sound_origins_ = play::sector_sound_origins(*level_);
  status_art_.reset();
  hud_font_.reset();
  palettes_.clear();
  if (source_.is_wad()) {
    const wad::Stack wads = bsp::read_wads(source_.wads);
    status_art_ = play::StatusBarArt::load(wads);
    hud_font_ = play::HudFont::load(wads);
    palettes_ = wad::Art(wads).palettes();
  }
}

std::string Session::title() const {
  return level_->title.empty() ? std::filesystem::path(name_).filename().string() : level_->title;
}

std::vector<std::filesystem::path> Session::files() const {
  if (source_.is_wad()) return source_.wads;
  return {source_.file};
}

void Session::spawn(geom::Vec2 pos, double angle) {
  player_ = previous_ = world_->spawn_at(pos, angle);
  player_.keys = previous_.keys = all_keys_ ? sim::kAllKeys : 0;
  tics_ = 0;
}

void Session::tic(const sim::TicCommand& cmd) {
  if (world_->exit() != sim::Exit::kNone) return;  // the level is over: waiting for the next one
  previous_ = player_;
  sim::TicCommand played = cmd;
  if (recording_on_ && doom_turns_) played.turn = sim::doom_demo_turn(cmd.turn);
  world_->tick(player_, played);
  ++tics_;
  if (recording_on_) recording_.tics.push_back(played);
  advance_message();
  face_.tic(other_random_, play::FaceInput{.health = player_.inventory.health});
  for (const sim::Event& e : world_->events())
    if (!e.message.empty()) say(e.message);
  if (listening_) keep_sounds();
  if (world_->reborn()) {  // Doom's G_DoReborn in a single-player game: the level from its start
    load();
    spawn(level_->player_start, level_->player_angle);
    return;
  }
  if (world_->exit() != sim::Exit::kNone) {
    recording_on_ = false;  // a demo holds one level: it ends at its exit
    say(world_->exit() == sim::Exit::kSecret ? "secret exit" : "exit");
  }
}

bool Session::enter_next_map() {
  std::string next, why;
  if (source_.is_wad()) {
    const wad::Stack wads = bsp::read_wads(source_.wads);
    const std::string current = bsp::resolve_map_name(wads, source_.map);
    next = doom::next_map(current, world_->exit() == sim::Exit::kSecret,
                          [&](const std::string& name) { return wads.map(name).has_value(); });
    if (next.empty()) why = "no map after " + current;
  } else {
    why = "a hand-made level has no next map";
  }
  if (!next.empty()) source_.map = next;
  intermission_.reset();
  // Doom's G_PlayerFinishLevel: health, armor, ammo and weapons go on to the next
  // map; keys, powers and the flash stay behind.
  play::Inventory carried = player_.inventory;
  carried.powers = {};
  carried.bonus_count = 0;
  carried.items = 0;
  load();
  spawn(level_->player_start, level_->player_angle);
  player_.inventory = previous_.inventory = carried;
  if (!select_renderer(renderer_name_)) select_renderer("bsp");
  say(next.empty() ? why + ": starting it again" : "entered " + next);
  return !next.empty();
}

render::Camera Session::camera(double alpha) const {
  alpha = std::clamp(alpha, 0.0, 1.0);
  double turn = player_.angle - previous_.angle;  // the short way round
  if (turn > 180) turn -= 360;
  if (turn < -180) turn += 360;
  return render::Camera{previous_.pos + (player_.pos - previous_.pos) * alpha,
                        previous_.view_z() + (player_.view_z() - previous_.view_z()) * alpha,
                        previous_.angle + turn * alpha, fov};
}

bool Session::select_renderer(const std::string& name) {
  auto r = render::make_renderer(name, renderer_options);
  if (!r) {
    say("no renderer '" + name + "'");
    return false;
  }
  if (!r->supports(*level_)) {
    say(name + " cannot draw this level (it needs a grid map)");
    return false;
  }
  r->prepare(*level_);
  renderer_ = std::move(r);
  renderer_name_ = name;
  say("renderer: " + name);
  return true;
}

const render::RenderStats& Session::render(render::Frame& frame, double alpha) {
  if (intermission_) {  // the tally in place of the view
    intermission_->draw(tally(), frame, palettes_.front());
    stats_ = {};
    return stats_;
  }
  probe_.want_order = show_automap;
  const int bar = status_bar_rows(frame);
  if (bar > 0 && (view_frame_.width != frame.width || view_frame_.height != frame.height - bar))
    view_frame_ = render::Frame(frame.width, frame.height - bar);
  render::Frame& view = bar > 0 ? view_frame_ : frame;  // the view above the bar, as Doom's 320x168 above its 32 rows
  const int flash = frame.keep_indices ? 0 : flash_palette();
  if (flash) view.keep_indices = true;  // drawn in palette indices, then seen through the flash's palette
  stats_ = renderer_->render(*level_, world_->state(), camera(alpha), view, &probe_);
  if (flash) {
    view.keep_indices = false;
    if (view.indexed()) {
      view.palette = palettes_[size_t(flash)];
      view.resolve_colours();
      view.indices.clear();
    }
  }
  if (bar > 0) {
    std::copy(view_frame_.pixels.begin(), view_frame_.pixels.end(), frame.pixels.begin());
    status_art_->draw(player_.inventory.status(player_.keys, face_.index()), frame,
                      flash ? palettes_[size_t(flash)] : level_->palette);
  }
  if (!show_automap) probe_.order.clear();
  return stats_;
}

int Session::flash_palette() const {
  const int p = play::flash_palette(player_.inventory);  // red while hurt, gold, the suit's green
  return size_t(p) < palettes_.size() ? p : 0;
}

int Session::status_bar_rows(const render::Frame& frame) const {
  if (!status_art_ || !show_status_bar || frame.keep_indices) return 0;
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
    const std::string progress = progress_line(player_.keys, world_->secrets_found(), world_->secrets_total(), player_.noclip);
    if (frame.width < kCompactWidth) {  // a low resolution: one short line
      char fps[32];
      std::snprintf(fps, sizeof fps, "%.0f fps  ", times.fps);
      lines = {fps + progress};
    } else {
      lines = hud_lines(title(), renderer_name_, stats_, times, player_);
      lines.push_back(progress);
    }
    y += draw_panel(frame, margin, y, lines, scale) + margin;
  }
  if (message_tics_ > 0) {  // Doom's messages, top left: in Doom's own font where the WADs have it
    const int doom_scale = play::ScreenPlace::scale_for(frame.width, frame.height);
    if (hud_font_ && frame.width >= 320 && !palettes_.empty())
      hud_font_->draw(frame, message_, 0, 0, doom_scale, 0, y == margin ? 0 : y, palettes_[size_t(flash_palette())]);
    else
      draw_panel(frame, margin, y, {message_}, scale);
  }
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
  constexpr uint64_t kPlayerOrigin = uint64_t(1) << 40;  // beyond every sector's number
  for (const sim::SoundEvent& e : world_->sounds()) {
    if (e.sector == level::kNone)
      sounds_.push_back({e.sound, kPlayerOrigin, std::nullopt});
    else
      sounds_.push_back({e.sound, uint64_t(e.sector) + 1, sound_origins_[size_t(e.sector)]});
  }
}

const play::SoundClip* Session::sound_clip(play::Sound sound) {
  if (!source_.is_wad()) return nullptr;
  if (const auto it = clips_.find(sound); it != clips_.end()) return it->second ? &*it->second : nullptr;
  std::optional<play::SoundClip>& clip = clips_[sound];
  const std::string lump_name = play::sound_lump_name(sound);
  try {
    if (!sound_wads_) sound_wads_ = std::make_unique<wad::Stack>(bsp::read_wads(source_.wads));
    if (const wad::Lump* lump = sound_wads_->find(lump_name))
      clip = play::decode_dmx(lump->bytes, source_.wads.back().filename().string() + ": " + lump_name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "game: %s (not played)\n", e.what());
  }
  return clip ? &*clip : nullptr;
}

play::Listener Session::listener() const { return listener_at(player_.pos, player_.angle); }

void Session::say(const std::string& text) {
  message_ = text;
  message_tics_ = 4 * sim::kTicRate;  // Doom's HU_MSGTIMEOUT
}

void Session::advance_message() {
  if (message_tics_ > 0) --message_tics_;
}

// The episode (0 for Doom II's MAPxx) and map number of the WAD map played; false
// for levels that are not a Doom map.
bool Session::doom_map_numbers(int& episode, int& number) const {
  if (!source_.is_wad()) return false;
  const std::string map = bsp::resolve_map_name(bsp::read_wads(source_.wads), source_.map);
  episode = 0;
  return std::sscanf(map.c_str(), "MAP%d", &number) == 1 || std::sscanf(map.c_str(), "E%dM%d", &episode, &number) == 2;
}

std::vector<uint8_t> Session::encode_recording(const std::filesystem::path& path) const {
  if (path.extension() != ".lmp") return sim::encode_demo(recording_);
  int episode = 0, number = 0;
  if (!doom_map_numbers(episode, number))
    throw Error(path.string() + ": a Doom demo (.lmp) records a WAD's MAPxx or ExMy map, not " + name_);
  return play::encode_doom_demo(sim::doom_from_demo(recording_, std::max(episode, 1), number));
}

bool Session::start_intermission() {
  int episode = 0, number = 0;
  if (!doom_map_numbers(episode, number) || palettes_.empty()) return false;
  intermission_ = play::IntermissionArt::load(bsp::read_wads(source_.wads), episode, number);
  return intermission_.has_value();
}

play::Tally Session::tally() const {
  play::Tally t;
  const level::State start = level::start_state(*level_, skill_);  // what the level held: the totals
  for (const level::ShownThing& shown : start.things) {
    if (shown.placed == level::kNone) continue;
    const play::ThingType type = play::thing_type_for_editor_number(level_->things[size_t(shown.placed)].type);
    if (type == play::ThingType::kCount) continue;
    t.total_kills += (play::thing_info(type).flags & play::kCountkill) != 0;
    t.total_items += (play::thing_info(type).flags & play::kCountitem) != 0;
  }
  t.items = player_.inventory.items;
  t.secrets = world_->secrets_found();
  t.total_secrets = world_->secrets_total();
  t.seconds = int(tics_ / sim::kTicRate);
  return t;
}

void Session::start_recording(bool doom_turns) {
  recording_on_ = true;
  doom_turns_ = doom_turns;
  recording_ = {sim::fingerprint(*level_), player_.pos, player_.angle, skill_, player_.keys, {}};
}

bool Session::reload() {
  const sim::Player keep = player_;
  const std::string file_name = std::filesystem::path(name_).filename().string();
  std::unique_ptr<level::Level> old_level = std::move(level_);
  std::unique_ptr<sim::World> old_world = std::move(world_);
  try {
    load();
  } catch (const std::exception& e) {
    level_ = std::move(old_level);
    world_ = std::move(old_world);
    automap_view_.set_level(*level_);
    say("not reloaded: " + std::string(e.what()));
    std::fprintf(stderr, "game: %s not reloaded, the old level kept: %s\n", file_name.c_str(), e.what());
    return false;
  }
  if (level_->sector_at(keep.pos) != level::kNone) {
    player_ = previous_ = keep;
    player_.z = previous_.z = std::max(keep.z, world_->heights_at(keep.pos).floor);
  } else {  // the ground under the player is gone
    const uint8_t keys = keep.keys;
    player_ = previous_ = world_->spawn();
    set_keys(keys);
  }
  if (watch_) watch_->rebase();
  if (!select_renderer(renderer_name_)) select_renderer("bsp");
  say("reloaded " + file_name);
  std::fprintf(stderr, "game: reloaded %s\n", file_name.c_str());
  return true;
}

}  // namespace p3d::game
