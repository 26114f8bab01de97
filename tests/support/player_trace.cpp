#include "tests/support/player_trace.h"

#include <fstream>
#include <sstream>

namespace p3d::test {

std::vector<PlayerTic> read_player_trace(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<PlayerTic> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    PlayerTic t;
    fields >> t.tic >> t.x >> t.y >> t.z >> t.angle >> t.momx >> t.momy >> t.health >> t.random_index >> t.view_z;
    out.push_back(t);
  }
  return out;
}

PlayerTic player_tic(const play::World& world, int64_t tic) {
  const play::Player& p = world.player();
  const play::Mobj& mo = *p.mo;
  return {tic, mo.x, mo.y, mo.z, int64_t(mo.angle), mo.mom_x, mo.mom_y, p.inv.health, world.random().play_index(), p.view_z};
}

std::string describe(const PlayerTic& t) {
  std::ostringstream o;
  o << "tic " << t.tic << ": x " << t.x << " y " << t.y << " z " << t.z << " angle " << t.angle << " mom " << t.momx << ","
    << t.momy << " health " << t.health << " random " << t.random_index << " viewz " << t.view_z;
  return o.str();
}

}  // namespace p3d::test
