#include "game/headless.h"

#include <cstdio>

#include "engine/image/image.h"
#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::game {

int replay_headless(Session& session, const sim::Demo& demo, const HeadlessOptions& o) {
  if (demo.level_fingerprint != sim::fingerprint(session.level()))
    throw Error("the demo was recorded on a different level than " + session.name());
  std::filesystem::create_directories(o.out_dir);
  session.spawn(demo.start, demo.angle);
  render::Frame frame(o.width, o.height);
  std::string csv = "frame,tic,x,y,z,angle,renderer,nodes_visited,subtrees_culled,fragments_drawn,columns_closed,"
                    "pixels_written,early_exit\n";
  int frames = 0;
  for (size_t tic = 0;; ++tic) {
    if (tic % size_t(o.capture_every) == 0) {
      const render::RenderStats& s = session.render(frame, 1.0);
      char name[32];
      std::snprintf(name, sizeof name, "frame%05d.png", frames);
      image::save_png(frame, o.out_dir / name);
      const sim::Player& p = session.player();
      char line[320];
      std::snprintf(line, sizeof line, "%d,%zu,%.6f,%.6f,%.6f,%.6f,%s,%llu,%llu,%llu,%llu,%llu,%d\n", frames, tic, p.pos.x,
                    p.pos.y, p.z, p.angle, session.renderer_name().c_str(), (unsigned long long)s.nodes_visited,
                    (unsigned long long)s.subtrees_culled, (unsigned long long)s.fragments_drawn,
                    (unsigned long long)s.columns_closed, (unsigned long long)s.pixels_written, int(s.early_exit));
      csv += line;
      ++frames;
    }
    if (tic == demo.tics.size()) break;
    session.tic(demo.tics[tic]);
  }
  write_file_atomically(o.out_dir / "stats.csv", csv);
  return frames;
}

}  // namespace p3d::game
