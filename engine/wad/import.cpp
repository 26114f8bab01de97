// WAD map records -> map::Source. Index: Importer::run (the pipeline), sectors and
// flats, walls (sides, textures, flags), trim_overlaps (collinear overlaps),
// report_* (what is kept with a warning), things and the player start, art.
#include "engine/wad/import.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "engine/util/error.h"
#include "engine/wad/art_cache.h"
#include "engine/wad/nodes.h"
#include "engine/wad/things.h"

namespace p3d::wad {

namespace {

using geom::IPoint;

constexpr int kPlayerOneStart = 1;  // the thing type of player 1's start
constexpr int kPlaceholderSide = 64;
constexpr int kMaxLight = 255;

// A collinear piece of a wall, by its end vertices.
struct Piece {
  int v1, v2;
};

class Importer {
 public:
  Importer(const Stack& stack, const MapData& data, const ImportOptions& options)
      : data_(data),
        options_(options),
        own_cache_(options.art_cache ? nullptr : std::make_unique<ArtCache>(stack, false)),
        cache_(options.art_cache ? *options.art_cache : *own_cache_),
        art_(cache_.art()) {
    if (&cache_.stack() != &stack) throw std::logic_error("ImportOptions::art_cache serves another Stack");
  }

  ImportResult run() {
    src_.path = data_.where;
    src_.title = data_.name;
    make_light_maps();
    add_sectors();
    add_vertices();
    add_walls();
    trim_overlaps();
    if (src_.walls.empty()) throw Error(data_.where + ": no usable lines: there is no level to build");
    report_missing_parts();
    report_crossings();
    report_open_sectors();
    add_things();
    add_always_frames();
    add_sky();
    finish_warnings();
    size_t count = 0;
    for (const auto& [kind, n] : warning_counts_) count += n;
    return {std::move(src_), std::move(warnings_), count};
  }

 private:
  // ---- warnings --------------------------------------------------------------
  void warn(const std::string& kind, const std::string& record, const std::string& message) {
    if (++warning_counts_[kind] > options_.max_warnings_per_kind) return;
    warnings_.push_back(escape_controls(data_.where + ": " + record + ": warning: " + message));
  }
  void finish_warnings() {
    for (const auto& [kind, count] : warning_counts_)
      if (count > options_.max_warnings_per_kind)
        warnings_.push_back(data_.where + ": warning: " + std::to_string(count - options_.max_warnings_per_kind) +
                            " more " + kind);
  }
  static std::string line_record(int i) { return "LINEDEFS #" + std::to_string(i); }
  static std::string side_record(int i) { return "SIDEDEFS #" + std::to_string(i); }
  static std::string sector_record(int i) { return "SECTORS #" + std::to_string(i); }

  // ---- art -------------------------------------------------------------------
  void make_light_maps() {
    src_.palette = art_.palette();
    src_.light_maps.resize(size_t(limits::kStoredMaps) * limits::kPaletteSize);
    for (int m = 0; m < limits::kStoredMaps; ++m)
      for (int i = 0; i < limits::kPaletteSize; ++i)
        src_.light_maps[size_t(m) * limits::kPaletteSize + i] =
            art_.palette()[art_.colormap()[size_t(m) * kPaletteColors + i]];
  }

  int add_texture(const std::string& name, ArtCache::Picture picture) {
    map::Texture t;
    t.name = name;
    t.image = std::move(picture.colours);
    t.indices = std::move(picture.indices);
    t.opaque = std::move(picture.opaque);
    t.column_major = true;
    t.loc = FileLoc{data_.where, 0};
    src_.textures.push_back(std::move(t));
    return int(src_.textures.size()) - 1;
  }

  // A wall texture by name: its index, kNone for "-" or an unknown name (warned about
  // once). A switch texture brings its pair along, which the level shows once used.
  int wall_texture(const std::string& name, const std::string& record, bool must_exist = true) {
    if (name.empty() || name == "-") return map::kNone;
    const auto it = wall_textures_.find(name);
    if (it != wall_textures_.end()) return it->second;
    ArtCache::Entry* entry = must_exist || art_.has_texture(name) ? &cache_.texture(name) : nullptr;
    const bool found = entry && entry->picture;
    if (entry)
      for (const std::string& p : entry->problems) warn("broken patches", record, p);
    const int index = found ? add_texture(name, cache_.share(*entry, options_.colours)) : map::kNone;
    if (!found && must_exist) warn("unknown textures", record, "texture " + printable(name) + " does not exist (drawn as missing)");
    wall_textures_[name] = index;
    if (const std::string pair = doom::switch_partner(name); found && !pair.empty()) wall_texture(pair, record, false);
    if (found) animate(true, name, record);
    return index;
  }

