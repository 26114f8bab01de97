// The level from above as SVG: leaves' cells shaded by their sector, the BSP's
// splitting lines, walls, each leaf's fragments (a stroke in its colour on their side
// facing its convex region), split points; optionally one camera's view cone, the order in which
// the front-to-back renderer drew fragments, and the columns each closed.
#pragma once

#include <optional>
#include <string>

#include "engine/level/level.h"
#include "engine/render/camera.h"

namespace p3d::tools {

struct ViewTrace {
  render::Camera camera;
  int columns = 0, rows = 0;
  render::Probe probe;  // with columns and draw order from the "bsp" renderer
};

std::string overview_svg(const level::Level& level, const std::optional<ViewTrace>& view);

// Renders the camera with the front-to-back renderer, keeping what the picture needs.
ViewTrace trace_view(const level::Level& level, const render::Camera& camera, int columns, int rows);

}  // namespace p3d::tools
