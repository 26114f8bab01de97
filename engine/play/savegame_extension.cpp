// Our extension of Doom's savegames (savegame.h): what Doom's format loses, written
// after its end marker, read and checked before anything of it is applied, put back
// after Doom's part is loaded.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <unordered_map>

#include "engine/play/demo.h"
#include "engine/play/savegame_local.h"
#include "engine/util/bytes.h"

namespace p3d::play::savegame_local {

namespace {

constexpr char kExtensionMagic[8] = {'P', '3', 'D', 'S', 'A', 'V', 'E', '\0'};


// References to things: -1 none, 0.. the live ones in the thinkers section's order,
// then the removed ones still pointed at ("ghosts").
class MobjRefs {
 public:
  explicit MobjRefs(const std::vector<const Mobj*>& live) {
    for (size_t i = 0; i < live.size(); ++i) index_[live[i]] = int32_t(i);
    live_ = live.size();
  }
  int32_t ref(const Mobj* m) {
    if (!m) return -1;
    if (const auto it = index_.find(m); it != index_.end()) return it->second;
    const int32_t r = int32_t(live_ + ghosts.size());
    index_[m] = r;
    ghosts.push_back(m);
    return r;
  }
  std::vector<const Mobj*> ghosts;  // grows as refs meet removed things

