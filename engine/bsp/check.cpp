#include "engine/bsp/check.h"

#include <algorithm>
#include <cmath>

#include "engine/bsp/convex.h"

namespace p3d::bsp {

namespace {

using level::Fragment;
using level::Level;

// Exact side of fragment end k relative to line l (+1 left/back, -1 right/front, 0 on).
int end_side(const Level& level, const Fragment& f, int k, const geom::Line& l) {
  const level::Wall& w = level.walls[f.wall];
  if (f.cut[k] == level::kNone) return geom::side_of(l, k == 0 ? w.p1 : w.p2);
  return geom::side_of_crossing(l, w.line(), level.line(uint32_t(f.cut[k])));
}

// A leaf's fragments, facing the sides the level says, for convex_region.
struct LeafPieces {
  const Level& level;
  const level::Leaf& leaf;
  std::vector<geom::Line> lines;
  LeafPieces(const Level& l, const level::Leaf& lf) : level(l), leaf(lf) {
    for (uint32_t i = 0; i < leaf.fragment_count; ++i) lines.push_back(level.walls[at(i).wall].line());
  }
  const Fragment& at(size_t i) const { return level.fragments[leaf.first_fragment + i]; }
  size_t size() const { return leaf.fragment_count; }
  const geom::Line& line(size_t i) const { return lines[i]; }
  int side(size_t i) const { return at(i).side; }
  int end_side(size_t i, int k, const geom::Line& l) const { return bsp::end_side(level, at(i), k, l); }
};

class Checker {
 public:
  Checker(const Level& level, size_t max_problems) : level_(level), max_(max_problems) {}

  std::vector<std::string> run() {
    check_coverage();
    if (level_.leaves.size() != level_.nodes.size() + 1) {
      problem("the tree has " + std::to_string(level_.nodes.size()) + " nodes and " + std::to_string(level_.leaves.size()) +
              " leaves");
      return std::move(problems_);
    }
    check_tree();
    return std::move(problems_);
  }

 private:
  void problem(const std::string& text) {
    if (problems_.size() < max_) problems_.push_back(text);
  }

  void check_coverage() {
    std::vector<std::vector<uint32_t>> by_wall(level_.walls.size());
    for (uint32_t i = 0; i < level_.fragments.size(); ++i) by_wall[level_.fragments[i].wall].push_back(i);
    for (size_t w = 0; w < by_wall.size(); ++w) {
      auto& list = by_wall[w];
      const std::string name = "wall " + std::to_string(w);
      if (list.empty()) {
        problem(name + " has no fragments (lost)");
        continue;
      }
      std::sort(list.begin(), list.end(), [&](uint32_t a, uint32_t b) {
        return level_.fragments[a].t0 < level_.fragments[b].t0;
      });
      const Fragment& first = level_.fragments[list.front()];
      const Fragment& last = level_.fragments[list.back()];
      if (first.t0 != 0 || first.cut[0] != level::kNone) problem(name + " does not start at its first vertex");
      if (last.t1 != 1 || last.cut[1] != level::kNone) problem(name + " does not end at its second vertex");
      for (size_t i = 0; i + 1 < list.size(); ++i) {
        const Fragment& a = level_.fragments[list[i]];
        const Fragment& b = level_.fragments[list[i + 1]];
        if (a.t1 != b.t0 || a.cut[1] != b.cut[0] || a.cut[1] == level::kNone)
          problem(name + " has a gap or overlap at t=" + std::to_string(a.t1));
        else if (!split_param_ok(a))
          problem(name + " is split at t=" + std::to_string(a.t1) + ", not where its cut crosses it");
      }
    }
  }

  // The stored split parameter is the rounded crossing, nudged at most a few ulps.
  bool split_param_ok(const Fragment& f) const {
    const double exact = geom::crossing_param(level_.walls[f.wall].line(), level_.line(uint32_t(f.cut[1])));
    return std::fabs(exact - f.t1) <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(exact));
  }

  struct Constraint {
    geom::Line line;
    int side;  // -1: the subtree is in front (right), +1: behind (left)
  };

