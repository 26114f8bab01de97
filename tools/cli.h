// Small helpers shared by the command-line tools: argument value parsing with
// clear errors, timing, and the one place errors are turned into exit codes.
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "engine/geom/geom.h"
#include "engine/util/error.h"

namespace p3d::cli {

// "X,Y" -> point; throws CLI::ValidationError.
inline geom::Vec2 parse_point(const std::string& text, const char* option) {
  double x = 0, y = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf%c", &x, &y, &extra) != 2 || !std::isfinite(x) || !std::isfinite(y))
    throw CLI::ValidationError(option, "expected X,Y with finite numbers, got '" + text + "'");
  return {x, y};
}

// "WxH" -> size; throws CLI::ValidationError.
inline void parse_size(const std::string& text, int& w, int& h) {
  char extra = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw CLI::ValidationError("--size", "expected WxH between 1x1 and 16384x16384, got '" + text + "'");
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs a tool's body: CLI errors exit 2 with usage; p3d::Error and I/O errors exit 1.
template <typename Body>
int run(CLI::App& app, int argc, char** argv, Body&& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return body();
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "%s: %s\n", app.get_name().c_str(), e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}

}  // namespace p3d::cli
