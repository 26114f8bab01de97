// BSP invariants, checked exactly on a compiled level: the oracle for the
// compiler's tests (and `mapc --check`).
#pragma once

#include <string>
#include <vector>

#include "engine/level/level.h"

namespace p3d::bsp {

// Returns one line per violated invariant (empty when the tree is sound):
//  - every wall is exactly covered by its fragments (ranges tile [0, 1], ends match their cuts);
//  - every node's fragments lie on its splitter line, and no line splits twice on a
//    root-to-leaf path (so collinear fragments all sit on the node of their line);
//  - every leaf's fragments cover its cell's walls exactly: each lies inside the cell (on
//    its side of every ancestor's splitter, exact predicates, and on none of their
//    lines) and ends where its wall does or where an ancestor's line cuts it;
//  - every leaf's fragments bound a convex region (convex.h), facing the sides they say,
//    and face the leaf's sector (no two-sided wall between two sectors among them);
//  - every node's bounding box contains its fragments and its children's boxes.
std::vector<std::string> check_invariants(const level::Level& level, size_t max_problems = 20);

}  // namespace p3d::bsp
