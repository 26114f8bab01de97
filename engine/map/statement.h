// Statement-level parsing shared by the .map and .grid parsers: words, positional
// arguments, key=value options consumed exactly once, numbers with located errors.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/map/source.h"
#include "engine/util/limits.h"

namespace p3d::map::detail {

class Statement {
 public:
  // The words' vector becomes the arguments' (compacted in place): a line costs no
  // allocation beyond its words and, when it has options, one for them.
  Statement(const FileLoc& loc, std::vector<std::string_view> words) : loc_(loc), args_(std::move(words)) {
    keyword_ = args_.front();
    size_t positional = 0;
    for (size_t i = 1; i < args_.size(); ++i) {
      const std::string_view word = args_[i];
      const size_t eq = word.find('=');
      if (eq == std::string_view::npos) {
        if (!options_.empty()) fail("positional argument '" + std::string(word) + "' after key=value options");
        args_[positional++] = word;
      } else {
        const std::string_view key = word.substr(0, eq);
        if (key.empty()) fail("missing key before '=' in '" + std::string(word) + "'");
        // No statement knows more than a few keys; a cap keeps the search below linear.
        if (options_.size() == kMaxOptions) fail("more than " + std::to_string(kMaxOptions) + " key=value options");
        if (find(key) != options_.end()) fail("option '" + std::string(key) + "' given twice");
        if (options_.empty()) options_.reserve(std::min(kMaxOptions, args_.size() - i));
        options_.emplace_back(key, word.substr(eq + 1));
      }
    }
    args_.resize(positional);
  }

  std::string_view keyword() const { return keyword_; }
  const FileLoc& loc() const { return loc_; }
  [[noreturn]] void fail(const std::string& message) const { throw Error(loc_, message); }

  void expect_args(size_t n, const char* usage) const {
    if (args_.size() != n) fail(std::string(keyword_) + ": expected " + usage);
  }
  std::string_view arg(size_t i) const { return args_[i]; }
  size_t arg_count() const { return args_.size(); }

  double number(std::string_view text, std::string_view what) const {
    return parse_number(text, [&] { return std::string(what); });
  }
  // An argument that names something (a texture, sector, vertex): at most
  // limits::kMaxNameLength bytes, as the compiled format holds.
  std::string name(size_t i, const char* what) const {
    if (args_[i].size() > limits::kMaxNameLength)
      fail(std::string(what) + " name is longer than " + std::to_string(limits::kMaxNameLength) + " bytes");
    return std::string(args_[i]);
  }
  // The rest of the line as a title, at most limits::kMaxTitleLength bytes.
  std::string title() const {
    std::string t;
    for (size_t a = 0; a < args_.size(); ++a) (t += a ? " " : "") += args_[a];
    if (t.size() > limits::kMaxTitleLength)
      fail("title is longer than " + std::to_string(limits::kMaxTitleLength) + " bytes");
    return t;
  }
  // A number within +-limit.
  double bounded(std::string_view text, std::string_view what, double limit) const {
    const double v = number(text, what);
    if (std::fabs(v) > limit)
      fail(std::string(what) + " '" + std::string(text) + "' is outside +-" + std::to_string(static_cast<int64_t>(limit)));
    return v;
  }
  int integer(std::string_view text, std::string_view what, int lo, int hi) const {
    const double v = number(text, what);
    if (v != std::floor(v) || v < lo || v > hi)
      fail(std::string(what) + " '" + std::string(text) + "' must be an integer from " + std::to_string(lo) + " to " +
           std::to_string(hi));
    return static_cast<int>(v);
  }
  int64_t coordinate(std::string_view text, const char* axis) const {
    int64_t fixed = 0;
    if (!geom::to_fixed(parse_number(text, [&] { return std::string(axis) + " coordinate"; }), fixed))
      fail(std::string(axis) + " coordinate '" + std::string(text) + "' is outside +-" +
           std::to_string(static_cast<int64_t>(geom::kMaxCoord)));
    return fixed;
  }

