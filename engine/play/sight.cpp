// Line of sight (Doom's p_sight.c): the reject table first, then the trace from eye
// to target through the map's node tree, narrowing the slopes it may pass between at
// each two-sided line with a step. Without Doom's nodes, the same slopes along the
// blockmap traversal (Doom 1.2's way).
#include "engine/play/world.h"

namespace p3d::play {

namespace {

// Doom's P_DivlineSide: 0 front, 1 back, 2 on the line. Its test of a horizontal
// line compares x with the line's y: Doom's slip, kept.
int divline_side(Fixed x, Fixed y, const World::DivLine& node) {
  if (!node.dx) {
    if (x == node.x) return 2;
    return x <= node.x ? node.dy > 0 : node.dy < 0;
  }
  if (!node.dy) {
    if (x == node.y) return 2;
    return y <= node.y ? node.dx < 0 : node.dx > 0;
  }
  const Fixed dx = wrap_sub(x, node.x), dy = wrap_sub(y, node.y);
  const Fixed left = Fixed(uint32_t(node.dy >> kFracBits) * uint32_t(dx >> kFracBits));
  const Fixed right = Fixed(uint32_t(dy >> kFracBits) * uint32_t(node.dx >> kFracBits));
  if (right < left) return 0;
  return left == right ? 2 : 1;
}

struct SightTrace {
  World::DivLine trace;
  Fixed t2x = 0, t2y = 0;
  Fixed eye_z = 0, top_slope = 0, bottom_slope = 0;
};

// Narrows the slopes at a step between front and back at fraction frac; false once closed.
bool narrow(SightTrace& s, const Sector* front, const Sector* back, Fixed open_top, Fixed open_bottom, Fixed frac) {
  if (front->floor_height != back->floor_height) {
    const Fixed slope = fixed_div(wrap_sub(open_bottom, s.eye_z), frac);
    if (slope > s.bottom_slope) s.bottom_slope = slope;
  }
  if (front->ceiling_height != back->ceiling_height) {
    const Fixed slope = fixed_div(wrap_sub(open_top, s.eye_z), frac);
    if (slope < s.top_slope) s.top_slope = slope;
  }
  return s.top_slope > s.bottom_slope;
}

bool cross_subsector(Map& map, int num, SightTrace& s, int valid_count) {
  const Subsector& sub = map.subsectors[size_t(num)];
  for (int i = 0; i < sub.line_count; ++i) {
    const Seg& seg = map.segs[size_t(sub.first_line + i)];
    Line* line = seg.line;
    int& mark = map.line_marks[size_t(line->index)];
    if (mark == valid_count) continue;
    mark = valid_count;
    const Vertex *v1 = line->v1, *v2 = line->v2;
    if (divline_side(v1->x, v1->y, s.trace) == divline_side(v2->x, v2->y, s.trace)) continue;
    const World::DivLine divl{v1->x, v1->y, wrap_sub(v2->x, v1->x), wrap_sub(v2->y, v1->y)};
    if (divline_side(s.trace.x, s.trace.y, divl) == divline_side(s.t2x, s.t2y, divl)) continue;
    // The trace crosses the line.
    if (!line->back) return false;
    if (!(line->flags & kMlTwoSided)) return false;
    const Sector *front = seg.front, *back = seg.back;
    if (!back) return false;
    if (front->floor_height == back->floor_height && front->ceiling_height == back->ceiling_height) continue;
    const Fixed open_top = std::min(front->ceiling_height, back->ceiling_height);
    const Fixed open_bottom = std::max(front->floor_height, back->floor_height);
    if (open_bottom >= open_top) return false;  // a closed door
    if (!narrow(s, front, back, open_top, open_bottom, World::intercept_vector(s.trace, divl))) return false;
  }
  return true;
}

bool cross_bsp_node(Map& map, int bsp_num, SightTrace& s, int valid_count) {
  if (bsp_num & Node::kSubsectorBit) return cross_subsector(map, bsp_num == -1 ? 0 : bsp_num & ~Node::kSubsectorBit, s, valid_count);
  const Node& bsp = map.nodes[size_t(bsp_num)];
  const World::DivLine split{bsp.x, bsp.y, bsp.dx, bsp.dy};
  int side = divline_side(s.trace.x, s.trace.y, split);
  if (side == 2) side = 0;  // on the splitter: cross both sides
  if (!cross_bsp_node(map, bsp.children[size_t(side)], s, valid_count)) return false;
  if (side == divline_side(s.t2x, s.t2y, split)) return true;  // the target is on the same side
  return cross_bsp_node(map, bsp.children[size_t(side ^ 1)], s, valid_count);
}

}  // namespace

bool World::check_sight(Mobj* t1, Mobj* t2) {
  if (map_.rejected(t1->subsector->sector->index, t2->subsector->sector->index)) return false;
  ++valid_count_;
  SightTrace s;
  s.eye_z = wrap_sub(wrap_add(t1->z, t1->height), t1->height >> 2);
  s.top_slope = wrap_sub(wrap_add(t2->z, t2->height), s.eye_z);
  s.bottom_slope = wrap_sub(t2->z, s.eye_z);
  if (!map_.has_nodes()) {
    return path_traverse(t1->x, t1->y, t2->x, t2->y, kEarlyOut | kAddLines, [&](Intercept& in) {
      const Line* li = in.line;
      // A one-sided line reaches here only at the trace's very end (the early out stops
      // at one before it), where Doom 1.2 read its missing back sector: it blocks.
      if (!li->back) return false;
      const Opening o = line_opening(*li);
      if (o.bottom >= o.top) return false;
      return narrow(s, li->front, li->back, o.top, o.bottom, in.frac);
    });
  }
  s.trace = {t1->x, t1->y, wrap_sub(t2->x, t1->x), wrap_sub(t2->y, t1->y)};
  s.t2x = t2->x;
  s.t2y = t2->y;
  return cross_bsp_node(map_, int(map_.nodes.size()) - 1, s, valid_count_);
}

}  // namespace p3d::play
