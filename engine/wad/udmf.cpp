// UDMF's TEXTMAP (the Universal Doom Map Format 1.1, as Ultimate Doom Builder
// writes it): `namespace = "doom";` then blocks `vertex`, `linedef`, `sidedef`,
// `sector`, `thing` of `key = value;` assignments, in order (a block's index is its
// position among blocks of its kind). Keys are case-insensitive; unknown keys and
// blocks are ignored, as the specification asks. Namespaces doom and zdoom (its
// common fields: per-part texture offsets, sidedef light) are understood.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

#include "engine/util/error.h"
#include "engine/wad/map_data.h"

namespace p3d::wad {

namespace {

enum class TokenKind { kEnd, kIdentifier, kInteger, kFloat, kString, kPunct };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string text;  // identifiers lower-cased; strings unescaped; punctuation: one character
  double number = 0;
  int line = 0;
};

class Lexer {
 public:
  Lexer(std::string_view text, std::string where) : text_(text), where_(std::move(where)) {}

  Token next() {
    skip_space_and_comments();
    Token t;
    t.line = line_;
    if (pos_ >= text_.size()) return t;
    const char c = text_[pos_];
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return identifier(t);
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') return number(t);
    if (c == '"') return string(t);
    if (c == '{' || c == '}' || c == '=' || c == ';') {
      ++pos_;
      t.kind = TokenKind::kPunct;
      t.text = std::string(1, c);
      return t;
    }
    fail(line_, "unexpected character '" + printable(std::string_view(&text_[pos_], 1)) + "'");
  }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw Error(where_ + ": TEXTMAP:" + std::to_string(line) + ": " + message);
  }

