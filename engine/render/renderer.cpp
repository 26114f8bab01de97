#include "engine/render/renderer.h"

#include "engine/render/view.h"

namespace p3d::render {

Camera camera_at(const level::Level& level, Vec2 pos, double angle, double eye_height, double fov) {
  int sector = level.sector_at(pos);
  if (sector == level::kNone) sector = level.default_sector;
  const double floor = sector == level::kNone ? 0 : level.sectors[size_t(sector)].floor;
  return Camera{pos, floor + eye_height, angle, fov};
}

RenderStats Renderer::render(const level::Level& level, const Camera& camera, Frame& frame, Probe* probe) {
  if (start_for_ != level.generation) {
    start_ = level::start_state(level);
    start_for_ = level.generation;
  }
  return render(level, start_, camera, frame, probe);
}

Stats stat_fields(const RenderStats& s) {
  return {{"nodes_visited", double(s.nodes_visited)},     {"subtrees_culled", double(s.subtrees_culled)},
          {"fragments_drawn", double(s.fragments_drawn)}, {"columns_closed", double(s.columns_closed)},
          {"pixels_written", double(s.pixels_written)},   {"masked_pixels", double(s.masked_pixels)},
          {"sprites_drawn", double(s.sprites_drawn)},     {"sprite_pixels", double(s.sprite_pixels)},
          {"early_exit", s.early_exit ? 1.0 : 0.0},       {"rays", double(s.rays)},
          {"steps", double(s.steps)},                     {"max_steps", double(s.max_steps)}};
}

const std::vector<std::string>& renderer_names() {
  static const std::vector<std::string> names = {"bsp", "painter", "dda", "sphere", "sphere-naive", "reference"};
  return names;
}

std::unique_ptr<Renderer> make_renderer(std::string_view name, const RendererOptions& options) {
  if (name == "bsp") return make_bsp_front_to_back(options.threads, options.vector_columns);
  if (name == "painter") return make_painter();
  if (name == "dda") return make_grid_ray_caster();
  if (name == "sphere") return make_sphere_tracer(options, true);
  if (name == "sphere-naive") return make_sphere_tracer(options, false);
  if (name == "reference") return make_reference();
  return nullptr;
}

}  // namespace p3d::render
