// BSP invariants, checked exactly on a compiled level: the oracle for the
// compiler's tests (and `mapc --check`).
#pragma once

#include <string>
#include <vector>

#include "engine/level/level.h"

namespace p3d::bsp {

// Returns one line per violated invariant (empty when the tree is sound):
//  - every wall is exactly covered by its fragments (ranges tile [0, 1], ends match their cuts);
//  - every fragment lies on its node's splitter line, and no line splits twice on a
//    root-to-leaf path (so collinear fragments all sit on the node of their line);
//  - every fragment lies on its side of every ancestor's splitter (exact predicates);
//  - every node's bounding box contains its subtree's fragments.
std::vector<std::string> check_invariants(const level::Level& level, size_t max_problems = 20);

}  // namespace p3d::bsp
