#include "game/headless.h"

#include <cstdio>

#include "engine/image/image.h"
#include "engine/play/thing_dump.h"
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
  std::string things;
  for (size_t tic = 0;; ++tic) {
    const bool last = tic == demo.tics.size() || session.exited() != play::ExitKind::kNone;
    if (tic % size_t(o.capture_every) == 0 || last) {
      render::RenderStats s;
      if (o.frames) {
        s = session.render(frame, 1.0);
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
    session.tic(demo.tics[tic]);
    if (!o.thing_dump.empty()) things += play::dump_things(session.world(), tic);
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
