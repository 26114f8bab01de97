#include "game/headless.h"

#include <cstdio>

#include "engine/image/image.h"
#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::game {

const char* exit_name(sim::Exit exit) {
  switch (exit) {
    case sim::Exit::kNormal: return "normal";
    case sim::Exit::kSecret: return "secret";
    case sim::Exit::kNone: break;
  }
  return "none";
}

HeadlessResult replay_headless(Session& session, const sim::Demo& demo, const HeadlessOptions& o) {
  if (demo.level_fingerprint != sim::fingerprint(session.level()))
    throw Error("the demo was recorded on a different level than " + session.name());
  std::filesystem::create_directories(o.out_dir);
  session.spawn(demo.start, demo.angle);
  session.set_keys(demo.keys);
  render::Frame frame(o.width, o.height);
  std::string csv = "frame,tic,x,y,z,angle,renderer";
  for (const Stat& f : render::stat_fields({})) csv += "," + f.name;
  csv += ",keys,secrets,exit\n";
  std::string json = "{\"level\": " + json_string(session.name()) + ", \"frames\": [\n";
  HeadlessResult result;
  for (size_t tic = 0;; ++tic) {
    const bool last = tic == demo.tics.size() || session.exited() != sim::Exit::kNone;
    if (tic % size_t(o.capture_every) == 0 || last) {
      const render::RenderStats& s = session.render(frame, 1.0);
      char name[32];
      std::snprintf(name, sizeof name, "frame%05d.png", result.frames);
      image::save_png(frame, o.out_dir / name);
      const sim::Player& p = session.player();
      char line[200];
      std::snprintf(line, sizeof line, "%d,%zu,%.6f,%.6f,%.6f,%.6f,%s", result.frames, tic, p.pos.x, p.pos.y, p.z,
                    p.angle, session.renderer_name().c_str());
      csv += line;
      for (const Stat& f : render::stat_fields(s)) csv += "," + stat_number(f.value);
      std::snprintf(line, sizeof line, ",%d,%d,%s\n", int(p.keys), session.world().secrets_found(),
                    exit_name(session.exited()));
      csv += line;
      const Stats where = {{"frame", double(result.frames)}, {"tic", double(tic)}, {"x", p.pos.x}, {"y", p.pos.y},
                           {"z", p.z},  {"angle", p.angle}, {"keys", double(p.keys)},
                           {"secrets", double(session.world().secrets_found())}};
      json += std::string(result.frames ? ",\n" : "") + "  {\"player\": " + stats_json(where) + ", \"renderer\": " +
              json_string(session.renderer_name()) + ", \"stats\": " + stats_json(render::stat_fields(s)) +
              ", \"exit\": " + json_string(exit_name(session.exited())) + "}";
      ++result.frames;
    }
    if (last) {
      result.tics = tic;
      break;
    }
    session.tic(demo.tics[tic]);
  }
  result.exit = session.exited();
  write_file_atomically(o.out_dir / "stats.csv", csv);
  if (o.json) write_file_atomically(o.out_dir / "stats.json", json + "\n]}\n");
  return result;
}

}  // namespace p3d::game
