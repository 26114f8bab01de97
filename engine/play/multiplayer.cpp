// Players in a netgame (Doom's g_game.c and p_mobj.c): where a player may spawn
// (G_CheckSpot), the random deathmatch start (G_DeathMatchSpawnPlayer), coming back
// after death without the level starting again (G_DoReborn), and altdeath's items
// coming back 30 seconds after they were taken (P_RespawnSpecials).
#include "engine/play/world.h"

#include "engine/util/error.h"

namespace p3d::play {

namespace {
constexpr int kMinDeathmatchStarts = 4;  // Doom refuses a deathmatch on a map with fewer
constexpr int kSpotTries = 20;           // random spots tried before the player's own start
constexpr int kItemRespawnTics = 30 * 35;

// The unit vector G_CheckSpot puts the teleport fog along, 20 units from the spot, as
// the DOS Doom read it: its fine angle was a signed int, so the starts facing 180 to
// 315 degrees index before the sine table, into the tangent table (Chocolate Doom
// emulates it, after PrBoom+). A start at another angle gets no offset.
std::pair<Fixed, Fixed> fog_direction(int16_t angle) {
  const int an = (int(kAngle45 >> kAngleToFineShift)) * (angle / 45);
  switch (an) {
    case 4096: return {kFineTangent[2048], kFineTangent[0]};
    case 5120: return {kFineTangent[3072], kFineTangent[1024]};
    case 6144: return {kFineSine[0], kFineTangent[2048]};
    case 7168: return {kFineSine[1024], kFineTangent[3072]};
    case 0: case 1024: case 2048: case 3072: return {fine_cosine(an), fine_sine(an)};
    case 8192: return {Fixed(kTanToAngle[0]), kFineSine[8192]};
    default: return {0, 0};  // Chocolate Doom stops with an error here
  }
}
}  // namespace

bool World::check_spot(int n, const MapThing& spot) {
  Player& player = players_[size_t(n)];
  const Fixed x = Fixed(spot.x) << kFracBits, y = Fixed(spot.y) << kFracBits;
  if (!player.mo) {  // the level's first spawn: only players spawned before stand in the way
    for (int i = 0; i < n; ++i) {
      const Mobj* other = players_[size_t(i)].mo;
      if (in_game(i) && other && other->x == x && other->y == y) return false;
    }
    return true;
  }
  if (!check_position(player.mo, x, y)) return false;  // the corpse, tried at the spot
  // The corpse stays, up to Doom's 32: the oldest then goes.
  if (body_queue_.size() < kBodyQueueSize) body_queue_.resize(kBodyQueueSize, nullptr);
  Mobj*& slot = body_queue_[body_queue_slot_ % kBodyQueueSize];
  if (body_queue_slot_ >= kBodyQueueSize && slot && !slot->removed) remove_mobj(slot);
  slot = player.mo;
  ++body_queue_slot_;
  const auto [dx, dy] = fog_direction(spot.angle);
  const Fixed floor = map_.point_in_subsector(x, y)->sector->floor_height;
  // Doom's 20 * a tangent overflows its int: wrapped, as it did.
  Mobj* fog = spawn_mobj(wrap_add(x, Fixed(20u * uint32_t(dx))), wrap_add(y, Fixed(20u * uint32_t(dy))), floor,
                         ThingType::kTfog);
  if (World::player().view_z != 1) start_sound(fog, Sound::kTelept);  // not on the level's first frame
  return true;
}

void World::deathmatch_spawn_player(int n) {
  const int selections = int(deathmatch_starts_.size());
  if (selections < kMinDeathmatchStarts)
    throw Error("only " + std::to_string(selections) + " deathmatch starts on the map, " +
                std::to_string(kMinDeathmatchStarts) + " required");
  for (int j = 0; j < kSpotTries; ++j) {
    MapThing& spot = deathmatch_starts_[size_t(random_.play() % selections)];
    if (check_spot(n, spot)) {
      spot.type = int16_t(n + 1);
      spawn_player(spot);
      return;
    }
  }
  spawn_player(player_starts_[size_t(n)]);  // no room anywhere: the player's own start
}

void World::reborn_in_netgame(int n) {
  Player& player = players_[size_t(n)];
  player.mo->player = nullptr;  // the corpse is a thing like any other now
  if (options_.deathmatch != Deathmatch::kNone) {
    deathmatch_spawn_player(n);
    return;
  }
  if (check_spot(n, player_starts_[size_t(n)])) {
    spawn_player(player_starts_[size_t(n)]);
    return;
  }
  for (int i = 0; i < kMaxPlayers; ++i) {  // another player's start, as that player
    MapThing& start = player_starts_[size_t(i)];
    if (check_spot(n, start)) {
      start.type = int16_t(n + 1);
      spawn_player(start);
      start.type = int16_t(i + 1);
      return;
    }
  }
  spawn_player(player_starts_[size_t(n)]);  // inside something: too bad, as Doom says
}

void World::respawn_specials() {
  if (options_.deathmatch != Deathmatch::kAltdeath) return;
  if (item_queue_head_ == item_queue_tail_) return;
  if (level_time_ - item_queue_time_[item_queue_tail_] < kItemRespawnTics) return;
  const MapThing mt = item_queue_[item_queue_tail_];
  item_queue_tail_ = (item_queue_tail_ + 1) % kItemQueueSize;
  const Fixed x = Fixed(mt.x) << kFracBits, y = Fixed(mt.y) << kFracBits;
  Mobj* fog = spawn_mobj(x, y, map_.point_in_subsector(x, y)->sector->floor_height, ThingType::kIfog);
  start_sound(fog, Sound::kItmbk);
  const ThingType type = thing_type_for_editor_number(mt.type);
  if (type == ThingType::kCount) return;  // Chocolate Doom stops with an error
  const Fixed z = (info_of(type).flags & kSpawnceiling) ? kOnCeilingZ : kOnFloorZ;
  Mobj* mo = spawn_mobj(x, y, z, type);
  mo->spawn_point = mt;
  mo->angle = kAngle45 * Angle(mt.angle / 45);
}

}  // namespace p3d::play
