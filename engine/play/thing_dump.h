// Every thing of the world as text, for finding where two replays of a demo part: one
// "T tic random_index" line, then a line per thing in thinker order, "M type x y z angle
// momx momy momz state tics health flags movedir movecount reactiontime threshold target
// tracer" (target and tracer as indices in this list, -1 for none), the values as Doom
// keeps them: what tools/peers/demo_batch.py asks of a traced Chocolate Doom.
#pragma once

#include <cstddef>
#include <string>

#include "engine/play/world.h"

namespace p3d::play {

std::string dump_things(const World& world, size_t tic);

}  // namespace p3d::play
