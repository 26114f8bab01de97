#include "engine/play/thing_dump.h"

#include <sstream>
#include <unordered_map>

namespace p3d::play {

std::string dump_things(const World& world, size_t tic) {
  std::ostringstream out;
  out << "T " << tic << " " << int(world.random().play_index()) << "\n";
  const std::vector<const Mobj*> things = world.things();
  std::unordered_map<const Mobj*, int> index;
  for (size_t i = 0; i < things.size(); ++i) index.emplace(things[i], int(i));
  auto index_of = [&](const Mobj* m) {
    const auto it = index.find(m);
    return it == index.end() ? -1 : it->second;
  };
  for (const Mobj* m : things)
    out << "M " << int(m->type) << " " << m->x << " " << m->y << " " << m->z << " " << m->angle << " " << m->mom_x
        << " " << m->mom_y << " " << m->mom_z << " " << int(m->state) << " " << m->tics << " " << m->health << " "
        << m->flags << " " << m->move_dir << " " << m->move_count << " " << m->reaction_time << " " << m->threshold
        << " " << index_of(m->target) << " " << index_of(m->tracer) << "\n";
  return out.str();
}

}  // namespace p3d::play
