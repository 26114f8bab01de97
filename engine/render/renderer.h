// The one renderer interface, and the registry that builds renderers by name
// for capture, compare, bench and the game.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/render/camera.h"
#include "engine/util/statdump.h"

namespace p3d::render {

// Settings some renderers take; the rest ignore them.
struct RendererOptions {
  double sphere_epsilon = 0.1;     // map units: closer than this, a marching ray tests walls exactly
  double sphere_relaxation = 1.6;  // over-relaxation factor omega in [1, 2); 1 is plain sphere tracing
  int sphere_max_steps = 512;      // marching steps before a ray gives up (grazing rays)
  int threads = 1;                 // bsp: threads drawing the frame's column strips (same frame for any count)
  bool vector_columns = true;      // bsp: AVX-512 column, flat and projection loops where the processor has them (same frame)
};

class Renderer {
 public:
  virtual ~Renderer() = default;
  virtual std::string_view name() const = 0;
  // Whether this renderer can draw the level at all (the grid ray caster needs a grid map).
  virtual bool supports(const level::Level&) const { return true; }
  // What a level needs for this renderer to draw it, for messages ("a grid map").
  virtual std::string_view needs() const { return ""; }
  // Builds per-level acceleration data ahead of time (otherwise the first render does).
  virtual void prepare(const level::Level&) {}
  // Draws the level in a state seen by the camera into frame (whose size is the
  // resolution). probe, when given, receives the optional outputs it asks for.
  virtual RenderStats render(const level::Level& level, const level::State& state, const Camera& camera,
                             Frame& frame, Probe* probe = nullptr) = 0;
  // The level as it starts, at the default skill.
  RenderStats render(const level::Level& level, const Camera& camera, Frame& frame, Probe* probe = nullptr);

 private:
  level::State start_;      // the start state of the level last drawn without one
  uint64_t start_for_ = 0;  // that level's generation
};

// A frame's statistics by name, every field in a fixed order (statdump, JSON, CSV).
Stats stat_fields(const RenderStats& stats);

// nullptr for an unknown name.
std::unique_ptr<Renderer> make_renderer(std::string_view name, const RendererOptions& options = {});
const std::vector<std::string>& renderer_names();

// Internal factories, one per renderer file.
std::unique_ptr<Renderer> make_bsp_front_to_back(int threads, bool vector_columns = true);
std::unique_ptr<Renderer> make_painter();
std::unique_ptr<Renderer> make_grid_ray_caster();
std::unique_ptr<Renderer> make_sphere_tracer(const RendererOptions& options, bool accelerated);
std::unique_ptr<Renderer> make_reference();

}  // namespace p3d::render
