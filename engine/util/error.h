// The one error type of the project: a message with an optional source location,
// thrown at the edges (parsers, loaders) and caught once in each main.
#pragma once

#include <stdexcept>
#include <string>

namespace p3d {

struct FileLoc {
  std::string file;
  int line = 0;  // 1-based; 0 means "the whole file"

  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  Error(const FileLoc& loc, const std::string& message) : std::runtime_error(loc.str() + ": " + message) {}
};

}  // namespace p3d
