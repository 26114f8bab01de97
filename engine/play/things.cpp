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

// What an action spawns (Doom's P_SpawnMobj, P_SpawnMissile, P_SpawnPuff and
// P_SpawnBlood in it): add(type) for each type, enter(state) for a state it puts
// one in beyond that type's own (the brain's explosions are rockets in
// S_BRAINEXPLODE1).
template <typename Add, typename Enter>
void spawned_by(Action action, Add&& add, Enter&& enter) {
  using T = ThingType;
  switch (action) {
    case Action::kTroopAttack: return add(T::kTroopshot);
    case Action::kHeadAttack: return add(T::kHeadshot);
    case Action::kBruisAttack: return add(T::kBruisershot);
    case Action::kSkelMissile: return add(T::kTracer);
    case Action::kTracer: return add(T::kSmoke), add(T::kPuff);
    case Action::kFatAttack1:
    case Action::kFatAttack2:
    case Action::kFatAttack3: return add(T::kFatshot);
    case Action::kBspiAttack: return add(T::kArachplaz);
    case Action::kCyberAttack:
    case Action::kFireMissile: return add(T::kRocket);
    case Action::kFirePlasma: return add(T::kPlasma);
    case Action::kFireBFG: return add(T::kBfg);
    case Action::kBFGSpray: return add(T::kExtrabfg);
    case Action::kPainAttack:
    case Action::kPainDie: return add(T::kSkull);
    case Action::kVileTarget: return add(T::kFire);
    case Action::kBrainSpit: return add(T::kSpawnshot);
    case Action::kSpawnFly:  // the fog, and whichever monster A_SpawnFly's roll picks
      for (T t : {T::kSpawnfire, T::kTroop, T::kSergeant, T::kShadows, T::kPain, T::kHead, T::kVile, T::kUndead,
                  T::kBaby, T::kFatso, T::kKnight, T::kBruiser})
        add(t);
      return;
    case Action::kBrainScream:
    case Action::kBrainExplode: return add(T::kRocket), enter(StateId::kBrainexplode1);
    case Action::kPosAttack:  // hitscans: a puff where they hit a wall, blood where they hit a thing
    case Action::kSPosAttack:
    case Action::kCPosAttack:
    case Action::kPunch:
    case Action::kSaw:
    case Action::kFirePistol:
    case Action::kFireShotgun:
    case Action::kFireShotgun2:
    case Action::kFireCGun: return add(T::kPuff), add(T::kBlood);
    default: return;
  }
}

