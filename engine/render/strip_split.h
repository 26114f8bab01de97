// Where a frame's column strips split (bsp_front_to_back draws one strip per thread):
// evenly at first, then frame by frame toward equal times, judged by how long each
// strip took in the last frame. The picture and its statistics are the same for any
// split, so a measured time decides only which thread draws which columns.
#pragma once

#include <span>
#include <vector>

namespace p3d::render {

// The edges of `count` strips over `width` columns: edges[i] to edges[i + 1] is strip
// i. Every edge but the last is a multiple of `align`, and every strip but the last at
// least `align` wide (count <= width / align, or 1).
std::vector<int> even_edges(int width, int count, int align);

// Moves the inner edges halfway toward those that would have given each strip the same
// time, a column's cost taken as the mean of its strip's: seconds[i] is what strip i
// took. Halfway: one slow frame (a thread swapped out) moves an edge only so far.
void balance_edges(std::vector<int>& edges, std::span<const double> seconds, int align);

}  // namespace p3d::render