  // A flat by name; an unknown one becomes a checkered placeholder (warned about once).
  int flat(const std::string& name, const std::string& record) {
    const auto it = flats_.find(name);
    if (it != flats_.end()) return it->second;
    ArtCache::Entry& entry = cache_.flat(name);
    for (const std::string& p : entry.problems) warn("broken flats", record, p);
    int index;
    if (entry.picture) {
      index = add_texture(name, cache_.share(entry, options_.colours));
    } else {
      warn("unknown flats", record, "flat " + printable(name) + " does not exist (drawn as a placeholder)");
      index = add_texture(name, cache_.colour(placeholder()));
    }
    flats_[name] = index;
    if (entry.picture) animate(false, name, record);
    return index;
  }

  // A texture or flat in one of Doom's animated ranges brings the range's other
  // frames along, and the level learns to show them in turn.
  void animate(bool texture, const std::string& name, const std::string& record) {
    if (!animation_frames_) {  // the ranges these WADs hold, found once
      animation_frames_.emplace();
      for (const doom::AnimatedRange& range : doom::animated_ranges())
        if (Art::AnimationFrames f = art_.animation_frames(range); !f.names.empty())
          animation_frames_->push_back({range, std::move(f), false});
    }
    for (AnimatedRangeInUse& a : *animation_frames_) {
      if (a.used || a.range.texture != texture) continue;
      if (std::find(a.frames.names.begin(), a.frames.names.end(), name) == a.frames.names.end()) continue;
      a.used = true;
      doom::TextureAnimation animation;
      animation.tics = a.range.tics;
      const int n = int(a.frames.names.size());
      animation.phase = a.frames.first_number % n;
      for (const std::string& frame : a.frames.names)
        animation.frames.push_back(texture ? wall_texture(frame, record, false) : flat(frame, record));
      if (std::find(animation.frames.begin(), animation.frames.end(), map::kNone) == animation.frames.end())
        src_.animations.push_back(std::move(animation));
      return;
    }
  }

  // A checkerboard of the palette's darkest and brightest colours.
  IndexedImage placeholder() const {
    auto luma = [&](int i) {
      const uint32_t c = art_.palette()[size_t(i)];
      return int(c & 0xFF) + int(c >> 8 & 0xFF) + int(c >> 16 & 0xFF);
    };
    uint8_t dark = 0, bright = 0;
    for (int i = 0; i < kPaletteColors; ++i) {
      if (luma(i) < luma(dark)) dark = uint8_t(i);
      if (luma(i) > luma(bright)) bright = uint8_t(i);
    }
    IndexedImage img(kPlaceholderSide, kPlaceholderSide);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) img.indices[img.at(x, y)] = ((x / 8 + y / 8) & 1) ? bright : dark;
    std::fill(img.opaque.begin(), img.opaque.end(), 1);
    return img;
  }

  void add_sky() {
    const std::string name = sky_texture_name(data_.name);
    src_.sky_texture = wall_texture(name, "sky");
  }

