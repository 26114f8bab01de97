#include "game/headless.h"

#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "engine/front/finale.h"
#include "engine/front/game_mode.h"
#include "engine/front/menu_art.h"
#include "engine/image/image.h"
#include "engine/play/dehacked.h"
#include "engine/play/thing_dump.h"
#include "engine/wad/art.h"
#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::game {

const char* exit_name(play::ExitKind exit) {
  switch (exit) {
    case play::ExitKind::kNormal: return "normal";
    case play::ExitKind::kSecret: return "secret";
    case play::ExitKind::kNone: break;
  }
  return "none";
}

namespace {

// Where the player stands and what it carries, as the CSV and JSON give it.
Stats player_fields(const Session& session, int frame, size_t tic, bool raw) {
  const Session::Pose pose = session.pose();
  const play::Player& p = session.player();
  Stats out = {{"frame", double(frame)},
          {"tic", double(tic)},
          {"x", pose.pos.x},
          {"y", pose.pos.y},
          {"z", pose.z},
          {"angle", pose.angle},
          {"health", double(p.inv.health)},
          {"armor", double(p.inv.armor)},
          {"kills", double(p.kill_count)},
          {"items", double(p.inv.items)},
          {"secrets", double(p.secret_count)},
          {"keys", double(p.cards)}};
  if (raw && p.mo)
    for (const auto& [name, value] : {std::pair<const char*, double>{"x_raw", p.mo->x}, {"y_raw", p.mo->y}, {"z_raw", p.mo->z},
                                      {"angle_raw", double(p.mo->angle)}, {"momx_raw", p.mo->mom_x}, {"momy_raw", p.mo->mom_y},
                                      {"viewz_raw", p.view_z}, {"random", session.world().random().play_index()}})
      out.push_back({name, value});
  return out;
}

// Doom's way from a level's end to the next map, between a demo's tics (G_DoCompleted,
// WI_Ticker, F_Ticker, G_DoWorldDone), as Chocolate Doom replays a demo that exits: the
// tally, counted on until a press hurries it, Doom II's text between its clusters, then
// the next map, the players' health, armour and weapons going with them. The game ends
// at an episode's end (Doom's eighth maps, Doom II's MAP30), after the last map, and at
// the exit of a level that is no Doom map. FrontEnd::level_tic takes the same steps,
// with the screens melting between them.
class BetweenLevels {
 public:
  // After each tic: false once the game is over.
  bool after_tic(Session& s) {
    if (finale_) return finale_tic(s);
    if (s.in_intermission()) return !s.intermission_over() || next_map(s);
    if (s.exited() == play::ExitKind::kNone) return true;
    if (!s.source().is_wad()) return false;
    if (doom(s).mode != front::GameMode::kCommercial && start_finale(s)) return false;  // an episode's end: no tally
    return s.start_intermission() || next_map(s);
  }
  // Whether this tic's world is a level's (not the tally's or Doom II's text).
  bool in_level(const Session& s) const { return !finale_ && !s.in_intermission() && s.exited() == play::ExitKind::kNone; }
  // Draws Doom II's text between clusters while it shows; false when it does not.
  bool draw_finale(render::Frame& frame) const {
    if (!finale_) return false;
    frame.pixels.resize(size_t(frame.width) * size_t(frame.height));
    finale_->draw(doom_->art, doom_->wads, frame, doom_->palette);
    return true;
  }

 private:
  // The WADs' art and texts, read at the first exit.
  struct DoomArt {
    explicit DoomArt(const bsp::LevelSource& source)
        : wads(bsp::read_wads(source.wads)), art(wads), texts(play::dehacked_texts(wads)), mode(front::game_mode(wads)) {
      const wad::Art palettes(wads);
      if (!palettes.palettes().empty()) palette = palettes.palettes().front();
    }
    wad::Stack wads;
    front::MenuArt art;  // holds a reference to wads
    std::map<std::string, std::string> texts;
    front::GameMode mode;
    std::vector<uint32_t> palette;
  };
  DoomArt& doom(const Session& s) {
    if (!doom_) doom_ = std::make_unique<DoomArt>(s.source());
    return *doom_;
  }
  // F_StartFinale where Doom has one after the map just left; false where it has none.
  bool start_finale(Session& s) {
    int episode = 0, map = 0;
    if (!s.doom_map_numbers(episode, map)) return false;
    if (!front::has_finale(doom(s).mode, episode, map, s.exited() == play::ExitKind::kSecret)) return false;
    const DoomArt& d = doom(s);
    finale_.emplace(d.mode, episode, map, [&d](const std::string& mnemonic) {
      const std::string english = play::english_text(mnemonic);
      const auto it = d.texts.find(english);
      return it != d.texts.end() ? it->second : english;
    });
    return true;
  }
  // G_WorldDone: Doom II's text when a cluster ends, else the next map.
  bool next_map(Session& s) {
    if (doom(s).mode == front::GameMode::kCommercial && start_finale(s)) return true;
    return enter(s);
  }
  bool enter(Session& s) {
    if (s.next_map_name().empty()) return false;
    s.enter_next_map();
    return true;
  }
  // F_Ticker: Doom II's text gives way at any player's button after 50 tics.
  bool finale_tic(Session& s) {
    const front::Finale::Next next = finale_->tic(s.any_button());
    if (next == front::Finale::Next::kStay) return true;
    finale_.reset();
    return next == front::Finale::Next::kNextMap && enter(s);
  }

