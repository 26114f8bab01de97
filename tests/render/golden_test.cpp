// Golden captures of the default map: small PNGs and a stats text committed in
// tests/golden/. Tolerance: at least 99.5% of pixels within 2 levels per channel
// (the renderer is deterministic; the slack covers libm differences between
// machines). Set P3D_UPDATE_GOLDEN=1 to rewrite the goldens after a deliberate change.
#include <gtest/gtest.h>

#include <cstdlib>

#include "engine/image/image.h"
#include "engine/map/source.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d::render {
namespace {

std::string stats_line(const std::string& name, const RenderStats& s) {
  char line[256];
  std::snprintf(line, sizeof line,
                "%s nodes_visited=%llu subtrees_culled=%llu fragments_drawn=%llu columns_closed=%llu "
                "pixels_written=%llu early_exit=%d\n",
                name.c_str(), (unsigned long long)s.nodes_visited, (unsigned long long)s.subtrees_culled,
                (unsigned long long)s.fragments_drawn, (unsigned long long)s.columns_closed,
                (unsigned long long)s.pixels_written, int(s.early_exit));
  return line;
}

TEST(Golden, DefaultMapCaptures) {
  const auto golden = test::source_dir() / "tests/golden";
  const bool update = std::getenv("P3D_UPDATE_GOLDEN") != nullptr;
  const level::Level level = test::compile(map::load_map(test::source_dir() / "maps/outpost.map"));
  auto renderer = make_renderer("bsp");
  std::string stats;
  for (const CameraSpec& c : read_camera_list(golden / "outpost.cameras")) {
    Frame frame(160, 100);
    const RenderStats s = renderer->render(level, camera_at(level, c.pos, c.angle, c.eye, c.fov), frame);
    stats += stats_line(c.name, s);
    const auto path = golden / ("outpost_" + c.name + ".png");
    if (update) {
      image::save_png(frame, path);
      continue;
    }
    const image::Image expected = image::load_png(path);
    ASSERT_EQ(expected.width, frame.width);
    ASSERT_EQ(expected.height, frame.height);
    const image::Difference d = image::compare(frame, expected, 2);
    EXPECT_LE(d.fraction(frame), 0.005) << c.name << ": " << d.differing_pixels << " pixels differ, max delta "
                                        << d.max_channel_delta;
  }
  if (update)
    write_file_atomically(golden / "outpost.stats", stats);
  else
    EXPECT_EQ(stats, read_file_text(golden / "outpost.stats"));
}

}  // namespace
}  // namespace p3d::render