  // ---- sectors ---------------------------------------------------------------
  void add_sectors() {
    for (size_t i = 0; i < data_.sectors.size(); ++i) {
      const MapSector& m = data_.sectors[i];
      const std::string record = sector_record(int(i));
      map::Sector s;
      s.name = std::to_string(i);
      s.loc = FileLoc{data_.where + ": " + record, 0};
      for (double h : {m.floor, m.ceiling})
        if (!std::isfinite(h) || std::fabs(h) > geom::kMaxCoord)
          throw Error(s.loc, "height " + std::to_string(h) + " is outside +-" + std::to_string(int64_t(geom::kMaxCoord)));
      s.floor = m.floor;
      s.ceiling = m.ceiling;
      if (s.ceiling < s.floor)
        warn("ceilings below floors", record,
             "ceiling " + number(s.ceiling) + " is below floor " + number(s.floor) + " (kept: Doom draws it so)");
      s.light = std::clamp(m.light, 0, kMaxLight);
      if (s.light != m.light)
        warn("light out of range", record, "light " + std::to_string(m.light) + " is outside 0..255 (clamped)");
      s.floor_texture = m.floor_flat == kSkyFlat ? map::kSkyTexture : flat(m.floor_flat, record);
      s.ceiling_texture = m.ceiling_flat == kSkyFlat ? map::kSkyTexture : flat(m.ceiling_flat, record);
      s.special = m.special;
      s.tag = m.tag;
      src_.sectors.push_back(std::move(s));
    }
  }

  static std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }

  // ---- vertices --------------------------------------------------------------
  void add_vertices() {
    for (size_t i = 0; i < data_.vertices.size(); ++i) {
      const MapVertex& m = data_.vertices[i];
      map::Vertex v;
      if (!geom::to_fixed(m.x, v.pos.x) || !geom::to_fixed(m.y, v.pos.y))
        throw Error(FileLoc{data_.where + ": VERTEXES #" + std::to_string(i), 0},
                    "coordinates (" + number(m.x) + ", " + number(m.y) + ") are outside +-" +
                        std::to_string(int64_t(geom::kMaxCoord)));
      src_.vertices.push_back(v);
    }
  }

  // ---- walls -----------------------------------------------------------------
  // Whether sidedef k exists and names an existing sector.
  bool valid_side(int k) const {
    return k >= 0 && size_t(k) < data_.sidedefs.size() && data_.sidedefs[size_t(k)].sector >= 0 &&
           size_t(data_.sidedefs[size_t(k)].sector) < data_.sectors.size();
  }

  std::string why_invalid(int k) const {
    if (k < 0 || size_t(k) >= data_.sidedefs.size())
      return "sidedef " + std::to_string(k) + " does not exist (SIDEDEFS has " + std::to_string(data_.sidedefs.size()) + ")";
    return side_record(k) + " names sector " + std::to_string(data_.sidedefs[size_t(k)].sector) +
           ", which does not exist (SECTORS has " + std::to_string(data_.sectors.size()) + ")";
  }

  map::Side side(int k, const std::string& record) {
    const MapSidedef& m = data_.sidedefs[size_t(k)];
    map::Side s;
    s.sector = m.sector;
    s.upper = wall_texture(m.upper, record);
    s.middle = wall_texture(m.middle, record);
    s.lower = wall_texture(m.lower, record);
    s.x_offset = m.x_offset;
    s.y_offset = m.y_offset;
    const auto nonzero = [](const double(&v)[3]) { return v[0] != 0 || v[1] != 0 || v[2] != 0; };
    if (nonzero(m.part_x) || nonzero(m.part_y)) {  // rare: kept apart from the sides
      s.parts = int(src_.part_offsets.size());
      map::PartOffsets& parts = src_.part_offsets.emplace_back();
      std::copy(std::begin(m.part_x), std::end(m.part_x), parts.x);
      std::copy(std::begin(m.part_y), std::end(m.part_y), parts.y);
    }
    if (m.light_absolute || m.light != 0)
      s.light = std::clamp(m.light_absolute ? m.light : data_.sectors[size_t(m.sector)].light + m.light, 0, kMaxLight);
    return s;
  }