  std::unique_ptr<DoomArt> doom_;
  std::optional<front::Finale> finale_;
};

void save_to(const Session& session, const std::filesystem::path& file) {
  write_file_atomically(file, session.save_game("p3d " + session.name().substr(session.name().rfind(':') + 1)));
}

}  // namespace

HeadlessResult replay_headless(Session& session, const play::Demo& demo, const HeadlessOptions& o) {
  if (demo.level_fingerprint != play::fingerprint(session.level()))
    throw Error("the demo was recorded on a different level than " + session.name());
  std::filesystem::create_directories(o.out_dir);
  if (demo.custom_start) session.spawn(demo.start, demo.angle);
  session.set_keys(demo.keys);
  render::Frame frame(o.width, o.height);
  std::string csv;
  std::string json = "{\"level\": " + json_string(session.name()) + ", \"frames\": [\n";
  HeadlessResult result;
  result.maps.push_back(session.map_name());
  BetweenLevels between;
  bool game_over = false;
  std::string things;
  uint64_t level_tics = 0;  // the things are dumped after each tic in a level, numbered on across levels
  for (size_t tic = 0;; ++tic) {
    const bool last = tic == demo.tics.size() || game_over;
    if (tic % size_t(o.capture_every) == 0 || last) {
      render::RenderStats s;
      if (o.frames) {
        if (!between.draw_finale(frame)) s = session.render(frame, 1.0);
        char name[32];
        std::snprintf(name, sizeof name, "frame%05d.png", result.frames);
        image::save_png(frame, o.out_dir / name);
      }
      const Stats where = player_fields(session, result.frames, tic, o.raw);
      const std::vector<Stat> drawn = o.frames ? render::stat_fields(s) : std::vector<Stat>{};
      if (csv.empty()) {  // the header, from the first row's fields
        for (const Stat& f : where) csv += (csv.empty() ? "" : ",") + f.name;
        if (o.frames) csv += ",renderer";
        for (const Stat& f : drawn) csv += "," + f.name;
        csv += ",exit\n";
      }
      std::string row;
      for (const Stat& f : where) row += (row.empty() ? "" : ",") + stat_number(f.value);
      if (o.frames) row += "," + session.renderer_name();
      for (const Stat& f : drawn) row += "," + stat_number(f.value);
      csv += row + "," + exit_name(session.exited()) + "\n";
      json += std::string(result.frames ? ",\n" : "") + "  {\"player\": " + stats_json(where);
      if (o.frames)
        json += ", \"renderer\": " + json_string(session.renderer_name()) + ", \"stats\": " + stats_json(drawn);
      json += ", \"exit\": " + json_string(exit_name(session.exited())) + "}";
      ++result.frames;
    }
    if (last) {
      result.tics = tic;
      break;
    }
    const bool level_tic = between.in_level(session);
    session.tic(demo.tics[tic]);
    if (level_tic && !o.thing_dump.empty()) things += play::dump_things(session.world(), level_tics++);
    const std::string map = session.source().map;
    game_over = !between.after_tic(session);
    if (session.source().map != map) result.maps.push_back(session.map_name());
    if (result.beyond_chocolate.empty() && !session.world().beyond_chocolate().empty())
      result.beyond_chocolate = "demo tic " + std::to_string(tic) + " (" + session.world().beyond_chocolate() + ")";
    for (const HeadlessOptions::SaveAt& s : o.saves)
      if (s.tic == tic) save_to(session, s.file);
    for (const HeadlessOptions::SaveAt& l : o.loads)
      if (l.tic == tic) session.load_game(read_file_bytes(l.file), l.file.string(), o.loads_doom_only);
  }
  result.exit = session.exited();
  write_file_atomically(o.out_dir / "stats.csv", csv);
  if (o.json) write_file_atomically(o.out_dir / "stats.json", json + "\n]}\n");
  if (!o.thing_dump.empty()) write_file_atomically(o.thing_dump, things);
  return result;
}

}  // namespace p3d::game
