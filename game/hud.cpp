#include "game/hud.h"

#include <cstdio>

#include "engine/image/draw2d.h"
#include "engine/image/font.h"

namespace p3d::game {

namespace {

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace

std::vector<std::string> hud_lines(std::string_view title, std::string_view renderer, const render::RenderStats& s,
                                   const FrameTimes& t, geom::Vec2 pos, double z, double angle) {
  std::vector<std::string> lines;
  lines.push_back(format("%.*s  %.0f fps  %.2f ms (sim %.2f, render %.2f, present %.2f)", int(title.size()), title.data(),
                         t.fps, t.frame_ms, t.sim_ms, t.render_ms, t.present_ms));
  std::string stats = format("%.*s: ", int(renderer.size()), renderer.data());
  if (s.nodes_visited || s.subtrees_culled)
    stats += format("nodes %llu  culled %llu  fragments %llu  ", (unsigned long long)s.nodes_visited,
                    (unsigned long long)s.subtrees_culled, (unsigned long long)s.fragments_drawn);
  if (s.rays) stats += format("rays %llu  steps/ray %.1f  ", (unsigned long long)s.rays, double(s.steps) / double(s.rays));
  stats += format("columns closed %llu  pixels %llu", (unsigned long long)s.columns_closed,
                  (unsigned long long)s.pixels_written);
  if (s.sprites_drawn) stats += format("  sprites %llu (%llu px)", (unsigned long long)s.sprites_drawn,
                                       (unsigned long long)s.sprite_pixels);
  if (s.early_exit) stats += "  early exit";
  lines.push_back(stats);
  lines.push_back(format("x %.1f  y %.1f  z %.1f  angle %.1f", pos.x, pos.y, z, angle));
  return lines;
}

std::string progress_line(uint8_t keys, int secrets_found, int secrets_total, bool noclip) {
  static constexpr std::pair<uint8_t, const char*> kNames[] = {
      {1, "blue card"}, {2, "yellow card"}, {4, "red card"}, {8, "blue skull"}, {16, "yellow skull"}, {32, "red skull"}};
  std::string held;
  for (const auto& [bit, name] : kNames)
    if (keys & bit) held += (held.empty() ? "" : ", ") + std::string(name);
  std::string line = "keys: " + (held.empty() ? std::string("none") : held);
  if (secrets_total > 0) line += format("  secrets %d/%d", secrets_found, secrets_total);
  if (noclip) line += "  noclip";
  return line;
}

std::vector<std::string> help_lines() {
  return {
      "W/S, Up/Down    move",
      "A/D             strafe",
      "Space, E        use: open doors, press switches",
      "Ctrl, mouse     fire",
      "1-7             weapons (as Doom's keys)",
      "idclip, iddqd, idkfa  (typed) walk through walls, god mode, every weapon",
      "Left/Right      turn (Alt: strafe)",
      "Shift           run",
      "Tab             automap (O: over the view, B: BSP lines, T: things, +/-: zoom)",
      "[ ]             renderer: bsp painter dda sphere reference",
      "`               heads-up text",
      "Alt+Enter       fullscreen",
      "F12             screenshot (PNG, in out/screenshots/)",
      "Pause           pause",
      "Esc             menu (F10 quits at once)",
      "F1              this help",
  };
}

std::vector<std::string> wrap_lines(const std::vector<std::string>& lines, size_t columns) {
  columns = std::max<size_t>(columns, 1);
  std::vector<std::string> out;
  for (std::string line : lines) {
    while (line.size() > columns) {
      size_t cut = line.rfind(' ', columns);
      if (cut == std::string::npos || cut == 0) cut = columns;
      out.push_back(line.substr(0, cut));
      line.erase(0, line.find_first_not_of(' ', cut) == std::string::npos ? line.size() : line.find_first_not_of(' ', cut));
    }
    out.push_back(line);
  }
  return out;
}

int draw_panel(render::Frame& frame, int x, int y, const std::vector<std::string>& unwrapped, int scale) {
  const auto lines = wrap_lines(unwrapped, size_t(std::max(1, (frame.width - x - 8 * scale) / (image::kGlyphWidth * scale))));
  int width = 0;
  for (const std::string& l : lines) width = std::max(width, image::text_width(l, scale));
  const int line_h = image::kGlyphHeight * scale, pad = 3 * scale;
  image::fill_rect(frame, x, y, width + 2 * pad, int(lines.size()) * line_h + 2 * pad, image::rgba(0, 0, 0), 150);
  for (size_t i = 0; i < lines.size(); ++i)
    image::draw_text(frame, x + pad, y + pad + int(i) * line_h, lines[i], image::rgba(235, 235, 220), scale);
  return int(lines.size()) * line_h + 2 * pad;
}

}  // namespace p3d::game