  void check_tree() {
    struct Item {
      int32_t child;
      size_t depth;
      Constraint from_parent;
    };
    std::vector<Constraint> path;  // constraints of the current item's ancestors (depth-first order)
    std::vector<Item> stack{{level_.root(), 0, {}}};
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      path.resize(item.depth == 0 ? 0 : item.depth - 1);
      if (item.depth > 0) path.push_back(item.from_parent);
      if (level::is_leaf(item.child)) {
        check_leaf(level::leaf_index(item.child), path);
        continue;
      }
      const level::Node& n = level_.nodes[item.child];
      const geom::Line splitter = level_.line(n.splitter);
      const std::string node_name = "node " + std::to_string(item.child);
      for (const Constraint& c : path)
        if (geom::same_line(c.line, splitter)) problem(node_name + " splits along the same line as an ancestor");
      for (uint32_t i = n.first_fragment; i < n.first_fragment + n.fragment_count; ++i) {
        const Fragment& f = level_.fragments[i];
        const std::string name = "fragment " + std::to_string(i) + " of " + node_name;
        if (end_side(level_, f, 0, splitter) != 0 || end_side(level_, f, 1, splitter) != 0)
          problem(name + " is off its node's splitter line");
        in_cell(f, path, name);
        if (!n.bbox.contains(f.p0, 1e-9) || !n.bbox.contains(f.p1, 1e-9)) problem(node_name + "'s bounding box misses " + name);
      }
      for (int c = 0; c < 2; ++c) {
        const int32_t child = n.child[c];
        const geom::BBox& box = level::is_leaf(child) ? level_.leaves[size_t(level::leaf_index(child))].bbox
                                                      : level_.nodes[size_t(child)].bbox;
        if (!n.bbox.contains(box)) problem(node_name + "'s bounding box misses its child's");
        stack.push_back({child, item.depth + 1, {splitter, c == 0 ? -1 : +1}});
      }
    }
  }

  // Fragment f lies in the cell `path` bounds: on its side of every ancestor's splitter,
  // each end an original one or a cut by an ancestor's line. Returns whether it lies on
  // one of those lines (the cell's edge).
  bool in_cell(const Fragment& f, const std::vector<Constraint>& path, const std::string& name) {
    bool on_edge = false;
    for (const Constraint& c : path) {
      const int s0 = end_side(level_, f, 0, c.line), s1 = end_side(level_, f, 1, c.line);
      if (s0 == -c.side || s1 == -c.side) problem(name + " lies on the wrong side of an ancestor's splitter");
      on_edge |= s0 == 0 && s1 == 0;
    }
    for (int k = 0; k < 2; ++k) {
      if (f.cut[k] == level::kNone) continue;
      const geom::Line cut = level_.line(uint32_t(f.cut[k]));
      if (std::none_of(path.begin(), path.end(), [&](const Constraint& c) { return geom::same_line(c.line, cut); }))
        problem(name + " is cut by a line that splits none of its ancestors");
    }
    return on_edge;
  }

  // The leaf's fragments lie inside its cell (not on its edges, whose fragments are its
  // ancestors'), face its sector (no barrier among them), and bound a convex region.
  void check_leaf(int32_t index, const std::vector<Constraint>& path) {
    const level::Leaf& leaf = level_.leaves[size_t(index)];
    const std::string leaf_name = "leaf " + std::to_string(index);
    for (uint32_t i = leaf.first_fragment; i < leaf.first_fragment + leaf.fragment_count; ++i) {
      const Fragment& f = level_.fragments[i];
      const level::Wall& w = level_.walls[f.wall];
      const std::string name = "fragment " + std::to_string(i) + " of " + leaf_name;
      if (in_cell(f, path, name)) problem(name + " lies on an ancestor's line, not on its node");
      if (w.segment()) continue;
      if (!w.two_sided() && f.side != 0) problem(name + " faces the back of its one-sided wall");
      const int behind = w.two_sided() ? w.sides[1].sector : level_.default_sector;
      if (behind != level::kNone && behind != w.sides[0].sector) problem(name + " separates two sectors inside its leaf");
      else if (w.sides[0].sector != leaf.sector) problem(name + " faces another sector than its leaf's");
    }
    // With the sides the level gives them (convex_region keeps a side that is given).
    if (!convex_region(LeafPieces(level_, leaf), sides_, order_).convex)
      problem(leaf_name + "'s fragments do not bound a convex region");
  }

  const Level& level_;
  size_t max_;
  std::vector<std::string> problems_;
  std::vector<int8_t> sides_;
  std::vector<uint32_t> order_;
};

}  // namespace

std::vector<std::string> check_invariants(const level::Level& level, size_t max_problems) {
  return Checker(level, max_problems).run();
}

}  // namespace p3d::bsp
