// The heads-up text: frame rate and time split, the renderer and its statistics,
// where the player is; plus the key help and a translucent text panel to show them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "engine/render/camera.h"
#include "engine/geom/geom.h"

namespace p3d::game {

struct FrameTimes {
  double fps = 0;
  double frame_ms = 0, sim_ms = 0, render_ms = 0, present_ms = 0;
};

std::vector<std::string> hud_lines(std::string_view title, std::string_view renderer, const render::RenderStats& stats,
                                   const FrameTimes& times, geom::Vec2 pos, double z, double angle);
std::vector<std::string> help_lines();

// "keys: blue card, red skull  secrets 1/3  noclip": what the player has found.
std::string progress_line(uint8_t keys, int secrets_found, int secrets_total, bool noclip);

// Lines of text on a dark translucent box with its top-left corner at (x, y); lines
// wider than the frame wrap at spaces. Returns the box's height.
int draw_panel(render::Frame& frame, int x, int y, const std::vector<std::string>& lines, int scale);

// Breaks lines longer than `columns` characters at spaces (a word longer than that is cut).
std::vector<std::string> wrap_lines(const std::vector<std::string>& lines, size_t columns);

}  // namespace p3d::game