  // Options: each must be consumed exactly once; leftovers are reported as unknown.
  std::optional<std::string_view> take(std::string_view key) {
    const auto it = find(key);
    if (it == options_.end()) return std::nullopt;
    const std::string_view v = it->second;
    options_.erase(it);
    return v;
  }
  std::string_view require(std::string_view key) {
    auto v = take(key);
    if (!v) fail(std::string(keyword_) + ": missing option " + std::string(key) + "=");
    return *v;
  }
  void finish() const {  // the first unknown option in name order: the same message whatever the order given
    if (!options_.empty())
      fail(std::string(keyword_) + ": unknown option '" + std::string(std::min_element(options_.begin(), options_.end())->first) +
           "'");
  }

 private:
  FileLoc loc_;
  std::string_view keyword_;
  std::vector<std::string_view> args_;
  static constexpr size_t kMaxOptions = 64;
  using Options = std::vector<std::pair<std::string_view, std::string_view>>;  // a few per line: searched in turn
  Options::iterator find(std::string_view key) {
    return std::find_if(options_.begin(), options_.end(), [&](const auto& o) { return o.first == key; });
  }
  Options options_;

  // Most numbers in a map are short integers: read by a plain loop, they are the same
  // doubles from_chars would give (exact below 2^53), -0 included.
  static std::optional<double> short_integer(std::string_view text) {
    const bool negative = !text.empty() && text[0] == '-';
    const std::string_view digits = text.substr(negative ? 1 : 0);
    if (digits.empty() || digits.size() > 15) return std::nullopt;
    int64_t value = 0;
    for (const char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;
      value = value * 10 + (c - '0');
    }
    return negative ? -double(value) : double(value);
  }
  // A number; what() names it in a failure's message, made only then.
  template <typename What>
  double parse_number(std::string_view text, const What& what) const {
    if (const auto v = short_integer(text)) return *v;
    double v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec == std::errc::result_out_of_range) fail(what() + " '" + std::string(text) + "' is out of range");
    if (ec != std::errc() || ptr != end) fail(what() + " '" + std::string(text) + "' is not a number");
    if (!std::isfinite(v)) fail(what() + " '" + std::string(text) + "' is not finite");
    return v;
  }
};

// A text map's lines: LF, CRLF and old Mac CR-only line ends alike, a leading UTF-8 byte
// order mark skipped (editors on Windows write one).
inline std::vector<std::string_view> split_lines(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<std::string_view> lines;
  size_t pos = 0;
  // memchr over [from, to), never given a null pointer (an empty mapped file has none).
  const auto find = [&](char c, size_t from, size_t to) -> const char* {
    return to > from ? static_cast<const char*>(std::memchr(text.data() + from, c, to - from)) : nullptr;
  };
  for (;;) {  // memchr for the next LF, then for a CR before it (rare: CRLF or CR-only files)
    const char* lf = find('\n', pos, text.size());
    const size_t newline = lf ? size_t(lf - text.data()) : text.size();
    const char* cr = find('\r', pos, newline);
    const size_t end = cr ? size_t(cr - text.data()) : newline;
    if (end == text.size()) {
      lines.push_back(text.substr(pos));
      return lines;
    }
    lines.push_back(text.substr(pos, end - pos));
    pos = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
}

inline std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  words.reserve(8);  // a statement's words, mostly: one allocation where growing took three
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size() || line[i] == '#') break;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' && line[i] != '#') ++i;
    words.push_back(line.substr(start, i - start));
  }
  return words;
}

// Loads a texture statement's PNG (relative to the map's directory, see LoadOptions)
// and checks its size.
Texture load_texture(const Statement& s, const std::string& name, const std::filesystem::path& map_path,
                     std::string_view file, const LoadOptions& options);

// Things' pictures, shared by the .map and .grid parsers:
//   sprite TYPE FILE.png [anchor=X,Y] [place=floor|ceiling] [bright=yes|no]
// gives every thing of TYPE that picture, seen alike from every side. The anchor
// pixel (default: the middle of the bottom row, or of the top row when hanging)
// lies at the thing's position, on its sector's floor or at its ceiling.
class Sprites {
 public:
  void statement(Statement& s, Source& source, const LoadOptions& options);
  // After parsing: every thing of a type with a sprite shows it.
  void assign(Source& source) const;

 private:
  std::map<int, int> frame_of_type_;
};

}  // namespace p3d::map::detail