  void add_walls() {
    for (size_t i = 0; i < data_.linedefs.size(); ++i) {
      const MapLinedef& l = data_.linedefs[i];
      const std::string record = line_record(int(i));
      if (src_.point(l.v1) == src_.point(l.v2)) {
        warn("zero-length lines", record, "zero-length line (dropped)");
        continue;
      }
      if (!valid_side(l.front)) {
        warn("lines without a front side", record, "front " + why_invalid(l.front) + " (line dropped)");
        continue;
      }
      map::Wall w;
      w.v1 = l.v1;
      w.v2 = l.v2;
      w.loc = FileLoc{data_.where + ": " + record, 0};
      w.source = int(i);
      w.special = l.special;
      w.tag = l.tag;
      w.flags = (l.flags & kLineUnpegUpper ? map::kUnpegUpper : 0u) | (l.flags & kLineUnpegLower ? map::kUnpegLower : 0u) |
                (l.flags & kLineBlocking ? map::kImpassable : 0u) | (l.flags & kLineSecret ? map::kSecret : 0u) |
                (l.flags & kLineHidden ? map::kHidden : 0u) | (l.flags & kLineMapped ? map::kMapped : 0u);
      w.front = side(l.front, record);
      if (l.back != kNoSide) {
        if (valid_side(l.back))
          w.back = side(l.back, record);
        else
          warn("bad back sides", record, "back " + why_invalid(l.back) + " (line made one-sided)");
      }
      if (w.two_sided() && w.front.sector == w.back.sector && l.special == 0 && w.front.middle == map::kNone &&
          w.back.middle == map::kNone)
        warn("same sector on both sides", record,
             "sector " + std::to_string(w.front.sector) + " on both sides, no special, no texture (it draws nothing)");
      if (src_.walls.size() >= limits::kMaxWalls) throw Error(data_.where + ": " + limits::too_many_walls());
      src_.walls.push_back(std::move(w));
    }
  }

  // ---- collinear overlaps ----------------------------------------------------
  // Two collinear walls on the same stretch conflict when one viewpoint can see
  // both: they face the same way, or either is two-sided.
  bool conflict(const map::Wall& a, const map::Wall& b) const {
    const IPoint da = geom::sub(src_.point(a.v2), src_.point(a.v1)), db = geom::sub(src_.point(b.v2), src_.point(b.v1));
    const bool same_way = da.x * db.x + da.y * db.y > 0;
    return same_way || a.two_sided() || b.two_sided();
  }

  void trim_overlaps() {
    std::vector<std::vector<uint32_t>> earlier(src_.walls.size());  // conflicting overlaps with earlier walls
    for (const map::Contact& c : map::find_contacts(src_, SIZE_MAX))
      if (c.kind == geom::SegmentContact::kOverlap && conflict(src_.walls[c.a], src_.walls[c.b]))
        earlier[c.b].push_back(c.a);
    std::vector<std::vector<Piece>> pieces(src_.walls.size());
    for (size_t j = 0; j < src_.walls.size(); ++j) {
      const map::Wall& w = src_.walls[j];
      pieces[j] = {{w.v1, w.v2}};
      for (uint32_t i : earlier[j])
        for (const Piece& p : pieces[i]) pieces[j] = subtract(pieces[j], p);
      if (earlier[j].empty()) continue;
      const std::string record = line_record(w.source);
      std::string other;
      for (uint32_t i : earlier[j]) other += (other.empty() ? "" : ", ") + line_record(src_.walls[i].source);
      if (pieces[j].empty())
        warn("overlapping lines", record, "lies on " + other + " (dropped: the earlier line is drawn)");
      else if (pieces[j].size() != 1 || pieces[j][0].v1 != w.v1 || pieces[j][0].v2 != w.v2)
        warn("overlapping lines", record, "overlaps " + other + " (keeps only the part the earlier line leaves)");
    }
    std::vector<map::Wall> kept;
    for (size_t j = 0; j < src_.walls.size(); ++j)
      for (const Piece& p : pieces[j]) kept.push_back(piece_of(src_.walls[j], p));
    src_.walls = std::move(kept);
  }

  // Position of p along the (collinear) direction d: exact, on the dominant axis.
  static int64_t along(IPoint d, IPoint p) { return std::llabs(d.x) >= std::llabs(d.y) ? p.x * geom::sign(d.x) : p.y * geom::sign(d.y); }

  // The parts of `pieces` (collinear, directed) that `cut` does not cover.
  std::vector<Piece> subtract(const std::vector<Piece>& pieces, const Piece& cut) const {
    std::vector<Piece> out;
    for (const Piece& p : pieces) {
      const IPoint d = geom::sub(src_.point(p.v2), src_.point(p.v1));
      const int64_t a = along(d, src_.point(p.v1)), b = along(d, src_.point(p.v2));
      int c0 = cut.v1, c1 = cut.v2;
      if (along(d, src_.point(c0)) > along(d, src_.point(c1))) std::swap(c0, c1);
      const int64_t ca = along(d, src_.point(c0)), cb = along(d, src_.point(c1));
      if (cb <= a || ca >= b) {
        out.push_back(p);
        continue;
      }
      if (ca > a) out.push_back({p.v1, c0});
      if (cb < b) out.push_back({c1, p.v2});
    }
    return out;
  }