// The frames of `roots` and of everything they may spawn (reachable_frames).
std::vector<wad::FrameName> frames_from(std::initializer_list<ThingType> roots) {
  std::vector<bool> type_seen(size_t(ThingType::kCount), false), state_seen(size_t(StateId::kCount), false);
  std::vector<ThingType> types;
  std::vector<StateId> states;
  auto add = [&](ThingType t) {
    if (!type_seen[size_t(t)]) type_seen[size_t(t)] = true, types.push_back(t);
  };
  auto enter = [&](StateId s) {
    if (s != StateId::kNull && !state_seen[size_t(s)]) state_seen[size_t(s)] = true, states.push_back(s);
  };
  for (ThingType t : roots) add(t);
  std::vector<wad::FrameName> out;
  std::vector<bool> frame_seen;  // by (sprite, frame, bright)
  size_t next_type = 0, next_state = 0;
  while (next_type < types.size() || next_state < states.size()) {
    if (next_state < states.size()) {  // a type's states all come before the types they spawn
      const StateInfo& s = state_info(states[next_state++]);
      const size_t key = (size_t(s.sprite) * 32 + s.frame) * 2 + s.bright;
      if (frame_seen.size() <= key) frame_seen.resize(key + 1, false);
      if (!frame_seen[key]) frame_seen[key] = true, out.push_back({kSpriteNames[size_t(s.sprite)], char('A' + s.frame), s.bright});
      enter(s.next);
      spawned_by(s.action, add, enter);
      continue;
    }
    const ThingType type = types[next_type++];
    const ThingInfo& info = thing_info(type);
    for (StateId s : {info.spawn, info.see, info.pain, info.melee, info.missile, info.death, info.extreme_death, info.raise})
      enter(s);
    if ((info.flags & kShootable) && !(info.flags & kNoblood)) add(ThingType::kBlood);
    switch (type) {  // what Doom's A_Fall... P_KillMobj drops
      case ThingType::kPossessed:
      case ThingType::kWolfss: add(ThingType::kClip); break;
      case ThingType::kShotguy: add(ThingType::kShotgun); break;
      case ThingType::kChainguy: add(ThingType::kChaingun); break;
      default: break;
    }
  }
  return out;
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

std::vector<wad::FrameName> reachable_frames(int editor_number) {
  const ThingType type = thing_type_for_editor_number(editor_number);
  if (type == ThingType::kCount) return {};
  return frames_from({type});
}

std::vector<wad::FrameName> always_frames() {
  using T = ThingType;
  return frames_from({T::kPlayer, T::kPuff, T::kBlood, T::kTfog, T::kIfog, T::kRocket, T::kPlasma, T::kBfg, T::kExtrabfg});
}

ThingClocks::ThingClocks(const level::Level& level, level::State& state, Random& random) : level_(level) {
  for (size_t i = 0; i < level.sprite_frames.size(); ++i) {
    const level::SpriteFrame& f = level.sprite_frames[i];
    frames_.emplace(frame_key(f.name, f.bright, drop_key(f)), int32_t(i));
  }
  find_entries(state);
  for (size_t i = 0; i < level.things.size(); ++i) {
    const level::Thing& t = level.things[i];
    if (t.type == doom::kPlayerOneStart) {
      random.play();  // Doom spawns the player here (its first look-around target)
      continue;
    }
    if (entry_[i] == level::kNone) continue;
    const ThingType type = thing_type_for_editor_number(t.type);
    if (type == ThingType::kCount || type == ThingType::kPlayer) continue;  // unknown, or another player's start
    random.play();  // P_SpawnMobj: the player the thing looks for first
    StateClock clock = spawn_clock(thing_info(type).spawn);
    if (clock.tics > 0) clock.tics = 1 + random.play() % clock.tics;
    if (thing_info(type).flags & kShadow) state.things[size_t(entry_[i])].flags |= level::kShownShadow;
    if (t.sprite == level::kNone) continue;  // never drawn: nothing to show
    clocks_.push_back({uint32_t(i), clock, drop_key(level.sprite_frames[size_t(t.sprite)])});
  }
}

int32_t ThingClocks::frame_for(const Clock& c, int32_t fallback) const {
  const StateInfo& s = c.clock.info();
  const std::string name = std::string(kSpriteNames[size_t(s.sprite)]) + char('A' + s.frame);
  const auto it = frames_.find(frame_key(name, s.bright, c.drop_key));
  return it == frames_.end() ? fallback : it->second;  // a frame the level lacks (a PWAD's missing art): keep what shows
}

void ThingClocks::find_entries(const level::State& state) {
  entry_.assign(level_.things.size(), level::kNone);
  for (size_t k = 0; k < state.things.size(); ++k) {
    const int32_t placed = state.things[k].placed;
    if (placed >= 0 && size_t(placed) < entry_.size()) entry_[size_t(placed)] = int32_t(k);
  }
}

void ThingClocks::tick(level::State& state) {
  auto no_actions_yet = [](StateClock&, Action) {};
  find_entries(state);
  for (Clock& c : clocks_) {
    if (entry_[c.thing] == level::kNone) continue;  // picked up
    advance_state(c.clock, no_actions_yet);
  }
  show(state);
}

void ThingClocks::show(level::State& state) {
  find_entries(state);
  for (const Clock& c : clocks_) {
    if (entry_[c.thing] == level::kNone) continue;
    int32_t& shown = state.things[size_t(entry_[c.thing])].frame;
    shown = frame_for(c, shown);
  }
}

}  // namespace p3d::play