 private:
  void skip_space_and_comments() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else if (text_.substr(pos_, 2) == "//") {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (text_.substr(pos_, 2) == "/*") {
        const int start = line_;
        pos_ += 2;
        while (pos_ < text_.size() && text_.substr(pos_, 2) != "*/") line_ += text_[pos_++] == '\n';
        if (pos_ >= text_.size()) fail(start, "comment never closed");
        pos_ += 2;
      } else {
        return;
      }
    }
  }

  Token identifier(Token& t) {
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      t.text.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(text_[pos_++]))));
    t.kind = TokenKind::kIdentifier;
    return t;
  }

  // Integers (decimal, 0x hexadecimal, leading-0 octal) and floats (with '.' or an exponent).
  Token number(Token& t) {
    const size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.' ||
                                   ((text_[pos_] == '-' || text_[pos_] == '+') &&
                                    (pos_ == start || text_[pos_ - 1] == 'e' || text_[pos_ - 1] == 'E'))))
      ++pos_;
    std::string s(text_.substr(start, pos_ - start));
    const bool negative = !s.empty() && s[0] == '-';
    std::string body = s.substr(!s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0);
    const bool hex = body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X');
    const bool is_float = !hex && body.find_first_of(".eE") != std::string::npos;
    if (hex || !is_float) {
      uint64_t v = 0;
      const int base = hex ? 16 : body.size() > 1 && body[0] == '0' ? 8 : 10;
      const char* first = body.data() + (hex ? 2 : 0);
      const auto [ptr, ec] = std::from_chars(first, body.data() + body.size(), v, base);
      if (ec != std::errc() || ptr != body.data() + body.size() || first == ptr)
        fail(t.line, "'" + printable(s) + "' is not a number");
      t.kind = TokenKind::kInteger;
      t.number = negative ? -double(v) : double(v);
    } else {
      double v = 0;
      const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), v);
      if (ec != std::errc() || ptr != body.data() + body.size() || !std::isfinite(v))
        fail(t.line, "'" + printable(s) + "' is not a number");
      t.kind = TokenKind::kFloat;
      t.number = negative ? -v : v;
    }
    t.text = s;
    return t;
  }

  Token string(Token& t) {
    ++pos_;
    for (;;) {
      if (pos_ >= text_.size()) fail(t.line, "string never closed");
      const char c = text_[pos_++];
      if (c == '"') break;
      if (c == '\n') ++line_;
      if (c == '\\' && pos_ < text_.size()) {
        t.text.push_back(text_[pos_++]);
        continue;
      }
      t.text.push_back(c);
    }
    t.kind = TokenKind::kString;
    return t;
  }

  std::string_view text_;
  std::string where_;
  size_t pos_ = 0;
  int line_ = 1;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& where) : lex_(text, where) { data_.where = where; }

  MapData run() {
    data_.udmf = true;
    for (Token t = lex_.next(); t.kind != TokenKind::kEnd; t = lex_.next()) {
      if (t.kind != TokenKind::kIdentifier) lex_.fail(t.line, "expected a block or an assignment, found '" + t.text + "'");
      const Token after = lex_.next();
      if (after.kind == TokenKind::kPunct && after.text == "=") {
        const Token value = lex_.next();
        expect(";");
        if (t.text == "namespace") namespace_ = value.text;
        continue;
      }
      if (after.kind != TokenKind::kPunct || after.text != "{")
        lex_.fail(after.line, "expected '=' or '{' after '" + t.text + "'");
      block(t.text, t.line);
    }
    if (namespace_.empty()) lex_.fail(1, "no 'namespace = \"...\";' statement");
    return std::move(data_);
  }

 private:
  struct Field {
    std::string key;
    Token value;
  };

  void expect(const char* punct) {
    const Token t = lex_.next();
    if (t.kind != TokenKind::kPunct || t.text != punct)
      lex_.fail(t.line, std::string("expected '") + punct + "', found '" + (t.kind == TokenKind::kEnd ? "end of text" : t.text) + "'");
  }

  void block(const std::string& kind, int line) {
    std::vector<Field> fields;
    for (;;) {
      const Token key = lex_.next();
      if (key.kind == TokenKind::kPunct && key.text == "}") break;
      if (key.kind != TokenKind::kIdentifier)
        lex_.fail(key.line, "expected a key or '}' in " + kind + ", found '" +
                                (key.kind == TokenKind::kEnd ? "end of text" : key.text) + "'");
      expect("=");
      Token value = lex_.next();
      if (value.kind == TokenKind::kPunct || value.kind == TokenKind::kEnd)
        lex_.fail(value.line, "expected a value for '" + key.text + "'");
      expect(";");
      fields.push_back({key.text, std::move(value)});
    }
    if (kind == "vertex") return vertex(fields);
    if (kind == "linedef") return linedef(fields, line);
    if (kind == "sidedef") return sidedef(fields);
    if (kind == "sector") return sector(fields);
    if (kind == "thing") return thing(fields);
  }

  double number(const Field& f) const {
    if (f.value.kind != TokenKind::kInteger && f.value.kind != TokenKind::kFloat)
      lex_.fail(f.value.line, "'" + f.key + "' must be a number");
    return f.value.number;
  }
  int integer(const Field& f) const {
    const double v = number(f);
    if (v < -2147483648.0 || v > 2147483647.0) lex_.fail(f.value.line, "'" + f.key + "' is out of range");
    return static_cast<int>(std::trunc(v));
  }
  bool boolean(const Field& f) const {
    if (f.value.kind != TokenKind::kIdentifier || (f.value.text != "true" && f.value.text != "false"))
      lex_.fail(f.value.line, "'" + f.key + "' must be true or false");
    return f.value.text == "true";
  }
  std::string text(const Field& f) const {
    if (f.value.kind != TokenKind::kString) lex_.fail(f.value.line, "'" + f.key + "' must be a quoted string");
    return normalize_name(f.value.text);
  }
  void flag(const Field& f, uint32_t& flags, uint32_t bit) const {
    if (boolean(f)) flags |= bit; else flags &= ~bit;
  }
  void add_flag(const Field& f, uint32_t& flags, uint32_t bit) const {
    if (boolean(f)) flags |= bit;
  }

  void vertex(const std::vector<Field>& fields) {
    MapVertex v;
    for (const Field& f : fields) {
      if (f.key == "x") v.x = number(f);
      else if (f.key == "y") v.y = number(f);
    }
    data_.vertices.push_back(v);
  }

  void linedef(const std::vector<Field>& fields, int line) {
    MapLinedef l;
    bool have_v1 = false, have_v2 = false, have_front = false;
    for (const Field& f : fields) {
      const std::string& k = f.key;
      if (k == "v1") l.v1 = integer(f), have_v1 = true;
      else if (k == "v2") l.v2 = integer(f), have_v2 = true;
      else if (k == "sidefront") l.front = integer(f), have_front = true;
      else if (k == "sideback") l.back = integer(f);
      else if (k == "special") l.special = integer(f);
      else if (k == "id") l.tag = integer(f);
      else if (k == "blocking") flag(f, l.flags, kLineBlocking);
      else if (k == "blockmonsters") flag(f, l.flags, kLineBlockMonsters);
      else if (k == "twosided") flag(f, l.flags, kLineTwoSided);
      else if (k == "dontpegtop") flag(f, l.flags, kLineUnpegUpper);
      else if (k == "dontpegbottom") flag(f, l.flags, kLineUnpegLower);
      else if (k == "secret") flag(f, l.flags, kLineSecret);
      else if (k == "blocksound") flag(f, l.flags, kLineBlockSound);
      else if (k == "dontdraw") flag(f, l.flags, kLineHidden);
      else if (k == "mapped") flag(f, l.flags, kLineMapped);
    }
    const std::string which = "linedef #" + std::to_string(data_.linedefs.size());
    if (!have_v1 || !have_v2 || !have_front) lex_.fail(line, which + " needs v1, v2 and sidefront");
    for (int v : {l.v1, l.v2})
      if (v < 0 || size_t(v) >= data_.vertices.size())
        lex_.fail(line, which + ": vertex " + std::to_string(v) + " does not exist (" +
                            std::to_string(data_.vertices.size()) + " vertices come before it)");
    if (l.back < 0) l.back = kNoSide;
    data_.linedefs.push_back(l);
  }

  void sidedef(const std::vector<Field>& fields) {
    MapSidedef s;
    for (const Field& f : fields) {
      const std::string& k = f.key;
      if (k == "offsetx") s.x_offset = number(f);
      else if (k == "offsety") s.y_offset = number(f);
      else if (k == "texturetop") s.upper = text(f);
      else if (k == "texturemiddle") s.middle = text(f);
      else if (k == "texturebottom") s.lower = text(f);
      else if (k == "sector") s.sector = integer(f);
      else if (k == "offsetx_top") s.part_x[0] = number(f);
      else if (k == "offsetx_mid") s.part_x[1] = number(f);
      else if (k == "offsetx_bottom") s.part_x[2] = number(f);
      else if (k == "offsety_top") s.part_y[0] = number(f);
      else if (k == "offsety_mid") s.part_y[1] = number(f);
      else if (k == "offsety_bottom") s.part_y[2] = number(f);
      else if (k == "light") s.light = integer(f);
      else if (k == "lightabsolute") s.light_absolute = boolean(f);
    }
    data_.sidedefs.push_back(s);
  }

  void sector(const std::vector<Field>& fields) {
    MapSector s;
    for (const Field& f : fields) {
      const std::string& k = f.key;
      if (k == "heightfloor") s.floor = number(f);
      else if (k == "heightceiling") s.ceiling = number(f);
      else if (k == "texturefloor") s.floor_flat = text(f);
      else if (k == "textureceiling") s.ceiling_flat = text(f);
      else if (k == "lightlevel") s.light = integer(f);
      else if (k == "special") s.special = integer(f);
      else if (k == "id") s.tag = integer(f);
    }
    data_.sectors.push_back(s);
  }

  void thing(const std::vector<Field>& fields) {
    MapThing t;
    bool single = false;
    for (const Field& f : fields) {
      const std::string& k = f.key;
      if (k == "x") t.x = number(f);
      else if (k == "y") t.y = number(f);
      else if (k == "angle") t.angle = integer(f);
      else if (k == "type") t.type = integer(f);
      else if (k == "skill1" || k == "skill2") add_flag(f, t.flags, doom::kThingEasy);  // either skill sets the bit
      else if (k == "skill3") add_flag(f, t.flags, doom::kThingMedium);
      else if (k == "skill4" || k == "skill5") add_flag(f, t.flags, doom::kThingHard);
      else if (k == "ambush") flag(f, t.flags, doom::kThingAmbush);
      else if (k == "single") single = boolean(f);
    }
    if (!single) t.flags |= doom::kThingNotSingle;
    data_.things.push_back(t);
  }

  Lexer lex_;
  MapData data_;
  std::string namespace_;
};

}  // namespace

MapData parse_udmf(std::string_view text, const std::string& where) { return Parser(text, where).run(); }

}  // namespace p3d::wad
