#include "engine/render/strip_split.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace p3d::render {

namespace {

// Edge k of `count` on a multiple of `align`, leaving every strip at least `align` wide.
int aligned_edge(double x, size_t k, size_t count, int previous, int width, int align) {
  const int edge = int(std::lround(x / align)) * align;
  return std::clamp(edge, previous + align, width - int(count - k) * align);
}

}  // namespace

std::vector<int> even_edges(int width, int count, int align) {
  const size_t n = size_t(std::max(1, std::min(count, width / align)));
  std::vector<int> edges(n + 1, 0);
  for (size_t k = 1; k < n; ++k)
    edges[k] = aligned_edge(double(width) * double(k) / double(n), k, n, edges[k - 1], width, align);
  edges[n] = width;
  return edges;
}

void balance_edges(std::vector<int>& edges, std::span<const double> seconds, int align) {
  const size_t n = seconds.size();
  const double total = std::accumulate(seconds.begin(), seconds.end(), 0.0);
  if (n < 2 || edges.size() != n + 1 || !(total > 0) || !std::isfinite(total)) return;
  const std::vector<int> old = edges;
  const int width = old[n];
  size_t strip = 0;      // the old strip where the k-th share of the time ends
  double before = 0;     // the time of the old strips left of it
  for (size_t k = 1; k < n; ++k) {
    const double share = total * double(k) / double(n);
    while (strip + 1 < n && before + seconds[strip] < share) before += seconds[strip++];
    const double within = seconds[strip] > 0 ? (share - before) / seconds[strip] : 0.5;
    const double equal = old[strip] + std::clamp(within, 0.0, 1.0) * (old[strip + 1] - old[strip]);
    edges[k] = aligned_edge((old[k] + equal) / 2, k, n, edges[k - 1], width, align);
  }
}

}  // namespace p3d::render
