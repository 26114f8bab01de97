#include "engine/play/things.h"

#include "engine/play/info.h"
#include "engine/util/doom.h"

namespace p3d::play {

namespace {

// A level sprite frame by what a state shows: "TROOA", "*" when full bright, and
// for hanging things "@" and their drop (two hanging things may share a picture).
std::string frame_key(const std::string& name, bool bright, const std::string& drop_key) {
  return name + (bright ? "*" : "") + drop_key;
}

std::string drop_key(const level::SpriteFrame& f) {
  return f.hanging ? "@" + std::to_string(int(f.drop)) : std::string();
}

}  // namespace

std::vector<wad::FrameName> idle_frames(int editor_number) {
  std::vector<wad::FrameName> out;
  const ThingType type = thing_type_for_editor_number(editor_number);
  if (type == ThingType::kCount) return out;
  std::vector<bool> seen(size_t(StateId::kCount), false);
  for (StateId s = thing_info(type).spawn; s != StateId::kNull && !seen[size_t(s)];) {
    seen[size_t(s)] = true;
    const StateInfo& info = state_info(s);
    if (info.tics != 0) out.push_back({kSpriteNames[size_t(info.sprite)], char('A' + info.frame), info.bright});
    s = info.next;
  }
  return out;
}

ThingClocks::ThingClocks(const level::Level& level, const level::State& state, Random& random) : level_(level) {
  for (size_t i = 0; i < level.sprite_frames.size(); ++i) {
    const level::SpriteFrame& f = level.sprite_frames[i];
    frames_.emplace(frame_key(f.name, f.bright, drop_key(f)), int32_t(i));
  }
  for (size_t i = 0; i < level.things.size(); ++i) {
    const level::Thing& t = level.things[i];
    if (t.type == doom::kPlayerOneStart) {
      random.play();  // Doom spawns the player here (its first look-around target)
      continue;
    }
    if (!state.things[i]) continue;
    const ThingType type = thing_type_for_editor_number(t.type);
    if (type == ThingType::kCount || type == ThingType::kPlayer) continue;  // unknown, or another player's start
    random.play();  // P_SpawnMobj: the player the thing looks for first
    StateClock clock = spawn_clock(thing_info(type).spawn);
    if (clock.tics > 0) clock.tics = 1 + random.play() % clock.tics;
    if (t.sprite == level::kNone) continue;  // never drawn: nothing to show
    clocks_.push_back({uint32_t(i), clock, drop_key(level.sprite_frames[size_t(t.sprite)])});
  }
}

int32_t ThingClocks::frame_for(const Clock& c, int32_t fallback) const {
  const StateInfo& s = c.clock.info();
  const std::string name = std::string(kSpriteNames[size_t(s.sprite)]) + char('A' + s.frame);
  const auto it = frames_.find(frame_key(name, s.bright, c.drop_key));
  // A frame the level lacks (a PWAD's missing art), or of another sprite name than
  // the thing's first (which its reach does not cover): keep what shows.
  if (it == frames_.end() || level_.sprite_frames[size_t(it->second)].name.compare(0, 4, name, 0, 4) != 0 ||
      level_.sprite_frames[size_t(fallback)].name.compare(0, 4, name, 0, 4) != 0)
    return fallback;
  return it->second;
}

void ThingClocks::tick(level::State& state) {
  auto no_actions_yet = [](StateClock&, Action) {};
  for (Clock& c : clocks_) {
    if (!state.things[c.thing]) continue;  // picked up
    advance_state(c.clock, no_actions_yet);
  }
  show(state);
}

void ThingClocks::show(level::State& state) const {
  if (state.thing_sprites.empty()) {
    state.thing_sprites.resize(level_.things.size());
    for (size_t i = 0; i < level_.things.size(); ++i) state.thing_sprites[i] = level_.things[i].sprite;
  }
  for (const Clock& c : clocks_) {
    int32_t& shown = state.thing_sprites[c.thing];
    shown = frame_for(c, shown);
  }
}

}  // namespace p3d::play
