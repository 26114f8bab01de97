// Golden captures of the default map: small PNGs and a stats text committed in
// tests/golden/. Tolerance: at least 99.5% of pixels within 2 levels per channel
// (the renderer is deterministic; the slack covers libm differences between
// machines). Set P3D_UPDATE_GOLDEN=1 to rewrite the goldens after a deliberate change.
#include <gtest/gtest.h>

#include <cstdlib>

#include "engine/bsp/load.h"
#include "engine/image/image.h"
#include "engine/map/source.h"
#include "engine/render/camera_file.h"
#include "engine/render/renderer.h"
#include "engine/util/file.h"
#include "tests/support/support.h"

namespace p3d::render {
namespace {

std::string stats_line(const std::string& name, const RenderStats& s) {
  return name + " " + statdump(stat_fields(s)) + "\n";
}

// Compares a frame with its golden PNG (or rewrites it when updating).
void check_golden(const Frame& frame, const std::filesystem::path& path, bool update, const std::string& name) {
  if (update) return image::save_png(frame, path);
  const image::Image expected = image::load_png(path);
  ASSERT_EQ(expected.width, frame.width);
  ASSERT_EQ(expected.height, frame.height);
  const image::Difference d = image::compare(frame, expected, 2);
  EXPECT_LE(d.fraction(frame), 0.005) << name << ": " << d.differing_pixels << " pixels differ, max delta "
                                      << d.max_channel_delta;
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
    check_golden(frame, golden / ("outpost_" + c.name + ".png"), update, c.name);
  }
  if (update)
    write_file_atomically(golden / "outpost.stats", stats);
  else
    EXPECT_EQ(stats, read_file_text(golden / "outpost.stats"));
}

// Freedoom views with Doom's own art: plain rooms, skies, masked bars and grates.
TEST(Golden, FreedoomViews) {
  struct View {
    const char* wad;
    const char* map;
    const char* name;
    bool at_start;
    double x, y, angle;
  };
  const View views[] = {
      {"freedoom2.wad", "MAP01", "map01_start", true, 0, 0, 0},
      {"freedoom2.wad", "MAP01", "map01_grate", false, 1889.7, -877.3, 116.6},
      {"freedoom2.wad", "MAP02", "map02_sky", true, 0, 0, 0},
      {"freedoom1.wad", "E1M1", "e1m1_bars", false, 2080, 520, 90},
      {"freedoom1.wad", "E2M1", "e2m1_start", true, 0, 0, 0},
      {"freedoom1.wad", "E3M1", "e3m1_start", true, 0, 0, 0},
  };
  const auto golden = test::source_dir() / "tests/golden";
  const bool update = std::getenv("P3D_UPDATE_GOLDEN") != nullptr;
  auto renderer = make_renderer("bsp");
  std::string stats;
  for (const View& v : views) {
    const wad::Stack wads = bsp::read_wads({test::freedoom_path(v.wad)});
    const level::Level level = bsp::build_wad_map(wads, v.map, {}, nullptr);
    const Camera camera = v.at_start ? camera_at(level, level.player_start, level.player_angle)
                                     : camera_at(level, {v.x, v.y}, v.angle);
    Frame frame(160, 100);
    stats += stats_line(v.name, renderer->render(level, camera, frame));
    check_golden(frame, golden / (std::string("freedoom_") + v.name + ".png"), update, v.name);
  }
  if (update)
    write_file_atomically(golden / "freedoom.stats", stats);
  else
    EXPECT_EQ(stats, read_file_text(golden / "freedoom.stats"));
}

}  // namespace
}  // namespace p3d::render
