// Camera lists (.cameras files): one camera per line, "NAME X Y ANGLE [EYE [FOV]]",
// '#' starts a comment. Used by capture --cameras, compare --path and bench.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine/render/camera.h"

namespace p3d::render {

struct CameraSpec {
  std::string name;
  Vec2 pos;
  double angle = 0;
  double eye = kEyeHeight;  // above the floor at pos
  double fov = 90;
};

// Throws Error("file:line: message") on a malformed line or an empty list.
std::vector<CameraSpec> parse_camera_list(const std::string& text, const std::string& path);
std::vector<CameraSpec> read_camera_list(const std::filesystem::path& path);

}  // namespace p3d::render
