#include "techniques/mass_spring/spring_system.h"

#include <algorithm>
#include <stdexcept>

namespace tb::mass_spring {

void buildSolverTables(SpringSystem& system) {
  const size_t n = system.vertex_count;
  // Colours used at each vertex, as a growing bit list (valences stay small).
  std::vector<std::vector<bool>> used(n);
  auto isFree = [&](uint32_t v, uint32_t c) { return c >= used[v].size() || !used[v][c]; };
  auto take = [&](uint32_t v, uint32_t c) {
    if (used[v].size() <= c) used[v].resize(c + 1, false);
    used[v][c] = true;
  };
  system.colour_of.assign(system.springs.size(), 0);
  system.colour_count = 0;
  // Welsh-Powell order: springs at the busiest vertices first (the degree of a spring is
  // the larger spring count of its vertices), ties in spring order.
  std::vector<uint32_t> degree(n, 0);
  for (const Spring& spring : system.springs) {
    if (spring.a < n) ++degree[spring.a];
    if (!spring.anchored() && spring.b < n) ++degree[spring.b];
  }
  auto springDegree = [&](const Spring& spring) {
    const uint32_t a = spring.a < n ? degree[spring.a] : 0;
    const uint32_t b = !spring.anchored() && spring.b < n ? degree[spring.b] : 0;
    return std::max(a, b);
  };
  std::vector<uint32_t> visit(system.springs.size());
  for (uint32_t s = 0; s < visit.size(); ++s) visit[s] = s;
  std::stable_sort(visit.begin(), visit.end(), [&](uint32_t x, uint32_t y) {
    return springDegree(system.springs[x]) > springDegree(system.springs[y]);
  });
  for (const uint32_t s : visit) {
    const Spring& spring = system.springs[s];
    if (spring.a >= n || (!spring.anchored() && spring.b >= n)) {
      throw std::logic_error("mass_spring: spring " + std::to_string(s) + " ends out of range");
    }
    uint32_t c = 0;
    while (!isFree(spring.a, c) || (!spring.anchored() && !isFree(spring.b, c))) ++c;
    take(spring.a, c);
    if (!spring.anchored()) take(spring.b, c);
    system.colour_of[s] = c;
    system.colour_count = std::max(system.colour_count, c + 1);
  }
  system.colour_start.assign(system.colour_count + 1, 0);
  for (uint32_t c : system.colour_of) ++system.colour_start[c + 1];
  for (uint32_t c = 0; c < system.colour_count; ++c) {
    system.colour_start[c + 1] += system.colour_start[c];
  }
  system.colour_order.assign(system.springs.size(), 0);
  std::vector<uint32_t> cursor(system.colour_start.begin(), system.colour_start.end() - 1);
  for (size_t s = 0; s < system.springs.size(); ++s) {
    system.colour_order[cursor[system.colour_of[s]]++] = uint32_t(s);
  }

  system.end_start.assign(n + 1, 0);
  for (const Spring& spring : system.springs) {
    ++system.end_start[spring.a + 1];
    if (!spring.anchored()) ++system.end_start[spring.b + 1];
  }
  for (size_t v = 0; v < n; ++v) system.end_start[v + 1] += system.end_start[v];
  system.ends.assign(system.end_start[n], {});
  std::vector<uint32_t> fill(system.end_start.begin(), system.end_start.end() - 1);
  for (const Spring& spring : system.springs) {
    system.ends[fill[spring.a]++] = {spring.b, spring.rest_m, spring.weight};
    if (!spring.anchored())
      system.ends[fill[spring.b]++] = {spring.a, spring.rest_m, spring.weight};
  }
}

uint32_t colourCountOf(const SpringSystem& system, std::initializer_list<SpringKind> kinds) {
  SpringSystem subset;
  subset.vertex_count = system.vertex_count;
  subset.anchor_count = system.anchor_count;
  for (const Spring& spring : system.springs) {
    if (std::find(kinds.begin(), kinds.end(), spring.kind) != kinds.end()) {
      subset.springs.push_back(spring);
    }
  }
  buildSolverTables(subset);
  return subset.colour_count;
}

ColourConflict findColourConflict(const SpringSystem& system) {
  // Per colour, the spring that last claimed each vertex.
  std::vector<long long> owner(system.vertex_count, -1);
  for (uint32_t c = 0; c + 1 < system.colour_start.size(); ++c) {
    std::vector<uint32_t> touched;
    for (uint32_t i = system.colour_start[c]; i < system.colour_start[c + 1]; ++i) {
      const uint32_t s = system.colour_order[i];
      const Spring& spring = system.springs[s];
      for (uint32_t v : {spring.a, spring.anchored() ? kAnchorBit : spring.b}) {
        if (v == kAnchorBit) continue;
        if (owner[v] >= 0) return {owner[v], s};
        owner[v] = s;
        touched.push_back(v);
      }
    }
    for (uint32_t v : touched) owner[v] = -1;
  }
  return {};
}

}  // namespace tb::mass_spring
