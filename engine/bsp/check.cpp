#include "engine/bsp/check.h"

#include <algorithm>
#include <cmath>

namespace p3d::bsp {

namespace {

using level::Fragment;
using level::Level;

// Exact side of fragment end k relative to line l (+1 left/back, -1 right/front, 0 on).
int end_side(const Level& level, const Fragment& f, int k, const geom::Line& l) {
  const level::Wall& w = level.walls[f.wall];
  if (f.cut[k] == level::kNone) return geom::side_of(l, k == 0 ? w.p1 : w.p2);
  return geom::side_of_crossing(l, w.line(), level.walls[f.cut[k]].line());
}

class Checker {
 public:
  Checker(const Level& level, size_t max_problems) : level_(level), max_(max_problems) {}

  std::vector<std::string> run() {
    check_coverage();
    if (level_.nodes.empty()) {  // no walls: the whole plane is one leaf
      if (!level_.walls.empty() || level_.leaves.size() != 1) problem("a tree without nodes must be one leaf and no walls");
    } else {
      check_tree();
    }
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
    const double exact = geom::crossing_param(level_.walls[f.wall].line(), level_.walls[f.cut[1]].line());
    return std::fabs(exact - f.t1) <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(exact));
  }

  void check_tree() {
    struct Constraint {
      geom::Line line;
      int side;  // -1: the subtree is in front (right), +1: behind (left)
    };
    struct Item {
      int32_t node;
      size_t depth;
      Constraint from_parent;
    };
    std::vector<Constraint> path;  // constraints of the current node's ancestors (depth-first order)
    std::vector<Item> stack{{0, 0, {}}};
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      path.resize(item.depth == 0 ? 0 : item.depth - 1);
      if (item.depth > 0) path.push_back(item.from_parent);
      const level::Node& n = level_.nodes[item.node];
      const geom::Line splitter = level_.walls[n.splitter].line();
      for (const Constraint& c : path)
        if (geom::same_line(c.line, splitter))
          problem("node " + std::to_string(item.node) + " splits along the same line as an ancestor");
      for (uint32_t i = n.first_fragment; i < n.first_fragment + n.fragment_count; ++i) {
        const Fragment& f = level_.fragments[i];
        const std::string name = "fragment " + std::to_string(i) + " of node " + std::to_string(item.node);
        if (end_side(level_, f, 0, splitter) != 0 || end_side(level_, f, 1, splitter) != 0)
          problem(name + " is off its node's splitter line");
        for (const Constraint& c : path)
          if (end_side(level_, f, 0, c.line) == -c.side || end_side(level_, f, 1, c.line) == -c.side)
            problem(name + " lies on the wrong side of an ancestor's splitter");
        if (!n.bbox.contains(f.p0, 1e-9) || !n.bbox.contains(f.p1, 1e-9))
          problem("node " + std::to_string(item.node) + "'s bounding box misses " + name);
      }
      for (int c = 0; c < 2; ++c) {
        const int32_t child = n.child[c];
        if (level::is_leaf(child)) continue;
        if (!n.bbox.contains(level_.nodes[child].bbox))
          problem("node " + std::to_string(item.node) + "'s bounding box misses its child's");
        stack.push_back({child, item.depth + 1, {splitter, c == 0 ? -1 : +1}});
      }
    }
  }

  const Level& level_;
  size_t max_;
  std::vector<std::string> problems_;
};

}  // namespace

std::vector<std::string> check_invariants(const level::Level& level, size_t max_problems) {
  return Checker(level, max_problems).run();
}

}  // namespace p3d::bsp
