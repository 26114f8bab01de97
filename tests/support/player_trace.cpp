#include "tests/support/player_trace.h"

#include <fstream>
#include <sstream>

#include "engine/util/bytes.h"

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

NetTrace read_net_trace(const std::filesystem::path& path) {
  std::ifstream in(path);
  NetTrace out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] == '#') continue;
    std::istringstream fields(line.substr(2));
    size_t tic = 0;
    fields >> tic;
    if (line[0] == 'H') {
      std::string hex;
      fields >> hex;
      out.hashes.resize(tic + 1);
      out.hashes[tic] = std::stoull(hex, nullptr, 16);
    } else if (line[0] == 'F') {
      out.full[tic].push_back(line.substr(2));
    }
  }
  return out;
}

std::vector<std::string> net_lines(const play::World& w, size_t tic) {
  std::vector<std::string> out;
  for (int n = 0; n < play::kMaxPlayers; ++n) {
    const play::Player& p = w.player(n);
    if (!w.in_game(n) || !p.mo) continue;
    std::ostringstream o;
    o << tic << " " << n << " " << p.mo->x << " " << p.mo->y << " " << p.mo->z << " " << uint32_t(p.mo->angle) << " "
      << p.mo->mom_x << " " << p.mo->mom_y << " " << p.inv.health << " " << p.inv.armor;
    for (int f : p.frags) o << " " << f;
    o << " " << int(w.random().play_index()) << " " << p.view_z;
    out.push_back(o.str());
  }
  return out;
}

uint64_t net_hash(const std::vector<std::string>& lines) {
  std::string text;
  for (size_t i = 0; i < lines.size(); ++i) text += (i ? "\n" : "") + lines[i];
  return fnv1a64({reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

}  // namespace p3d::test