  // The wall restricted to a piece; texture offsets keep the texture where it was.
  map::Wall piece_of(const map::Wall& w, const Piece& p) const {
    map::Wall out = w;
    out.v1 = p.v1;
    out.v2 = p.v2;
    auto distance = [&](int a, int b) { return glm::length(geom::to_world(src_.point(a)) - geom::to_world(src_.point(b))); };
    if (p.v1 != w.v1) out.front.x_offset += distance(w.v1, p.v1);
    if (p.v2 != w.v2) out.back.x_offset += distance(p.v2, w.v2);  // the back side's texture runs from v2
    return out;
  }

  // ---- what is kept, with a warning -----------------------------------------
  void report_missing_parts() {
    for (const map::Wall& w : src_.walls) {
      const std::string record = line_record(w.source);
      if (!w.two_sided()) {
        if (w.front.middle == map::kNone)
          warn("missing textures", record, "one-sided line without a middle texture (the sector shows through)");
        continue;
      }
      const map::Sector& f = src_.sectors[size_t(w.front.sector)];
      const map::Sector& b = src_.sectors[size_t(w.back.sector)];
      const bool both_sky = f.ceiling_texture == map::kSkyTexture && b.ceiling_texture == map::kSkyTexture;
      auto check = [&](const map::Side& s, const map::Sector& near, const map::Sector& far, const char* which) {
        if (far.ceiling < near.ceiling && !both_sky && s.upper == map::kNone)
          warn("missing textures", record,
               std::string(which) + " side needs an upper texture (the far ceiling shows instead)");
        if (far.floor > near.floor && s.lower == map::kNone)
          warn("missing textures", record, std::string(which) + " side needs a lower texture (the far floor shows instead)");
      };
      check(w.front, f, b, "front");
      check(w.back, b, f, "back");
    }
  }

  void report_crossings() {
    for (const map::Contact& c : map::find_contacts(src_, SIZE_MAX))
      if (c.kind == geom::SegmentContact::kCross)
        warn("crossing lines", line_record(src_.walls[c.b].source),
             "crosses " + line_record(src_.walls[c.a].source) + " (both kept, as Doom draws both)");
  }

  void report_open_sectors() {
    for (const map::OpenSector& o : map::find_open_sectors(src_)) {
      const geom::Vec2 p = geom::to_world(o.at);
      warn("unclosed sectors", sector_record(o.sector),
           "not closed: its boundary has an open end at (" + number(p.x) + ", " + number(p.y) + ")");
    }
  }

  // ---- things ----------------------------------------------------------------
  void add_things() {
    int start = -1;
    for (size_t i = 0; i < data_.things.size(); ++i) {
      const MapThing& m = data_.things[i];
      const std::string record = "THINGS #" + std::to_string(i);
      if (!std::isfinite(m.x) || !std::isfinite(m.y) || std::fabs(m.x) > geom::kMaxCoord || std::fabs(m.y) > geom::kMaxCoord) {
        warn("things out of range", record, "position is outside the map range (ignored)");
        continue;
      }
      map::Thing t;
      t.type = m.type;
      t.pos = {m.x, m.y};
      t.angle = std::trunc(m.angle / 45) * 45;  // Doom faces things in 45-degree steps
      t.flags = m.flags;
      t.sprite = sprite_for(m.type, record);
      src_.things.push_back(t);
      if (m.type == kPlayerOneStart) start = int(i);  // Doom spawns the player at the last one
    }
    if (start >= 0) {
      const MapThing& m = data_.things[size_t(start)];
      src_.player = {{m.x, m.y}, m.angle, FileLoc{data_.where + ": THINGS #" + std::to_string(start), 0}};
      return;
    }
    warn("no player start", "THINGS", "no player 1 start (the player starts beside the first line)");
    src_.player = {inside_first_wall(), 90, FileLoc{data_.where + ": THINGS", 0}};
  }

