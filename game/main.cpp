// game: Doom's front end on a WAD (title loop, menus, saves) or a level walked in a
// window; demos recorded and replayed; or, headless, a demo replayed into PNG frames
// and a stats CSV, a route walked, or a key script run through the menus.
#include <cctype>
#include <cstdio>

#include "engine/bsp/load.h"
#include "engine/play/doom_demo.h"
#include "engine/play/thing_dump.h"
#include "engine/render/camera_file.h"
#include "engine/util/doom.h"
#include "engine/util/file.h"
#include "game/autopilot.h"
#include "game/headless.h"
#include "game/key_script.h"
#include "game/netgame.h"
#include "game/sdl_platform.h"
#include "game/settings.h"
#include "tools/cli.h"

using namespace p3d;

namespace {

std::vector<game::Waypoint> route(const std::string& path) {
  return game::route_from_cameras(render::read_camera_list(path));
}

// Walks the waypoints with no window at all, until the last or the level's exit;
// returns the tics recorded.
size_t autopilot_headless(game::Session& session, const std::vector<game::Waypoint>& route, uint64_t max_tics) {
  game::Autopilot pilot(route);
  while (!pilot.done() && session.exited() == play::ExitKind::kNone && (!max_tics || session.tics() < max_tics))
    session.tic(pilot.next(session.pose().pos, session.pose().angle));
  return session.recording().tics.size();
}

// Whether the WADs hold Doom II's maps (MAPxx) rather than Doom's (ExMy).
bool has_doom2_maps(const bsp::LevelSource& source) {
  const auto names = bsp::read_wads(source.wads).map_names();
  return std::any_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind("MAP", 0) == 0; });
}

// A demo's bytes: a file, or else a WAD's DEMOn lump by that name.
struct DemoBytes {
  std::vector<uint8_t> bytes;
  std::string what;  // for messages
};
DemoBytes demo_bytes(const std::string& name, const bsp::LevelSource& source) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(name, ec)) return {read_file_bytes(name), name};
  const std::string lump = wad::normalize_name(name);
  const bool lump_name = lump.size() == 5 && lump.compare(0, 4, "DEMO") == 0 && std::isdigit(static_cast<unsigned char>(lump[4]));
  if (!source.is_wad() || !lump_name)
    throw cli::ValidationError("--play", name + ": no such file" + std::string(source.is_wad() ? " or DEMOn lump" : ""));
  const wad::Stack wads = bsp::read_wads(source.wads);
  const wad::Lump* found = wads.find(lump);
  if (!found) throw cli::ValidationError("--play", name + ": no such file, and the WADs have no lump " + lump);
  return {{found->bytes.begin(), found->bytes.end()}, source.wads.back().filename().string() + ":" + lump};
}

// What a Doom demo holds that is not played as recorded, said once.
void say_what_is_not_played(const play::DoomDemo& d, const std::string& what) {
  if (d.truncated) std::fprintf(stderr, "pseudo3d: %s: ends without Doom's end marker (played as far as it goes)\n", what.c_str());
}

// Doom's -warp: "MAP" on a Doom II IWAD (MAPxx maps), "EPISODE [MAP]" on Doom's (ExMy).
std::string warp_map(const bsp::LevelSource& source, const std::vector<int>& warp) {
  if (has_doom2_maps(source)) return doom::map_name(true, 1, warp[0]);
  return doom::map_name(false, warp[0], warp.size() > 1 ? warp[1] : 1);
}

// The console player's commands of a demo (ours or Doom's), tic by tic.
std::vector<play::TicCmd> console_tics(const std::string& path, const bsp::LevelSource& source) {
  const DemoBytes bytes = demo_bytes(path, source);
  std::vector<play::TicCmd> out;
  if (play::is_our_demo(bytes.bytes)) {
    for (const play::DemoTic& t : play::decode_demo(bytes.bytes, bytes.what).tics) out.push_back(t.cmd);
    return out;
  }
  const play::DoomDemo d = play::decode_doom_demo(bytes.bytes, bytes.what);
  for (size_t t = 0; t < d.tic_count(); ++t) {
    const play::DoomTic c = d.console_tic(t);
    out.push_back({c.forward, c.side, c.turn, c.buttons});
  }
  return out;
}

