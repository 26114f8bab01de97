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

// A message safe to print: control bytes (NUL, CR, escape sequences...) as \xNN and a
// UTF-8 byte order mark as <BOM>, whatever the input held; other text (UTF-8 too) as is.
inline std::string escape_controls(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (text.compare(i, 3, "\xEF\xBB\xBF") == 0) {
      out += "<BOM>";
      i += 2;
    } else if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7F) {
      static const char kHex[] = "0123456789ABCDEF";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += char(c);
    }
  }
  return out;
}

// Messages are escaped once, here, whichever reader echoes input in them.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(escape_controls(message)) {}
  Error(const FileLoc& loc, const std::string& message) : std::runtime_error(escape_controls(loc.str() + ": " + message)) {}
};

}  // namespace p3d