  // The sprite frame a thing type shows at the start, built from the WADs' sprite
  // lumps; kNone for editor-only things, unknown types and missing sprites (warned).
  // Every other frame it may show or make shown comes along (more_frames), for the
  // world to show in turn.
  int sprite_for(int type, const std::string& record) {
    const ThingInfo* info = editor_only_thing(type) ? nullptr : thing_info(type);
    if (!info && !editor_only_thing(type))
      warn("unknown thing types", record, "thing type " + std::to_string(type) + " is not Doom's (not drawn)");
    const int first = info ? sprite_frame(*info, info->sprite, info->frame, info->bright, record) : map::kNone;
    more_frames(type, info, record);
    return first;
  }

  // The frames a type placed may go on to show (ImportOptions::thing_frames), once per
  // type: a hanging thing's hang as it does; the rest stand.
  void more_frames(int type, const ThingInfo* info, const std::string& record) {
    if (!options_.thing_frames || !framed_types_.insert(type).second) return;
    for (const FrameName& f : options_.thing_frames(type))
      sprite_frame(info ? *info : kStanding, f.sprite, f.frame, f.bright, record, true);
  }

  void add_always_frames() {
    for (const FrameName& f : options_.always_frames) sprite_frame(kStanding, f.sprite, f.frame, f.bright, "SPRITES", true);
  }

  // What builds the frames no type placed stands for: a thing standing on the floor.
  static constexpr ThingInfo kStanding{0, "", 'A', false, false, 0, 0, ThingKind::kDecoration};

  // A sprite frame of a thing type, built once for each way of showing it (a frame
  // may be bright in one state and not in another; two hanging things may show the
  // same picture at different drops). `quiet`: a frame the WADs lack is no warning
  // (the many a level may show and the WADs need not have).
  int sprite_frame(const ThingInfo& info, const std::string& sprite, char frame_letter, bool bright,
                   const std::string& record, bool quiet = false) {
    const std::string name = sprite + frame_letter;
    const std::string key = name + (bright ? "*" : "") + (info.hanging ? "@" + std::to_string(info.height) : "");
    if (const auto it = sprite_frames_.find(key); it != sprite_frames_.end()) return it->second;
    if (quiet && quietly_missing_.count(key)) return map::kNone;
    const int frame = build_frame(info, sprite, frame_letter, bright, record, quiet);
    if (frame == map::kNone && quiet)
      quietly_missing_.insert(key);  // not cached as missing: a thing showing it first is still warned about
    else
      sprite_frames_[key] = frame;
    return frame;
  }

  // Doom's sprite lumps: PPPPFR, or PPPPFRFR where the second frame and rotation use
  // the same picture mirrored; rotation 0 serves every direction.
  int build_frame(const ThingInfo& info, const std::string& sprite, char frame_letter, bool bright,
                  const std::string& record, bool quiet) {
    const std::string name = sprite + frame_letter;
    int lumps[map::kRotations];
    bool flips[map::kRotations] = {};
    std::fill(std::begin(lumps), std::end(lumps), -1);
    const std::vector<const Lump*>& sprite_lumps = cache_.sprite_lumps();
    auto install = [&](char rotation, int lump, bool flip) {
      if (rotation == '0') {
        for (int r = 0; r < map::kRotations; ++r)
          if (lumps[r] < 0) lumps[r] = lump, flips[r] = flip;
      } else if (rotation >= '1' && rotation <= '8') {
        lumps[rotation - '1'] = lump, flips[rotation - '1'] = flip;
      }
    };
    for (const uint32_t k : cache_.sprite_lumps_named(sprite)) {  // PPPP: the names that may hold the frame
      const std::string& lump = sprite_lumps[k]->name;
      if (lump[4] == frame_letter) install(lump[5], int(k), false);
      if (lump.size() >= 8 && lump[6] == frame_letter) install(lump[7], int(k), true);
    }
    const int any = *std::max_element(std::begin(lumps), std::end(lumps));
    if (any < 0) {
      if (!quiet) warn("missing sprites", record, "sprite " + name + " does not exist (not drawn)");
      return map::kNone;
    }
    if (std::count(std::begin(lumps), std::end(lumps), -1) > 0 && !quiet)
      warn("missing sprites", record, "sprite " + name + " lacks some rotations (the others stand in)");
    map::SpriteFrame frame;
    frame.name = name;
    frame.bright = bright;
    frame.hanging = info.hanging;
    frame.drop = info.height;
    for (int r = 0; r < map::kRotations; ++r) {
      const int lump = lumps[r] >= 0 ? lumps[r] : any;
      const int image = sprite_image(*sprite_lumps[size_t(lump)], record);
      if (image < 0) return map::kNone;
      frame.image[r] = image;
      frame.flip[r] = lumps[r] >= 0 && flips[r];
    }
    src_.sprites.push_back(frame);
    return int(src_.sprites.size()) - 1;
  }

