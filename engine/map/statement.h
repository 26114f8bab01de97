// Statement-level parsing shared by the .map and .grid parsers: words, positional
// arguments, key=value options consumed exactly once, numbers with located errors.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/map/name_index.h"
#include "engine/map/source.h"
#include "engine/util/limits.h"

namespace p3d::map::detail {

// A line's words, kept by a parser from one line to the next: a statement costs no
// allocation once the first lines have made room.
struct Words {
  std::vector<std::string_view> args;
  std::vector<std::pair<std::string_view, std::string_view>> options;
};

class Statement {
 public:
  // words.args holds the line's words (split_words): they become its positional
  // arguments, compacted in place, and its key=value options go to words.options.
  Statement(const FileLoc& file, int line, Words& words) : file_(file), line_(line), args_(words.args), options_(words.options) {
    keyword_ = args_.front();
    options_.clear();
    size_t positional = 0;
    for (size_t i = 1; i < args_.size(); ++i) {
      const std::string_view word = args_[i];
      const size_t eq = size_t(std::find(word.begin(), word.end(), '=') - word.begin());  // a short word: no memchr call
      if (eq == word.size()) {
        if (!options_.empty()) fail("positional argument '" + std::string(word) + "' after key=value options");
        args_[positional++] = word;
      } else {
        const std::string_view key = word.substr(0, eq);
        if (key.empty()) fail("missing key before '=' in '" + std::string(word) + "'");
        // No statement knows more than a few keys; a cap keeps the search below linear.
        if (options_.size() == kMaxOptions) fail("more than " + std::to_string(kMaxOptions) + " key=value options");
        if (find(key) != options_.end()) fail("option '" + std::string(key) + "' given twice");
        options_.emplace_back(key, word.substr(eq + 1));
      }
    }
    args_.resize(positional);
  }

  std::string_view keyword() const { return keyword_; }
  FileLoc loc() const { return file_.at(line_); }
  [[noreturn]] void fail(const std::string& message) const { throw Error(loc(), message); }

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
  const FileLoc& file_;  // made into a located FileLoc only when asked (a copy counts a reference)
  int line_;
  std::string_view keyword_;
  std::vector<std::string_view>& args_;
  static constexpr size_t kMaxOptions = 64;
  using Options = std::vector<std::pair<std::string_view, std::string_view>>;  // a few per line: searched in turn
  Options::iterator find(std::string_view key) {
    return std::find_if(options_.begin(), options_.end(), [&](const auto& o) { return same_word(o.first, key); });
  }
  Options& options_;

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

// A text map's lines one at a time: LF, CRLF and old Mac CR-only line ends alike, a
// leading UTF-8 byte order mark skipped (editors on Windows write one).
class LineReader {
 public:
  explicit LineReader(std::string_view text)
      : text_(text.substr(0, 3) == "\xEF\xBB\xBF" ? text.substr(3) : text), any_cr_(find('\r', 0, text_.size())) {}
  // The next line into `line`; false after the last (a text's last line may be empty).
  bool next(std::string_view& line) {
    if (done_) return false;
    // memchr for the next LF, then for a CR before it (rare: CRLF or CR-only files).
    const char* lf = find('\n', pos_, text_.size());
    const size_t newline = lf ? size_t(lf - text_.data()) : text_.size();
    const char* cr = any_cr_ ? find('\r', pos_, newline) : nullptr;
    const size_t end = cr ? size_t(cr - text_.data()) : newline;
    line = text_.substr(pos_, end - pos_);
    done_ = end == text_.size();
    if (!done_) pos_ = end + (text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n' ? 2 : 1);
    return true;
  }

 private:
  // memchr over [from, to), never given a null pointer (an empty mapped file has none).
  const char* find(char c, size_t from, size_t to) const {
    return to > from ? static_cast<const char*>(std::memchr(text_.data() + from, c, to - from)) : nullptr;
  }
  std::string_view text_;
  bool any_cr_;  // most texts have none: a line is then found by one memchr
  size_t pos_ = 0;
  bool done_ = false;
};

inline std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  LineReader reader(text);
  for (std::string_view line; reader.next(line);) lines.push_back(line);
  return lines;
}

// A line's words into `words` (what it held is dropped); a '#' starts a comment.
inline void split_words(std::string_view line, std::vector<std::string_view>& words) {
  static constexpr auto kind = [] {  // 1: a space between words, 2: a comment's start
    std::array<uint8_t, 256> k{};
    k[' '] = k['\t'] = k['\r'] = 1;
    k['#'] = 2;
    return k;
  }();
  words.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && kind[uint8_t(line[i])] == 1) ++i;
    if (i >= line.size() || line[i] == '#') break;
    const size_t start = i;
    while (i < line.size() && kind[uint8_t(line[i])] == 0) ++i;
    words.push_back(line.substr(start, i - start));
  }
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