// The game we would start as a netgame's controller: the map, the skill, the rules.
net::GameSettings net_settings(const bsp::LevelSource& source, int skill, const game::GameFlags& flags) {
  const wad::Stack wads = bsp::read_wads(source.wads);
  const std::string map = bsp::resolve_map_name(wads, source.map);
  const play::GameOptions o = play::game_options_for(wads, map, skill);
  net::GameSettings s;
  s.episode = o.commercial ? 1 : o.episode, s.map = o.map;
  s.skill = skill - 1;
  s.deathmatch = flags.deathmatch, s.time_limit = flags.time_limit;
  s.no_monsters = flags.no_monsters, s.fast_monsters = flags.fast, s.respawn_monsters = flags.respawn;
  return s;
}

// The settings from their file, each warning said once.
game::Settings read_settings(const std::filesystem::path& path) {
  std::vector<std::string> warnings;
  game::Settings s = game::load_settings(path, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "pseudo3d: %s\n", w.c_str());
  return s;
}

// Doom's music: -nomusic, the sound font, the volume.
void add_music_options(cli::App& app, bool& no_music, std::string& soundfont, int& volume) {
  app.add_flag("--nomusic", no_music, "no music (Doom's -nomusic)");
  app.add_option("--soundfont", soundfont,
                 "the music's SoundFont (.sf2); default: $SDL_SOUNDFONTS, else Debian's fluid-soundfont-gm");
  app.add_option("--music-volume", volume, "Doom's music volume, 0 to 15 (default: the settings', 8)")
      ->check(cli::Range(0, 15));
}

}  // namespace