 private:
  std::unordered_map<const Mobj*, int32_t> index_;
  size_t live_ = 0;
};

void put_mobj_full(ByteWriter& out, const DoomMobj& d) {
  for (int32_t v : {d.x, d.y, d.z, d.angle, d.sprite, d.frame, d.floor_z, d.ceiling_z, d.radius, d.height, d.mom_x, d.mom_y,
                    d.mom_z, d.valid_count, d.type, d.tics, d.state, d.flags, d.health, d.move_dir, d.move_count,
                    d.reaction_time, d.threshold, d.player, d.last_look})
    out.i32(v);
  for (int16_t v : {d.spawn_x, d.spawn_y, d.spawn_angle, d.spawn_type, d.spawn_options}) out.u16(uint16_t(v));
}

void put_plat(ByteWriter& out, const DoomPlat& r) {
  out.u8(r.thinking);
  for (int32_t v : {r.sector, r.speed, r.low, r.high, r.wait, r.count, r.status, r.old_status, r.crush, r.tag, r.type}) out.i32(v);
}

}  // namespace

std::vector<uint8_t> encode_extension(const World& w, const SaveExtras& x) {
  const ThinkerLists lists = thinker_lists(w);
  MobjRefs refs(lists.mobjs);
  std::unordered_map<const Thinker*, int32_t> thinker_ref;
  for (size_t i = 0; i < lists.order.size(); ++i) {
    const auto& e = lists.order[i];
    const Thinker* t = e.source == 0 ? lists.mobjs[e.index] : e.source == 1 ? lists.specials[e.index] : lists.own[e.index];
    thinker_ref[t] = int32_t(i);
  }
  auto tref = [&](const Thinker* t) {
    const auto it = t ? thinker_ref.find(t) : thinker_ref.end();
    return it == thinker_ref.end() ? int32_t(-1) : it->second;
  };
  ByteWriter out;
  out.u64(fingerprint(w.level_));
  // the game's extras
  out.u64(x.tics);
  out.str(x.message.substr(0, kMaxMessage));
  out.i32(x.message_tics);
  out.u8(x.other_random);
  for (int v : {x.face.index, x.face.count, x.face.priority, x.face.old_health, x.face.attack_countdown}) out.i32(v);
  for (bool b : x.face.old_weapons) out.u8(b);
  for (double v : x.previous_pose) out.f64(std::isfinite(v) ? v : 0);
  // the World's own state
  out.u8(w.random_.play_index()), out.u8(w.random_.other_index());
  out.i32(w.level_time_), out.i32(w.game_tic_at_start_);
  out.u8(w.on_ground_), out.u8(uint8_t(w.exit_));
  out.u32(w.next_id_);
  out.i32(w.total_kills_), out.i32(w.total_items_), out.i32(w.total_secrets_);
  out.u8(w.brain_easy_);
  out.u32(uint32_t(w.brain_target_on_));
  out.u32(uint32_t(w.brain_targets_.size()));
  for (const Mobj* m : w.brain_targets_) out.i32(refs.ref(m));
  for (int p = 0; p < kMaxPlayers; ++p)
    if (w.in_game(p)) out.i32(refs.ref(w.player(p).attacker)), out.str(w.player(p).message.substr(0, kMaxMessage));
  // the map in full precision, with the sectors' thing lists in order
  out.u32(uint32_t(w.map_.sectors.size()));
  for (const Sector& s : w.map_.sectors) {
    for (int32_t v : {s.floor_height, s.ceiling_height, s.floor_pic, s.ceiling_pic, s.light, s.special, s.tag}) out.i32(v);
    out.i32(refs.ref(s.sound_target));
    out.i32(tref(s.special_data));
    std::vector<int32_t> list;
    for (const Mobj* m = s.thing_list; m; m = m->snext) list.push_back(refs.ref(m));
    out.u32(uint32_t(list.size()));
    for (int32_t r : list) out.i32(r);
  }
  out.u32(uint32_t(w.map_.sides.size()));
  for (const Side& s : w.map_.sides)
    for (int32_t v : {s.texture_offset, s.row_offset, s.top, s.bottom, s.middle}) out.i32(v);
  out.u32(uint32_t(w.map_.lines.size()));
  for (const Line& l : w.map_.lines)
    for (int32_t v : {l.flags, l.special, l.tag}) out.i32(v);
  // the thinkers: Doom's sections' sizes, ours, and the order they all run in
  out.u32(uint32_t(lists.mobjs.size()));
  out.u32(uint32_t(lists.specials.size()));
  out.u32(uint32_t(lists.own.size()));
  for (const Thinker* t : lists.own) {
    if (t->kind == Thinker::Kind::kFireFlicker) {
      const FireFlicker& f = *static_cast<const FireFlicker*>(t);
      out.u8(0);
      for (int32_t v : {f.sector->index, f.count, f.max_light, f.min_light}) out.i32(v);
    } else if (t->kind == Thinker::Kind::kPlat) {
      out.u8(1);
      put_plat(out, doom_plat_of(*static_cast<const Plat*>(t)));
    } else {  // a crusher in stasis that Doom's list lost
      const Ceiling& c = *static_cast<const Ceiling*>(t);
      out.u8(2);
      out.u8(c.active);
      for (int32_t v : {int32_t(c.type), c.sector->index, c.bottom_height, c.top_height, c.speed, int32_t(c.crush), c.direction,
                        c.tag, c.old_direction})
        out.i32(v);
    }
  }
  out.u32(uint32_t(lists.order.size()));
  for (const auto& e : lists.order) out.u8(e.source), out.u32(e.index);
  // the live things' pointers and names
  for (const Mobj* m : lists.mobjs) {
    out.i32(refs.ref(m->target)), out.i32(refs.ref(m->tracer));
    out.u32(m->id), out.i32(m->spawn_point.placed);
  }
  // the blockmap's header, then its cells' thing lists in order
  const Blockmap& bm = w.map_.blockmap;
  for (int32_t v : {bm.origin_x, bm.origin_y, bm.width, bm.height}) out.i32(v);
  // a netgame's queues: the corpses kept, the items to come back
  out.u32(uint32_t(w.body_queue_slot_));
  out.u32(uint32_t(w.body_queue_.size()));
  for (const Mobj* m : w.body_queue_) out.i32(refs.ref(m));
  out.u32(uint32_t(w.item_queue_head_)), out.u32(uint32_t(w.item_queue_tail_));
  for (size_t i = w.item_queue_tail_; i != w.item_queue_head_; i = (i + 1) % World::kItemQueueSize) {
    const MapThing& t = w.item_queue_[i];
    for (int16_t v : {t.x, t.y, t.angle, t.type, t.options}) out.u16(uint16_t(v));
    out.i32(t.placed), out.i32(w.item_queue_time_[i]);
  }
  std::vector<std::pair<uint32_t, std::vector<int32_t>>> cells;
  for (size_t c = 0; c < w.block_links_.size(); ++c) {
    if (!w.block_links_[c]) continue;
    auto& cell = cells.emplace_back(uint32_t(c), std::vector<int32_t>{});
    for (const Mobj* m = w.block_links_[c]; m; m = m->bnext) cell.second.push_back(refs.ref(m));
  }
  out.u32(uint32_t(cells.size()));
  for (const auto& [c, list] : cells) {
    out.u32(c);
    out.u32(uint32_t(list.size()));
    for (int32_t r : list) out.i32(r);
  }
  // the lifts' and crushers' lists, empty slots kept
  out.u32(uint32_t(w.active_plats_.size()));
  for (const Plat* p : w.active_plats_) out.i32(tref(p));
  out.u32(uint32_t(w.active_ceilings_.size()));
  for (const Ceiling* c : w.active_ceilings_) out.i32(tref(c));
  // the switches waiting to flip back
  out.u32(uint32_t(w.buttons_.size()));
  for (const World::Button& b : w.buttons_) {
    out.i32(b.line ? b.line->index : -1), out.i32(b.where), out.i32(b.texture), out.i32(b.timer);
    out.i32(b.sound_sector ? b.sound_sector->index : -1);
  }
  // last, the removed things pointed at (refs above may have added some; theirs may add more)
  ByteWriter ghosts;
  for (size_t g = 0; g < refs.ghosts.size(); ++g) {
    const Mobj* m = refs.ghosts[g];
    put_mobj_full(ghosts, doom_mobj_of(w, *m));
    ghosts.i32(refs.ref(m->target)), ghosts.i32(refs.ref(m->tracer));
    ghosts.u32(m->id), ghosts.i32(m->spawn_point.placed);
  }
  out.u32(uint32_t(refs.ghosts.size()));
  out.raw(ghosts.bytes());

  std::vector<uint8_t> payload = out.release();
  ByteWriter file;
  file.raw(std::span(reinterpret_cast<const uint8_t*>(kExtensionMagic), sizeof kExtensionMagic));
  file.u32(kSaveExtensionVersion);
  file.u32(uint32_t(payload.size()));
  file.u64(fnv1a64(payload));
  file.raw(payload);
  return file.release();
}


namespace {

DoomMobj get_mobj_full(SaveReader& in) {
  DoomMobj d;
  const size_t at = in.position();
  for (int32_t* v : {&d.x, &d.y, &d.z, &d.angle, &d.sprite, &d.frame, &d.floor_z, &d.ceiling_z, &d.radius, &d.height, &d.mom_x,
                     &d.mom_y, &d.mom_z, &d.valid_count, &d.type, &d.tics, &d.state, &d.flags, &d.health, &d.move_dir,
                     &d.move_count, &d.reaction_time, &d.threshold, &d.player, &d.last_look})
    *v = in.i32();
  for (int16_t* v : {&d.spawn_x, &d.spawn_y, &d.spawn_angle, &d.spawn_type, &d.spawn_options}) *v = in.i16();
  check_range(in, at + 16, d.sprite, 0, int(Sprite::kCount) - 1, "a removed thing's sprite");
  check_range(in, at + 56, d.type, 0, int(ThingType::kCount) - 1, "a removed thing's type");
  check_range(in, at + 64, d.state, 0, int(StateId::kCount) - 1, "a removed thing's state");
  check_range(in, at + 76, d.move_dir, 0, 8, "a removed thing's direction");
  check_range(in, at + 92, d.player, 0, kMaxPlayers, "a removed thing's player");
  check_range(in, at + 96, d.last_look, 0, kMaxPlayers - 1, "a removed thing's last player looked at");
  check_mobj_counters(in, d, {at + 32, at + 36, at + 40, at + 44, at + 48, at + 60, at + 72, at + 80, at + 84, at + 88,
                             at + 8, at + 24, at + 28});
  return d;
}

DoomPlat get_plat(SaveReader& in, size_t sectors) {
  DoomPlat r;
  const size_t at = in.position();
  r.thinking = in.u8() != 0;
  for (int32_t* v : {&r.sector, &r.speed, &r.low, &r.high, &r.wait, &r.count, &r.status, &r.old_status, &r.crush, &r.tag, &r.type})
    *v = in.i32();
  check_range(in, at + 1, r.sector, 0, int64_t(sectors) - 1, "a lift's sector");
  check_range(in, at + 25, r.status, 0, int(Plat::Status::kInStasis), "a lift's status");
  check_range(in, at + 29, r.old_status, 0, int(Plat::Status::kInStasis), "a lift's old status");
  check_range(in, at + 41, r.type, 0, int(Plat::Type::kBlazeDwus), "a lift's type");
  check_height(in, at + 9, r.low, "a lift's height");
  check_height(in, at + 13, r.high, "a lift's height");
  check_counter(in, at + 17, r.wait, "a lift's wait");
  check_counter(in, at + 21, r.count, "a lift's count");
  return r;
}

}  // namespace

Extension read_extension(SaveReader& file, const DoomSave& doom, const World& w) {
  file.section("our extension");
  const size_t start = file.position();
  std::array<char, 8> magic{};
  for (char& c : magic) c = char(file.u8());
  if (std::memcmp(magic.data(), kExtensionMagic, sizeof magic) != 0)
    file.fail_at(start, "bytes after Doom's end marker that are not our extension (its magic is P3DSAVE)");
  const uint32_t version = file.u32();
  if (version != kSaveExtensionVersion && version != 1)
    file.fail_at(start + 8, "our extension's version " + std::to_string(version) + " is not " +
                                std::to_string(kSaveExtensionVersion) + " (a newer game's save? load it as Doom would)");
  const uint32_t length = file.u32();
  const uint64_t checksum = file.u64();
  if (length > file.remaining())
    file.fail_at(start + 12, "truncated: our extension says " + std::to_string(length) + " bytes, the file has " +
                                 std::to_string(file.remaining()) + " after its header");
  if (length < file.remaining())
    file.fail_at(start + 24 + length, std::to_string(file.remaining() - length) + " bytes after our extension");
  const size_t payload_at = file.position();
  if (fnv1a64(file.peek(length)) != checksum) file.fail_at(start + 16, "our extension's checksum does not match its bytes");
  SaveReader in = file;  // the payload, read in place (positions stay the file's)
  in.section("our extension");
  Extension x;
  const uint64_t print = in.u64();
  if (print != fingerprint(w.level_))
    in.fail_at(payload_at, "our extension was written on another level than " + w.map_.where +
                               " (load it as Doom would, without our extension)");
  SaveExtras& e = x.extras;
  e.tics = in.u64();
  e.message = in.str(kMaxMessage);
  e.message_tics = in.i32();
  check_counter(in, in.position() - 4, e.message_tics, "the message's time");
  e.other_random = in.u8();
  const size_t face_at = in.position();
  for (int* v : {&e.face.index, &e.face.count, &e.face.priority, &e.face.old_health, &e.face.attack_countdown}) *v = in.i32();
  check_range(in, face_at, e.face.index, 0, kFaceCount - 1, "the face");
  const int memory[] = {e.face.count, e.face.priority, e.face.old_health, e.face.attack_countdown};
  for (size_t k = 0; k < 4; ++k) check_counter(in, face_at + 4 * (k + 1), memory[k], "the face's memory");
  for (bool& b : e.face.old_weapons) b = in.u8() != 0;
  for (double& v : e.previous_pose) v = in.f64();
  x.play_random = in.u8(), x.other_random = in.u8();
  x.level_time = in.i32(), x.game_tic_at_start = in.i32();
  if (x.level_time < 0 || x.level_time > (1 << 30))
    in.fail_at(in.position() - 8, "level time " + std::to_string(x.level_time) + " (a game reaches 0..2^30)");
  x.on_ground = in.u8() != 0;
  const size_t exit_at = in.position();
  x.exit = in.u8();
  check_range(in, exit_at, x.exit, 0, int(ExitKind::kSecret), "the exit taken");
  x.next_id = in.u32();
  const size_t totals_at = in.position();
  x.total_kills = in.i32(), x.total_items = in.i32(), x.total_secrets = in.i32();
  const int32_t totals[] = {x.total_kills, x.total_items, x.total_secrets};
  for (size_t k = 0; k < 3; ++k) check_counter(in, totals_at + 4 * k, totals[k], "the level's totals");
  x.brain_easy = in.u8() != 0;
  const size_t on_at = in.position();
  x.brain_target_on = in.u32();
  const uint32_t brains = in.count(4, "boss brain spots");
  for (uint32_t i = 0; i < brains; ++i) x.brain_targets.push_back(in.i32());
  if (x.brain_target_on != 0 && x.brain_target_on >= brains)
    in.fail_at(on_at, "the boss brain's next spot " + std::to_string(x.brain_target_on) + " of " + std::to_string(brains));
  for (size_t p = 0; p < kMaxPlayers; ++p)
    if (doom.header.in_game[p]) x.attackers[p] = in.i32(), x.messages[p] = in.str(kMaxMessage);

  const Map& map = w.map_;
  const int64_t textures = int64_t(w.level_.textures.size());
  auto texture_index = [&](int32_t t, size_t at, bool flat) {
    if (t == level::kNone || (flat && t == level::kSky)) return;
    check_range(in, at, t, 0, textures - 1, flat ? "a flat" : "a texture");
  };
  auto sized = [&](size_t expected, const char* what, const char* where = "the map") {
    const size_t at = in.position();
    const uint32_t n = in.u32();
    if (n != expected)
      in.fail_at(at, std::to_string(n) + " " + what + " in our extension, " + std::to_string(expected) + " in " + where);
  };
  in.section("our extension's sectors");
  sized(map.sectors.size(), "sectors");
  for (size_t i = 0; i < map.sectors.size(); ++i) {
    Extension::SectorExtra& s = x.sectors.emplace_back();
    const size_t at = in.position();
    for (int32_t* v : {&s.floor, &s.ceiling, &s.floor_pic, &s.ceiling_pic, &s.light, &s.special, &s.tag}) *v = in.i32();
    texture_index(s.floor_pic, at + 8, true);
    texture_index(s.ceiling_pic, at + 12, true);
    check_counter(in, at + 16, s.light, "a sector's light");
    check_height(in, at, s.floor, "a sector's floor");
    check_height(in, at + 4, s.ceiling, "a sector's ceiling");
    s.sound_target = in.i32(), s.special_data = in.i32();
    const uint32_t n = in.count(4, "things in a sector");
    for (uint32_t k = 0; k < n; ++k) s.things.push_back(in.i32());
  }
  in.section("our extension's sides");
  sized(map.sides.size(), "sides");
  for (size_t i = 0; i < map.sides.size(); ++i) {
    auto& s = x.sides.emplace_back();
    const size_t at = in.position();
    for (int32_t& v : s) v = in.i32();
    for (size_t k = 2; k < 5; ++k) texture_index(s[k], at + 4 * k, false);
  }
  in.section("our extension's lines");
  sized(map.lines.size(), "lines");
  for (size_t i = 0; i < map.lines.size(); ++i)
    for (int32_t& v : x.lines.emplace_back()) v = in.i32();

  in.section("our extension's thinkers");
  sized(doom.mobjs.size(), "things", "Doom's part");
  sized(doom.specials.size(), "specials", "Doom's part");
  const uint32_t own = in.count(17, "own thinkers");
  for (uint32_t i = 0; i < own; ++i) {
    Extension::Own& o = x.own.emplace_back();
    const size_t at = in.position();
    o.kind = in.u8();
    if (o.kind == 0) {
      for (int32_t& v : o.flicker) v = in.i32();
      check_range(in, at + 1, o.flicker[0], 0, int64_t(map.sectors.size()) - 1, "a fire flicker's sector");
      for (size_t k = 1; k < 4; ++k) check_counter(in, at + 1 + 4 * k, o.flicker[k], "a fire flicker's count or light");
    } else if (o.kind == 1) {
      o.plat = get_plat(in, map.sectors.size());
    } else if (o.kind == 2) {
      DoomCeiling& c = o.ceiling;
      c.thinking = in.u8() != 0;
      for (int32_t* v : {&c.type, &c.sector, &c.bottom_height, &c.top_height, &c.speed, &c.crush, &c.direction, &c.tag, &c.old_direction})
        *v = in.i32();
      check_range(in, at + 2, c.type, 0, int(Ceiling::Type::kSilentCrushAndRaise), "a ceiling's type");
      check_range(in, at + 6, c.sector, 0, int64_t(map.sectors.size()) - 1, "a ceiling's sector");
      check_height(in, at + 10, c.bottom_height, "a ceiling's height");
      check_height(in, at + 14, c.top_height, "a ceiling's height");
      check_counter(in, at + 26, c.direction, "a ceiling's direction");
      check_counter(in, at + 34, c.old_direction, "a ceiling's direction");
    } else {
      in.fail_at(at, "own thinker kind " + std::to_string(o.kind) + " (0 fire flicker, 1 lift, 2 crusher)");
    }
  }
  const size_t order_at = in.position();
  const uint32_t order = in.count(5, "thinkers");
  const size_t counts[3] = {doom.mobjs.size(), doom.specials.size(), x.own.size()};
  if (order != counts[0] + counts[1] + counts[2])
    in.fail_at(order_at, std::to_string(order) + " thinkers in order, " + std::to_string(counts[0] + counts[1] + counts[2]) + " saved");
  std::array<std::vector<bool>, 3> seen{std::vector<bool>(counts[0]), std::vector<bool>(counts[1]), std::vector<bool>(counts[2])};
  for (uint32_t i = 0; i < order; ++i) {
    const size_t at = in.position();
    const ThinkerLists::Entry entry{in.u8(), in.u32()};
    if (entry.source > 2 || entry.index >= counts[entry.source] || seen[entry.source][entry.index])
      in.fail_at(at, "thinker " + std::to_string(i) + " names a thinker that is not there, or twice");
    seen[entry.source][entry.index] = true;
    x.order.push_back(entry);
  }
  for (size_t i = 0; i < doom.mobjs.size(); ++i) {
    Extension::MobjExtra& m = x.live.emplace_back();
    m.target = in.i32(), m.tracer = in.i32(), m.id = in.u32(), m.placed = in.i32();
  }
  in.section("our extension's blockmap");
  if (version >= 2) {
    x.blockmap_header = std::array<int32_t, 4>{in.i32(), in.i32(), in.i32(), in.i32()};
    x.queues = Extension::Queues{};
    Extension::Queues& q = *x.queues;
    q.body_slot = in.u32();
    const size_t bodies_at = in.position();
    const uint32_t bodies = in.count(4, "corpses kept");
    if (bodies > World::kBodyQueueSize) in.fail_at(bodies_at, std::to_string(bodies) + " corpses kept, Doom's queue holds 32");
    for (uint32_t i = 0; i < bodies; ++i) q.bodies.push_back(in.i32());
    const size_t items_at = in.position();
    q.item_head = in.u32(), q.item_tail = in.u32();
    if (q.item_head >= World::kItemQueueSize || q.item_tail >= World::kItemQueueSize)
      in.fail_at(items_at, "the item queue's ends " + std::to_string(q.item_head) + " and " + std::to_string(q.item_tail) +
                               " (Doom's holds 128)");
    for (uint32_t i = q.item_tail; i != q.item_head; i = (i + 1) % World::kItemQueueSize) {
      const size_t at = in.position();
      MapThing t;
      for (int16_t* v : {&t.x, &t.y, &t.angle, &t.type, &t.options}) *v = in.i16();
      t.placed = in.i32();
      check_range(in, at + 10, t.placed, -1, int64_t(w.level_.things.size()) - 1, "an item's placed thing");
      q.items.push_back({t, in.i32()});
    }
  }
  const uint32_t cells = in.count(8, "blockmap cells");
  for (uint32_t i = 0; i < cells; ++i) {
    auto& cell = x.cells.emplace_back();
    cell.first = in.u32();
    const uint32_t n = in.count(4, "things in a cell");
    for (uint32_t k = 0; k < n; ++k) cell.second.push_back(in.i32());
  }
  in.section("our extension's movers");
  const uint32_t plats = in.count(4, "active lifts");
  for (uint32_t i = 0; i < plats; ++i) x.plats.push_back(in.i32());
  const uint32_t ceilings = in.count(4, "active crushers");
  for (uint32_t i = 0; i < ceilings; ++i) x.ceilings.push_back(in.i32());
  const uint32_t buttons = in.count(20, "switches");
  for (uint32_t i = 0; i < buttons; ++i) {
    Extension::ButtonExtra& b = x.buttons.emplace_back();
    const size_t at = in.position();
    b.line = in.i32(), b.where = in.i32(), b.texture = in.i32(), b.timer = in.i32(), b.sound_sector = in.i32();
    if (b.line == -1 && b.timer == 0) continue;  // a free slot
    check_range(in, at, b.line, 0, int64_t(map.lines.size()) - 1, "a switch's line");
    if (map.lines[size_t(b.line)].side[0] < 0) in.fail_at(at, "a switch on a line without a front side");
    check_range(in, at + 4, b.where, 0, 2, "a switch's place");
    check_counter(in, at + 12, b.timer, "a switch's timer");
    texture_index(b.texture, at + 8, false);
    check_range(in, at + 16, b.sound_sector, 0, int64_t(map.sectors.size()) - 1, "a switch's sector");
  }
  in.section("our extension's removed things");
  const uint32_t ghosts = in.count(126, "removed things");
  for (uint32_t i = 0; i < ghosts; ++i) {
    auto& g = x.ghosts.emplace_back();
    g.first = get_mobj_full(in);
    g.second.target = in.i32(), g.second.tracer = in.i32(), g.second.id = in.u32(), g.second.placed = in.i32();
  }
  if (in.remaining()) in.fail_at(in.position(), std::to_string(in.remaining()) + " bytes after our extension's last section");

  // Every reference in range, and the thing lists exactly the lists the things' places give.
  const int64_t things = int64_t(doom.mobjs.size() + x.ghosts.size());
  auto mobj_ref = [&](int32_t r, const char* what) {
    if (r < -1 || r >= things) in.fail_at(payload_at, std::string(what) + " names thing " + std::to_string(r) + " of " + std::to_string(things));
  };
  auto thinker_ref = [&](int32_t r, const char* what) {
    if (r < -1 || r >= int64_t(x.order.size()))
      in.fail_at(payload_at, std::string(what) + " names thinker " + std::to_string(r) + " of " + std::to_string(x.order.size()));
    if (r >= 0 && x.order[size_t(r)].source == 0) in.fail_at(payload_at, std::string(what) + " names a thing, not a mover");
  };
  for (int32_t r : x.brain_targets) {
    mobj_ref(r, "a boss brain spot");
    if (r < 0) in.fail_at(payload_at, "an empty boss brain spot");
  }
  for (int32_t r : x.attackers) mobj_ref(r, "a player's attacker");
  if (x.queues)
    for (int32_t r : x.queues->bodies) mobj_ref(r, "a corpse kept");
  for (const auto& s : x.sectors) mobj_ref(s.sound_target, "a sector's sound target"), thinker_ref(s.special_data, "a sector's mover");
  for (const auto& m : x.live) mobj_ref(m.target, "a thing's target"), mobj_ref(m.tracer, "a thing's tracer");
  for (const auto& g : x.ghosts) mobj_ref(g.second.target, "a removed thing's target"), mobj_ref(g.second.tracer, "a removed thing's tracer");
  for (int32_t r : x.plats) thinker_ref(r, "an active lift");
  for (int32_t r : x.ceilings) thinker_ref(r, "an active crusher");
  return x;
}

namespace {

// The kind of the thinker at order position r, as it will be made.
Thinker::Kind kind_at(const Extension& x, const DoomSave& doom, int32_t r) {
  const ThinkerLists::Entry& e = x.order[size_t(r)];
  if (e.source == 0) return Thinker::Kind::kMobj;
  if (e.source == 2) {
    const uint8_t k = x.own[e.index].kind;
    return k == 0 ? Thinker::Kind::kFireFlicker : k == 1 ? Thinker::Kind::kPlat : Thinker::Kind::kCeiling;
  }
  static constexpr Thinker::Kind kKinds[] = {Thinker::Kind::kCeiling,    Thinker::Kind::kDoor,   Thinker::Kind::kFloor, Thinker::Kind::kPlat,
                                             Thinker::Kind::kLightFlash, Thinker::Kind::kStrobe, Thinker::Kind::kGlow};
  return kKinds[doom.specials[e.index].index()];
}

}  // namespace

void apply_extension(World& w, const DoomSave& doom, const Extension& x, SaveReader& in, size_t at) {
  // The thinkers Doom's part made (things, then specials), ours, and the removed things.
  std::vector<std::unique_ptr<Thinker>> made = std::move(w.thinkers_);
  w.thinkers_.clear();
  std::vector<Mobj*> mobjs;  // by reference: the live, then the ghosts
  std::vector<std::unique_ptr<Thinker>> from_doom[2];
  for (auto& t : made) from_doom[t->kind == Thinker::Kind::kMobj ? 0 : 1].push_back(std::move(t));
  for (auto& t : from_doom[0]) mobjs.push_back(static_cast<Mobj*>(t.get()));
  std::vector<std::unique_ptr<Thinker>> own;
  for (const Extension::Own& o : x.own) {
    if (o.kind == 0) {
      auto f = std::make_unique<FireFlicker>();
      f->sector = &w.map_.sectors[size_t(o.flicker[0])];
      f->count = o.flicker[1], f->max_light = o.flicker[2], f->min_light = o.flicker[3];
      own.push_back(std::move(f));
    } else if (o.kind == 1) {
      const DoomPlat& r = o.plat;
      auto p = std::make_unique<Plat>();
      p->active = r.thinking;
      p->sector = &w.map_.sectors[size_t(r.sector)], p->speed = r.speed, p->low = r.low, p->high = r.high;
      p->wait = r.wait, p->count = r.count, p->status = Plat::Status(r.status), p->old_status = Plat::Status(r.old_status);
      p->crush = r.crush != 0, p->tag = r.tag, p->type = Plat::Type(r.type);
      own.push_back(std::move(p));
    } else {
      const DoomCeiling& r = o.ceiling;
      auto c = std::make_unique<Ceiling>();
      c->active = r.thinking;
      c->type = Ceiling::Type(r.type), c->sector = &w.map_.sectors[size_t(r.sector)], c->bottom_height = r.bottom_height;
      c->top_height = r.top_height, c->speed = r.speed, c->crush = r.crush != 0, c->direction = r.direction;
      c->tag = r.tag, c->old_direction = r.old_direction;
      own.push_back(std::move(c));
    }
  }
  for (const ThinkerLists::Entry& e : x.order)
    w.thinkers_.push_back(std::move(e.source == 0 ? from_doom[0][e.index] : e.source == 1 ? from_doom[1][e.index] : own[e.index]));
  for (const auto& [d, extra] : x.ghosts) {
    auto g = std::make_unique<Mobj>();
    fill_mobj(w, *g, d);
    g->removed = true;
    g->subsector = w.map_.point_in_subsector(g->x, g->y);
    mobjs.push_back(g.get());
    w.graveyard_.push_back(std::move(g));
  }
  auto mobj = [&](int32_t r) { return r < 0 ? nullptr : mobjs[size_t(r)]; };
  auto thinker = [&](int32_t r) { return r < 0 ? nullptr : w.thinkers_[size_t(r)].get(); };

  // The things' own fields Doom's loader reset, and their pointers.
  for (size_t i = 0; i < doom.mobjs.size(); ++i) {
    Mobj& m = *mobjs[i];
    m.floor_z = doom.mobjs[i].floor_z, m.ceiling_z = doom.mobjs[i].ceiling_z;
    m.target = mobj(x.live[i].target), m.tracer = mobj(x.live[i].tracer);
    m.id = x.live[i].id, m.spawn_point.placed = x.live[i].placed;
  }
  for (size_t g = 0; g < x.ghosts.size(); ++g) {
    Mobj& m = *mobjs[doom.mobjs.size() + g];
    m.target = mobj(x.ghosts[g].second.target), m.tracer = mobj(x.ghosts[g].second.tracer);
    m.id = x.ghosts[g].second.id, m.spawn_point.placed = x.ghosts[g].second.placed;
  }
  for (Mobj* m : mobjs)
    if (m->spawn_point.placed < -1 || m->spawn_point.placed >= int32_t(w.level_.things.size())) m->spawn_point.placed = -1;

  // The map in full.
  for (size_t i = 0; i < x.sectors.size(); ++i) {
    const Extension::SectorExtra& e = x.sectors[i];
    Sector& s = w.map_.sectors[i];
    s.floor_height = e.floor, s.ceiling_height = e.ceiling, s.floor_pic = e.floor_pic, s.ceiling_pic = e.ceiling_pic;
    s.light = e.light, s.special = e.special, s.tag = e.tag;
    s.sound_target = mobj(e.sound_target);
    s.special_data = thinker(e.special_data);
  }
  for (size_t i = 0; i < x.sides.size(); ++i) {
    Side& s = w.map_.sides[i];
    s.texture_offset = x.sides[i][0], s.row_offset = x.sides[i][1];
    s.top = x.sides[i][2], s.bottom = x.sides[i][3], s.middle = x.sides[i][4];
  }
  for (size_t i = 0; i < x.lines.size(); ++i) {
    Line& l = w.map_.lines[i];
    l.flags = x.lines[i][0], l.special = x.lines[i][1], l.tag = x.lines[i][2];
  }

  // The thing lists in their saved order: each live thing in its sector's list and its
  // cell's exactly as its place and flags say, or the save is refused.
  for (Sector& s : w.map_.sectors) s.thing_list = nullptr;
  std::fill(w.block_links_.begin(), w.block_links_.end(), nullptr);
  const size_t live = doom.mobjs.size();
  std::vector<int> in_sector(live, 0), in_cell(live, 0);
  auto link_sector = [&](Sector& s, const std::vector<int32_t>& list) {
    Mobj* prev = nullptr;
    for (int32_t r : list) {
      if (r < 0 || size_t(r) >= live) in.fail_at(at, "a sector's thing list names thing " + std::to_string(r));
      Mobj* m = mobjs[size_t(r)];
      if (++in_sector[size_t(r)] > 1 || (m->flags & kNosector) || m->subsector->sector != &s)
        in.fail_at(at, "thing " + std::to_string(r) + " is listed in sector " + std::to_string(s.index) + " where it is not");
      m->sprev = prev;
      m->snext = nullptr;
      (prev ? prev->snext : s.thing_list) = m;
      prev = m;
    }
  };
  for (size_t i = 0; i < x.sectors.size(); ++i) link_sector(w.map_.sectors[i], x.sectors[i].things);
  Blockmap& bm = w.map_.blockmap;
  // After an intercepts overrun the header is not the lump's, and the lists are as
  // vanilla left them: heads of cells computed with the old header, lists that join
  // (a thing has one successor, whatever list reaches it). They are put back as saved.
  const bool overrun = x.blockmap_header && *x.blockmap_header != std::array{bm.origin_x, bm.origin_y, bm.width, bm.height};
  if (overrun) {
    const std::array<int32_t, 4>& h = *x.blockmap_header;
    bm.origin_x = h[0], bm.origin_y = h[1], bm.width = h[2], bm.height = h[3];
  }
  for (const auto& [cell, list] : x.cells) {
    if (cell >= w.block_links_.size()) in.fail_at(at, "blockmap cell " + std::to_string(cell) + " is not in the map");
    for (int32_t r : list)
      if (r < 0 || size_t(r) >= live) in.fail_at(at, "a blockmap cell's list names thing " + std::to_string(r));
    Mobj* prev = nullptr;
    for (size_t i = 0; i < list.size(); ++i) {
      Mobj* m = mobjs[size_t(list[i])];
      const std::string where = "thing " + std::to_string(list[i]) + " is listed in blockmap cell " + std::to_string(cell);
      if (m->flags & kNoblockmap) in.fail_at(at, where + ", which it stays out of");
      if (!overrun) {
        if (++in_cell[size_t(list[i])] > 1 || w.block_cell(w.block_x(m->x), w.block_y(m->y)) != cell)
          in.fail_at(at, where + " where it is not");
        m->bprev = prev;
        m->bnext = nullptr;
        (prev ? prev->bnext : w.block_links_[cell]) = m;
        prev = m;
        continue;
      }
      Mobj* next = i + 1 < list.size() ? mobjs[size_t(list[i + 1])] : nullptr;
      if (in_cell[size_t(list[i])]++ == 0) {
        m->bnext = next;
        m->bprev = prev;
      } else if (m->bnext != next) {
        in.fail_at(at, where + ", followed there by another thing than in an earlier list");
      } else if (prev) {
        m->bprev = prev;  // a list's head may be stale; the thing before it in a list is not
      }
      if (!prev) w.block_links_[cell] = m;
      prev = m;
    }
  }
  for (size_t r = 0; r < live; ++r) {
    const Mobj& m = *mobjs[r];
    if (!(m.flags & kNosector) && !in_sector[r]) in.fail_at(at, "thing " + std::to_string(r) + " is in no sector's list");
    const bool on_map = w.block_cell(w.block_x(m.x), w.block_y(m.y)) != World::kOffTheMap;
    if (!(m.flags & kNoblockmap) && on_map && !in_cell[r] && !overrun)
      in.fail_at(at, "thing " + std::to_string(r) + " is in no blockmap cell's list");
    if (!(m.flags & kNoblockmap) && !in_cell[r]) mobjs[r]->bnext = mobjs[r]->bprev = nullptr;
  }

  // The lists of lifts and crushers, each a lift or a crusher of the save.
  w.active_plats_.clear();
  w.active_ceilings_.clear();
  std::set<int32_t> listed;
  for (int32_t r : x.plats) {
    if (r >= 0 && (kind_at(x, doom, r) != Thinker::Kind::kPlat || !listed.insert(r).second))
      in.fail_at(at, "the active lifts name thinker " + std::to_string(r) + ", not a lift (or twice)");
    w.active_plats_.push_back(static_cast<Plat*>(thinker(r)));
  }
  for (int32_t r : x.ceilings) {
    if (r >= 0 && (kind_at(x, doom, r) != Thinker::Kind::kCeiling || !listed.insert(r).second))
      in.fail_at(at, "the active crushers name thinker " + std::to_string(r) + ", not a ceiling (or twice)");
    w.active_ceilings_.push_back(static_cast<Ceiling*>(thinker(r)));
  }
  w.buttons_.clear();
  for (const Extension::ButtonExtra& b : x.buttons)
    w.buttons_.push_back(b.line < 0 ? World::Button{}
                                    : World::Button{&w.map_.lines[size_t(b.line)], b.where, b.texture, b.timer,
                                                    &w.map_.sectors[size_t(b.sound_sector)]});

  // The rest of the World.
  w.random_ = Random::at(x.play_random, x.other_random);
  w.level_time_ = x.level_time;
  w.game_tic_at_start_ = x.game_tic_at_start;
  w.on_ground_ = x.on_ground;
  w.exit_ = ExitKind(x.exit);
  w.next_id_ = x.next_id;
  w.total_kills_ = x.total_kills, w.total_items_ = x.total_items, w.total_secrets_ = x.total_secrets;
  w.brain_easy_ = x.brain_easy;
  w.brain_targets_.clear();
  for (int32_t r : x.brain_targets) w.brain_targets_.push_back(mobj(r));
  w.brain_target_on_ = x.brain_target_on;
  for (size_t p = 0; p < kMaxPlayers; ++p) {
    w.players_[p].attacker = mobj(x.attackers[p]);
    w.players_[p].message = x.messages[p];
  }
  if (x.queues) {
    w.body_queue_slot_ = x.queues->body_slot;
    w.body_queue_.clear();
    for (int32_t r : x.queues->bodies) w.body_queue_.push_back(mobj(r));
    w.item_queue_head_ = x.queues->item_head, w.item_queue_tail_ = x.queues->item_tail;
    size_t i = w.item_queue_tail_;
    for (const auto& [spot, time] : x.queues->items) {
      w.item_queue_[i] = spot, w.item_queue_time_[i] = time;
      i = (i + 1) % World::kItemQueueSize;
    }
  }
}

}  // namespace p3d::play::savegame_local
