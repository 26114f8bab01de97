// The one renderer interface, and the registry that builds renderers by name
// for capture, compare, bench and the game.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/render/camera.h"

namespace p3d::render {

class Renderer {
 public:
  virtual ~Renderer() = default;
  virtual std::string_view name() const = 0;
  // Whether this renderer can draw the level at all (the grid ray caster needs a grid map).
  virtual bool supports(const level::Level&) const { return true; }
  // Draws the level seen by the camera into frame (whose size is the resolution).
  // hits, when given, receives the closing wall of every column.
  virtual RenderStats render(const level::Level& level, const Camera& camera, Frame& frame,
                             ColumnHits* hits = nullptr) = 0;
};

// nullptr for an unknown name.
std::unique_ptr<Renderer> make_renderer(std::string_view name);
const std::vector<std::string>& renderer_names();

// Internal factories, one per renderer file.
std::unique_ptr<Renderer> make_bsp_front_to_back();
std::unique_ptr<Renderer> make_reference();

}  // namespace p3d::render