int main(int argc, char** argv) {
  cli::App app{"pseudo3d: Doom's front end on a WAD (title, menus, saves), or walk a level (.bsp, .map, .grid)", "pseudo3d"};
  cli::LevelArgs level_args;
  std::vector<int> warp;
  std::string record, play, out_dir, resolution, window, renderer, autopilot, script, config;
  bool headless = false, fullscreen = false, windowed = false, no_vsync = false, map_reload = false, timedemo = false;
  bool long_tics = false;
  bool all_keys = false, json = false, no_sound = false, no_status_bar = false, stats_only = false;
  bool no_music = false;
  std::string soundfont;
  int music_volume = -1;
  game::GameFlags flags;
  int capture_every = 35;
  uint64_t quit_after = 0;
  int skill = level::kDefaultSkill;
  double fov = 90, sensitivity = 0;
  cli::add_level_options(app, level_args);
  app.add_option("--warp", warp, "start on a WAD map as Doom's -warp: MAP (Doom II) or EPISODE [MAP]")
      ->expected(1, 2)
      ->check(cli::Range(0, 99));
  app.add_option("--record", record, "record every tic's input to this demo file (x.lmp: as a Doom v1.9 demo)");
  app.add_flag("--longtics", long_tics, "with --record x.lmp: Doom v1.91's long tics (whole turns), as Chocolate's -longtics");
  app.add_option("--play", play,
                 "replay this demo, then quit: our .demo, a Doom .lmp, or a WAD's DEMO1..DEMO4 lump (--play demo1)");
  app.add_flag("--timedemo", timedemo, "with --play: one tic per frame as fast as possible, then report the fps");
  app.add_flag("--headless", headless,
               "no window: with --play, write frames and stats; with --autopilot, record; with --script, run it");
  app.add_option("--script", script, "--headless: drive Doom's front end by this key script (game/key_script.h)")
      ->check(cli::existing_file());
  app.add_option("--capture-every", capture_every, "--headless: tics between captured frames")
      ->check(cli::Range(1, 1 << 20))
      ->capture_default_str();
  app.add_option("--out", out_dir, "--headless: directory for the frames and stats.csv (a netgame's saves: DIR/savegames)");
  app.add_flag("--json", json, "--headless --play: also stats.json, the same statistics by name");
  app.add_flag("--stats-only", stats_only, "--headless --play: stats.csv alone, no frames drawn (as fast as the rules run)");
  std::vector<std::pair<size_t, std::string>> save_at, load_at;
  bool load_doom_only = false, raw_stats = false;
  app.add_option("--save-at", save_at,
                 "--headless --play: after the demo's tic N (0 the first), save the game to FILE (Doom's format); "
                 "repeatable")
      ->type_name("N FILE");
  app.add_option("--load-at", load_at,
                 "--headless --play: after the demo's tic N, load FILE's game and go on with the demo's input; repeatable")
      ->type_name("N FILE");
  app.add_flag("--load-doom-only", load_doom_only,
               "--load-at: load as Doom (Chocolate Doom) does, ignoring what our extension keeps");
  app.add_flag("--raw-stats", raw_stats,
               "--headless --play: stats.csv also gives Doom's exact values (16.16 x, y, z, momentum, view z, "
               "binary angle, random index)");
  std::string dump_things;
  app.add_option("--dump-things", dump_things,
                 "--headless --play: write every thing after every tic to this file (tools/peers/demo_batch.py compares "
                 "it with Chocolate Doom's), to find where two replays part")
      ->type_name("FILE");
  app.add_flag("--fast", flags.fast, "Doom's -fast: faster demons and monster missiles");
  app.add_flag("--respawn", flags.respawn, "Doom's -respawn: dead monsters come back (as in nightmare)");
  app.add_flag("--nomonsters", flags.no_monsters, "Doom's -nomonsters: no monsters are spawned");
  bool deathmatch = false, altdeath = false, avg = false;
  app.add_flag("--deathmatch", deathmatch, "Doom's -deathmatch: deathmatch starts, every key, weapons stay");
  app.add_flag("--altdeath", altdeath, "Doom's -altdeath: deathmatch where items and weapons come back after 30 s");
  app.add_option("--timer", flags.time_limit, "Doom's -timer: a deathmatch level ends after this many minutes")
      ->check(cli::Range(1, 1000000));
  app.add_flag("--avg", avg, "Doom's -avg: a deathmatch level ends after 20 minutes (Austin Virtual Gaming)");
  app.add_option("--resolution,--size", resolution, "render at this fixed WxH (320x200 for the old look); "
                 "default: the window's size (640x400 headless)");
  app.add_option("--window", window, "window size WxH (default: the settings', 960x600)");
  app.add_flag("--fullscreen", fullscreen, "start fullscreen (Alt+Enter toggles)");
  app.add_flag("--windowed", windowed, "start in a window even if the settings say fullscreen");
  app.add_flag("--no-vsync", no_vsync, "uncapped frame rate");
  app.add_option("--renderer", renderer, "bsp, painter, dda, sphere, sphere-naive or reference (default: the settings', bsp)");
  app.add_option("--fov", fov, "horizontal field of view")->check(cli::finite_range(30.0, 160.0))->capture_default_str();
  app.add_flag("--nosound", no_sound, "no sound effects and no music (headless runs are always silent)");
  add_music_options(app, no_music, soundfont, music_volume);
  app.add_flag("--no-status-bar", no_status_bar, "WAD levels: the view fills the frame, without Doom's status bar");
  app.add_flag("--map-reload", map_reload, "recompile and reload the level when its source or WAD changes on disk");
  app.add_option("--autopilot", autopilot,
                 "walk through these waypoints (a camera list; a camera named 'use' presses use there, 'wait' waits) "
                 "instead of reading input")
      ->check(cli::existing_file());
  app.add_option("--sensitivity", sensitivity, "mouse turn per pixel, in 1/65536 of a turn (default: from the menu's "
                 "mouse sensitivity)")
      ->check(cli::finite_range(0.0, 10000.0));
  app.add_option("--config", config, "the settings file (default: $XDG_CONFIG_HOME/pseudo3d/settings.cfg)");
  std::string connect, net_input;
  int nodes = 0, port = 0;
  bool serve = false;
  app.add_flag("--server", serve, "serve a netgame on this machine and join it (Chocolate Doom's -server): its "
               "players join with --connect or Chocolate Doom's -connect");
  app.add_option("--port", port, "--server: the UDP port (default 2342)")->check(cli::Range(1, 65535));
  app.add_option("--connect", connect,
                 "join a netgame on this Chocolate Doom server (HOST[:PORT], port 2342 by default): chocolate-server, "
                 "or chocolate-doom -server");
  app.add_option("--nodes", nodes, "--connect: as the first to join, start the game when this many players have joined")
      ->check(cli::Range(1, play::kMaxPlayers));
  app.add_option("--net-input", net_input, "--connect --headless: our player's commands, tic by tic, from this demo "
                 "(its console player's; then standing still)")
      ->check(cli::existing_file());
  app.add_option("--quit-after-tics", quit_after, "quit after this many tics (0: never)")->capture_default_str();
  cli::add_skill_option(app, skill);
  render::RendererOptions renderer_options;
  cli::add_renderer_options(app, renderer_options);
  app.add_flag("--all-keys", all_keys, "start every map with every key (recorded in demos)");

  return cli::run(app, argc, argv, [&] {
    if (!play.empty() && !autopilot.empty()) throw cli::ValidationError("--play", "use either --play or --autopilot");
    if (timedemo && play.empty()) throw cli::ValidationError("--timedemo", "needs --play");
    if (json && (!headless || play.empty())) throw cli::ValidationError("--json", "needs --headless --play");
    if (!script.empty() && (!headless || !play.empty() || !autopilot.empty()))
      throw cli::ValidationError("--script", "needs --headless, without --play or --autopilot");
    if (headless && play.empty() && autopilot.empty() && script.empty() && connect.empty() && !serve)
      throw cli::ValidationError("--headless", "needs --play (to capture frames), --autopilot (to record), --script, --connect or --server");
    if (headless && (!play.empty() || !script.empty()) && out_dir.empty())
      throw cli::ValidationError("--out", "--headless --play and --script need --out DIR");
    if (fullscreen && windowed) throw cli::ValidationError("--fullscreen", "use either --fullscreen or --windowed");

    // The settings, with what the command line says for this run on top.
    const std::filesystem::path settings_file = config.empty() ? game::settings_path() : std::filesystem::path(config);
    const game::Settings saved = headless ? game::Settings{} : read_settings(settings_file);
    game::Settings settings = saved;
    if (!window.empty()) cli::parse_size(window, settings.window_width, settings.window_height, "--window");
    if (deathmatch && altdeath) throw cli::ValidationError("--altdeath", "use either --deathmatch or --altdeath");
    flags.deathmatch = altdeath ? 2 : deathmatch ? 1 : 0;
    if (avg) flags.time_limit = 20;  // Doom's -avg
    if (flags.time_limit && !flags.deathmatch)
      throw cli::ValidationError("--timer", "--timer and --avg end deathmatch levels: add --deathmatch or --altdeath");
    if (fullscreen || windowed) settings.fullscreen = fullscreen;
    if (!renderer.empty()) settings.renderer = renderer;
    if (music_volume >= 0) settings.menu.music_volume = music_volume;

    // No level named: the WAD played last, or an IWAD found where Doom's are.
    if (level_args.path.empty() && level_args.iwad.empty()) {
      std::error_code ec;
      if (!saved.last_wad.empty() && std::filesystem::is_regular_file(saved.last_wad, ec))
        level_args.iwad = saved.last_wad.string();
      else if (const std::filesystem::path found = game::find_iwad(); !found.empty())
        level_args.iwad = found.string();
    }
    bsp::LevelSource source = cli::level_source(level_args);
    if (!warp.empty()) {
      if (!source.is_wad()) throw cli::ValidationError("--warp", "picks a map in WADs: use it with --iwad");
      if (!level_args.map.empty()) throw cli::ValidationError("--warp", "use either --warp or --map");
      source.map = warp_map(source, warp);
    }
    if (map_reload && !source.is_wad() && !bsp::is_source_path(source.file))
      throw cli::ValidationError("--map-reload", "needs a .map or .grid source or a WAD, not a compiled level");
    int rw = 0, rh = 0;
    if (!resolution.empty()) cli::parse_size(resolution, rw, rh, "--resolution");
    if (source.is_wad() && !level_args.iwad.empty()) settings.last_wad = std::filesystem::absolute(level_args.iwad);

    game::FrontEndOptions front_options;
    front_options.flags = flags;
    front_options.mouse_turn = sensitivity;
    if (source.is_wad()) front_options.save_dir = game::save_directory(source.wads.front());

    // Doom's start: the title loop, when a WAD is played and nothing else asked for.
    const bool title = source.is_wad() && source.map.empty() && warp.empty() && play.empty() && autopilot.empty() &&
                       record.empty() && !map_reload;
    if (headless && !script.empty()) {
      if (!source.is_wad()) throw cli::ValidationError("--script", "drives Doom's front end: name a WAD with --iwad");
      front_options.save_dir = std::filesystem::path(out_dir) / "savegames";  // never the player's own slots
      std::unique_ptr<game::FrontEnd> front =
          title ? std::make_unique<game::FrontEnd>(source, settings, front_options)
                : std::make_unique<game::FrontEnd>(std::make_unique<game::Session>(source, skill, flags), settings,
                                                   front_options);
      const auto steps = game::parse_key_script(read_file_text(script), script);
      const game::ScriptResult r = game::run_key_script(*front, steps, out_dir, rw ? rw : 320, rh ? rh : 200);
      std::printf("ran %llu tics, wrote %d frames and log.txt to %s\n", (unsigned long long)r.tics, r.shots,
                  out_dir.c_str());
      return 0;
    }

    std::optional<play::Demo> demo;
    std::optional<play::DoomDemo> doom_demo;
    if (stats_only && (!headless || play.empty())) throw cli::ValidationError("--stats-only", "needs --headless --play");
    if (serve && !connect.empty()) throw cli::ValidationError("--server", "use either --server or --connect");
    if (port && !serve) throw cli::ValidationError("--port", "needs --server");
    if (serve) connect = "127.0.0.1:" + std::to_string(port ? port : net::kDefaultPort);
    game::NetGameOptions n;
    n.host_port = serve ? (port ? port : net::kDefaultPort) : 0;
    if (!connect.empty()) {
      if (!source.is_wad()) throw cli::ValidationError("--connect", "a netgame plays a WAD's maps: name the IWAD with --iwad");
      if (!play.empty() || !autopilot.empty()) throw cli::ValidationError("--connect", "plays the keys' input, or --net-input's");
      if (!net_input.empty() && !headless) throw cli::ValidationError("--net-input", "needs --headless");
      n.connect = connect;
      n.launch_at_players = nodes;
      n.quit_after_tics = quit_after;
      n.record = record;
      n.long_tics = long_tics;
      n.settings = net_settings(source, skill, flags);
      n.wait_seconds = headless ? 60 : 0;  // a script waits a minute for the others; a player as long as it takes
      if (headless && !out_dir.empty()) n.save_dir = std::filesystem::path(out_dir) / "savegames";  // never the player's slots
    }
    if (!connect.empty() && headless) {
      const std::vector<play::TicCmd> input = net_input.empty() ? std::vector<play::TicCmd>{} : console_tics(net_input, source);
      // The things after each tic played in a level (not the tally's), numbered on
      // across levels as Chocolate's P3D_DUMP numbers them; written even when the game
      // parts, to show where.
      std::string things;
      uint64_t level_tics = 0;
      std::pair<const play::World*, int> last_dumped{nullptr, -1};
      auto dump = [&](const game::Session& s, uint64_t) {
        const std::pair<const play::World*, int> now{&s.world(), s.world().level_time()};
        if (dump_things.empty() || now == last_dumped || now.second == 0) return;  // 0: a level set up, not played
        things += play::dump_things(s.world(), level_tics++);
        last_dumped = now;
      };
      uint64_t tics = 0;
      try {
        tics = game::play_netgame_headless(
            source, n, [&](uint64_t t) { return t < input.size() ? input[t] : play::TicCmd{}; }, dump);
      } catch (const std::exception&) {
        if (!dump_things.empty()) write_file_atomically(dump_things, things);
        throw;
      }
      if (!dump_things.empty()) write_file_atomically(dump_things, things);
      std::printf("played %llu tics of a netgame on %s%s\n", (unsigned long long)tics, connect.c_str(),
                  record.empty() ? "" : (", recorded to " + record).c_str());
      return 0;
    }
    if ((!net_input.empty() || nodes) && connect.empty())
      throw cli::ValidationError("--net-input", "--net-input and --nodes need --connect");
    if ((!save_at.empty() || !load_at.empty() || raw_stats || !dump_things.empty()) && (!headless || play.empty()))
      throw cli::ValidationError("--save-at", "--save-at, --load-at, --raw-stats and --dump-things need --headless --play");
    if (load_doom_only && load_at.empty()) throw cli::ValidationError("--load-doom-only", "needs --load-at");
    if (!play.empty()) {
      const DemoBytes bytes = demo_bytes(play, source);
      if (play::is_our_demo(bytes.bytes)) {
        demo = play::decode_demo(bytes.bytes, bytes.what);
        skill = demo->skill;  // the game the demo recorded
        flags = {demo->fast, demo->respawn, demo->no_monsters};
      } else {
        doom_demo = play::decode_doom_demo(bytes.bytes, bytes.what);
        if (!source.is_wad()) throw Error(bytes.what + ": a Doom demo plays a WAD's map: name the IWAD with --iwad");
        if (level_args.map.empty() && warp.empty()) source.map = doom_demo->map_name(has_doom2_maps(source));
        skill = doom_demo->skill;
        const int time_limit = flags.time_limit;  // a demo holds no timer: Doom's -timer plays it too
        flags = game::flags_of(*doom_demo);
        flags.time_limit = time_limit;
        say_what_is_not_played(*doom_demo, bytes.what);
      }
    }

    auto keep_settings = [&](const game::Settings& live) {
      game::Settings out = live;  // what the command line changed for this run is not kept
      if (!window.empty()) out.window_width = saved.window_width, out.window_height = saved.window_height;
      if (fullscreen || windowed) out.fullscreen = saved.fullscreen;
      if (!renderer.empty()) out.renderer = saved.renderer;
      if (music_volume >= 0 && out.menu.music_volume == music_volume) out.menu.music_volume = saved.menu.music_volume;
      std::string why;
      if (!settings_file.empty() && !game::save_settings(out, settings_file, why))
        std::fprintf(stderr, "pseudo3d: settings not saved: %s\n", why.c_str());
    };
    game::WindowOptions o;
    o.render_width = rw, o.render_height = rh;
    o.vsync = !no_vsync;
    o.sound = !no_sound;
    o.music = !no_music && !no_sound;
    o.soundfont = soundfont;
    o.keep_settings = keep_settings;
    o.wad_changed = settings.last_wad != saved.last_wad;
    o.quit_after_tics = quit_after;
    if (!connect.empty()) {  // a netgame in the window: joined and started first, here
      game::NetPlay net(source, n);
      std::printf("pseudo3d: joining the netgame on %s\n", connect.c_str());
      net.wait_for_start([](const std::string& s) { std::printf("pseudo3d: %s\n", s.c_str()), std::fflush(stdout); });
      auto session = std::make_unique<game::Session>(net.level_source(), net.skill(), net.flags());
      session->fov = fov;
      session->show_status_bar = !no_status_bar;
      session->renderer_options = renderer_options;
      if (!session->select_renderer(settings.renderer, false)) session->select_renderer("bsp", false);
      game::FrontEnd front(std::move(session), settings, front_options);
      o.netplay = &net;
      o.quit_after_tics = quit_after;
      const int status = game::run_window(front, settings, o);
      net.leave();
      return status;
    }
    if (title) {
      std::printf("pseudo3d: %s: Doom's title screen\n", source.wads.back().c_str());
      std::fflush(stdout);
      game::FrontEnd front(source, settings, front_options);
      return game::run_window(front, settings, o);
    }

    auto session = std::make_unique<game::Session>(source, skill, flags);
    if (doom_demo) {
      demo = play::demo_from_doom(*doom_demo, session->level());
      if (doom_demo->player_count() > 1) session->play_other_players(*doom_demo);
    }
    session->fov = fov;
    session->show_status_bar = !no_status_bar;
    session->renderer_options = renderer_options;
    session->give_all_keys(all_keys);
    const std::string& map_path = session->name();
    if (!session->select_renderer(settings.renderer, false)) throw Error("renderer '" + settings.renderer + "' cannot draw " + map_path);
    if (demo && demo->level_fingerprint != play::fingerprint(session->level()))
      throw Error(play + ": the demo was recorded on a different level than " + map_path);

    if (headless) {
      if (demo) {
        game::HeadlessOptions h{capture_every, out_dir, rw ? rw : 640, rh ? rh : 400, json, !stats_only};
        for (const auto& [tic, file] : save_at) h.saves.push_back({tic, file});
        for (const auto& [tic, file] : load_at) h.loads.push_back({tic, file});
        h.loads_doom_only = load_doom_only;
        h.raw = raw_stats;
        h.thing_dump = dump_things;
        const game::HeadlessResult r = game::replay_headless(*session, *demo, h);
        std::string maps;  // a demo that went on across levels names them
        for (const std::string& m : r.maps) maps += (maps.empty() ? "maps " : ", ") + m;
        std::printf("replayed %zu of %zu tics (%sexit: %s), wrote %d %s to %s\n", r.tics, demo->tics.size(),
                    r.maps.size() > 1 ? (maps + "; ").c_str() : "", game::exit_name(r.exit), r.frames,
                    stats_only ? "rows of stats.csv" : "frames and stats.csv", out_dir.c_str());
        if (!r.beyond_chocolate.empty())
          std::fprintf(stderr, "warning: beyond Chocolate Doom from %s: vanilla overran memory that Chocolate does not emulate, so its replay may part from here\n",
                       r.beyond_chocolate.c_str());
        return 0;
      }
      session->start_recording(std::filesystem::path(record).extension() == ".lmp", long_tics);
      const size_t tics = autopilot_headless(*session, route(autopilot), quit_after);
      if (!record.empty()) write_file_atomically(record, session->encode_recording(record));
      std::printf("autopilot walked %zu tics (exit: %s)%s\n", tics, game::exit_name(session->exited()),
                  record.empty() ? "" : (", recorded to " + record).c_str());
      return 0;
    }

    std::printf("pseudo3d: %s, skill %d%s\n", map_path.c_str(), skill, demo ? ", playing the demo" : "");
    std::fflush(stdout);
    o.map_reload = map_reload;
    o.record = record;
    o.long_tics = long_tics;
    o.play = demo;
    o.timedemo = timedemo;
    if (timedemo) o.vsync = false;
    if (!autopilot.empty()) o.autopilot = route(autopilot);
    front_options.watching = demo || !autopilot.empty();
    front_options.plays_demo = demo.has_value();
    game::FrontEnd front(std::move(session), settings, front_options);
    return game::run_window(front, settings, o);
  });
}
