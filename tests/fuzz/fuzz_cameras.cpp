// A camera list, each camera drawn on a small level when the list is accepted.
#include "engine/bsp/build.h"
#include "engine/map/source.h"
#include "engine/render/camera_file.h"
#include "tests/fuzz/harness.h"
#include "tests/fuzz/target.h"

using namespace p3d;

P3D_FUZZ_TARGET(cameras) {
  static const level::Level level = bsp::build(map::load_map(fuzz::maps_dir() / "outpost.map"), {});
  try {
    const auto cameras = render::parse_camera_list(std::string(reinterpret_cast<const char*>(data), size), "fuzz.cameras");
    auto r = render::make_renderer("bsp");
    render::Frame frame(24, 16);
    for (size_t i = 0; i < cameras.size() && i < 16; ++i)
      r->render(level, render::camera_at(level, cameras[i].pos, cameras[i].angle, cameras[i].eye, cameras[i].fov), frame);
  } catch (const Error&) {
  }
  return 0;
}