  int sprite_image(const Lump& lump, const std::string& record) {
    if (const auto it = sprite_images_.find(lump.name); it != sprite_images_.end()) return it->second;
    int index = -1;
    ArtCache::Entry& entry = cache_.sprite(lump);
    for (const std::string& p : entry.problems) warn("broken sprites", record, p + " (not drawn)");
    if (entry.picture) {
      ArtCache::Picture picture = cache_.share(entry, options_.colours);
      map::SpriteImage out;
      out.name = lump.name;
      out.image = std::move(picture.colours);
      out.indices = std::move(picture.indices);
      out.opaque = std::move(picture.opaque);
      out.column_major = true;
      out.left = picture.left;
      out.top = picture.top;
      src_.sprite_images.push_back(std::move(out));
      index = int(src_.sprite_images.size()) - 1;
    }
    sprite_images_[lump.name] = index;
    return index;
  }

  // A point just in front of the first wall's middle.
  geom::Vec2 inside_first_wall() const {
    if (src_.walls.empty()) return {0, 0};
    const map::Wall& w = src_.walls.front();
    const geom::Vec2 a = geom::to_world(src_.point(w.v1)), b = geom::to_world(src_.point(w.v2));
    const geom::Vec2 d = glm::normalize(b - a);
    return (a + b) * 0.5 + geom::Vec2(d.y, -d.x) * 8.0;  // the front is on the right
  }

  const MapData& data_;
  const ImportOptions& options_;
  std::unique_ptr<ArtCache> own_cache_;  // when the options bring none
  ArtCache& cache_;
  const Art& art_;
  map::Source src_;
  std::vector<std::string> warnings_;
  std::map<std::string, size_t> warning_counts_;
  std::unordered_map<std::string, int> wall_textures_, flats_, sprite_frames_, sprite_images_;
  std::unordered_set<std::string> quietly_missing_;  // sprite_frame's keys of frames the WADs lack
  std::unordered_set<int> framed_types_;             // types whose more_frames are in
  struct AnimatedRangeInUse {
    doom::AnimatedRange range;
    Art::AnimationFrames frames;
    bool used;
  };
  std::optional<std::vector<AnimatedRangeInUse>> animation_frames_;
};

}  // namespace

ImportResult import_map_data(const Stack& stack, const MapData& data, const ImportOptions& options,
                             const MapLumps* lumps) {
  ImportResult result = Importer(stack, data, options).run();
  if (lumps) {
    std::vector<geom::Vec2> points;
    for (const map::Thing& t : result.source.things) points.push_back(t.pos);
    if (const auto sectors = sectors_by_doom_nodes(*lumps, data, points))
      for (size_t i = 0; i < points.size(); ++i) result.source.things[i].sector = (*sectors)[i];
  }
  return result;
}

ImportResult import_map(const Stack& stack, std::string_view map_name, const ImportOptions& options) {
  const std::optional<MapLumps> lumps = stack.map(map_name);
  if (!lumps) {
    std::string wads, names;
    for (const Wad& w : stack.wads()) wads += (wads.empty() ? "" : ", ") + w.name();
    for (const std::string& n : stack.map_names()) names += (names.empty() ? "" : " ") + n;
    throw Error(wads + ": no map " + printable(normalize_name(map_name)) +
                (names.empty() ? " (the WADs hold no maps)" : " (maps: " + names + ")"));
  }
  return import_map_data(stack, read_map(*lumps), options, &*lumps);
}

}  // namespace p3d::wad
