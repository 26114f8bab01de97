// The one error type of the project: a message with an optional source location,
// thrown at the edges (parsers, loaders) and caught once in each main.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace p3d {

// Where something was read: a file (or a WAD record) and a line. Every record of a
// parsed map carries one, so the name is shared, not copied: a million walls would
// otherwise hold a million copies of the path.
struct FileLoc {
  int line = 0;  // 1-based; 0 means "the whole file"

  FileLoc() = default;
  FileLoc(std::string file, int line_number = 0) : line(line_number), file_(std::make_shared<const std::string>(std::move(file))) {}
  // The same file at another line.
  FileLoc at(int other_line) const {
    FileLoc loc = *this;
    loc.line = other_line;
    return loc;
  }
  const std::string& file() const {
    static const std::string none;
    return file_ ? *file_ : none;
  }
  std::string str() const { return line > 0 ? file() + ":" + std::to_string(line) : file(); }

 private:
  std::shared_ptr<const std::string> file_;
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
