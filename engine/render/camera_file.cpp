#include "engine/render/camera_file.h"

#include <cmath>
#include <sstream>

#include "engine/util/error.h"
#include "engine/util/file.h"

namespace p3d::render {

std::vector<CameraSpec> parse_camera_list(const std::string& text, const std::string& path) {
  std::vector<CameraSpec> specs;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    CameraSpec s;
    if (!(words >> s.name)) continue;
    const FileLoc loc{path, number};
    if (!(words >> s.pos.x >> s.pos.y >> s.angle)) throw Error(loc, "expected NAME X Y ANGLE [EYE [FOV]]");
    if (!(words >> s.eye)) {
      s.eye = kEyeHeight;
      if (!words.eof()) throw Error(loc, "expected a number for EYE");
    } else if (!(words >> s.fov)) {
      s.fov = 90;
      if (!words.eof()) throw Error(loc, "expected a number for FOV");
    }
    std::string extra;
    if (words >> extra) throw Error(loc, "unexpected '" + extra + "'");
    if (!std::isfinite(s.pos.x) || !std::isfinite(s.pos.y) || !std::isfinite(s.angle) || !std::isfinite(s.eye))
      throw Error(loc, "numbers must be finite");
    for (double v : {s.pos.x, s.pos.y, s.eye})
      if (std::fabs(v) > kMaxCameraCoord)
        throw Error(loc, "positions and eye heights must lie within +-" + std::to_string(int64_t(kMaxCameraCoord)));
    if (!(s.fov >= 1 && s.fov <= 179)) throw Error(loc, "field of view must be between 1 and 179 degrees");
    if (s.name.find('/') != std::string::npos) throw Error(loc, "camera names cannot contain '/'");
    specs.push_back(s);
  }
  if (specs.empty()) throw Error(path + ": no cameras");
  return specs;
}

std::vector<CameraSpec> read_camera_list(const std::filesystem::path& path) {
  return parse_camera_list(read_file_text(path), path.string());
}

}  // namespace p3d::render
