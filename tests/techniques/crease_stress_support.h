// The shapes of the crease stress test (crease_stress_test.cpp): creased meshes generated
// deterministically from a seed out of the bundled OBJ assets (assets/opensubdiv,
// assets/tessbench). Each is the bundled mesh, optionally refined once or twice with
// OpenSubdiv Far (keeping the refined tags half the time), with random tags on top:
// infinitely sharp and semi-sharp crease tags (single edges and polylines), corner tags,
// holes, a boundary interpolation and sometimes Chaikin creasing. A shape is written as
// OBJ text and loaded back, so the text alone reproduces it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/technique.h"
#include "tests/test_support.h"

namespace tb::techniques::testing {

// splitmix64: the same numbers on every platform and standard library.
class StressRng {
 public:
  explicit StressRng(uint64_t seed)
      : state_(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  uint32_t below(size_t n) { return uint32_t(next() % n); }
  double unit() { return double(next() >> 11) * 0x1p-53; }
  bool chance(double p) { return unit() < p; }
  template <class T>
  const T& pick(const std::vector<T>& values) {
    return values[below(values.size())];
  }

 private:
  uint64_t state_;
};

struct StressBase {
  std::string name;  // "opensubdiv/catmark_helmet.obj"
  mesh::Mesh mesh;
};

// Every bundled OBJ of assets/opensubdiv and assets/tessbench, sorted by name.
inline std::vector<StressBase> stressBases() {
  std::vector<std::string> names;
  for (const char* folder : {"opensubdiv", "tessbench"}) {
    for (const auto& entry : std::filesystem::directory_iterator(tb::testing::assetPath(folder))) {
      if (entry.path().extension() == ".obj")
        names.push_back(std::string(folder) + "/" + entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  std::vector<StressBase> bases;
  for (const std::string& name : names)
    bases.push_back({name, mesh::loadObjFile(tb::testing::assetPath(name))});
  return bases;
}

struct StressShape {
  uint64_t seed = 0;
  std::string description;  // one line: base, refinement, tags
  std::string obj;          // OBJ text that reproduces the shape
  mesh::Mesh mesh;          // obj, loaded
};

// Faces a generated shape may reach by refinement (the bundled meshes above it stay as
// they are): keeps a shape's build and Bfr check at a few milliseconds.
inline constexpr size_t kStressMaxRefinedFaces = 400;

// Sharpness values: infinitely sharp half the time, else semi-sharp values that round
// either way (0.25, 0.75), decay in one level (0.5, 1) or take several (1.5 .. 3.3).
// A shape is "infinitely sharp only" 40 % of the time: then nothing is refined away, and
// meshes with triangles keep them (one semi-sharp tag has a small mesh refined to quads).
inline double stressSharpness(StressRng& rng, bool sharp_only) {
  static const std::vector<double> kValues = {10, 10, 10, 10, 10, 0.25, 0.5, 0.75, 1, 1.5, 2, 3.3};
  return sharp_only ? 10.0 : rng.pick(kValues);
}

inline std::string formatSharpness(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

// Crease tags: single random edges and polylines walked along the mesh's edges.
inline std::string stressCreaseTags(const mesh::Mesh& mesh, StressRng& rng, bool sharp_only,
                                    std::vector<uint32_t>& ends) {
  const mesh::Topology topology = mesh::buildTopology(mesh);
  std::vector<std::vector<uint32_t>> neighbours(mesh.positions.size());
  for (const mesh::MeshEdge& e : topology.edges) {
    neighbours[e.v0].push_back(e.v1);
    neighbours[e.v1].push_back(e.v0);
  }
  std::string tags;
  const auto tag = [&](uint32_t a, uint32_t b, double s) {
    tags += "t crease 2/1/0 " + std::to_string(a) + " " + std::to_string(b) + " " +
            formatSharpness(s) + "\n";
    ends.push_back(a);
    ends.push_back(b);
  };
  const double edge_chance = rng.pick(std::vector<double>{0, 0, 0.03, 0.1, 0.3});
  for (const mesh::MeshEdge& e : topology.edges) {
    if (rng.chance(edge_chance)) tag(e.v0, e.v1, stressSharpness(rng, sharp_only));
  }
  const uint32_t paths = rng.below(5);
  for (uint32_t p = 0; p < paths && !topology.edges.empty(); ++p) {
    const double s = stressSharpness(rng, sharp_only);
    const mesh::MeshEdge& first = topology.edges[rng.below(topology.edges.size())];
    std::vector<uint32_t> visited = {first.v0};
    uint32_t at = first.v0, to = first.v1;
    for (uint32_t step = rng.below(8) + 1; step > 0; --step) {
      tag(at, to, s);
      visited.push_back(to);
      at = to;
      const std::vector<uint32_t>& next = neighbours[at];
      std::vector<uint32_t> fresh;
      for (uint32_t w : next) {
        if (std::find(visited.begin(), visited.end(), w) == visited.end()) fresh.push_back(w);
      }
      if (fresh.empty()) break;
      to = rng.pick(fresh);
    }
  }
  return tags;
}

// Corner tags (mostly on vertices of tagged creases, where they make corners; elsewhere
// cone points, which the techniques refuse unless semi-sharp), holes, boundary rule, method.
inline std::string stressOtherTags(const mesh::Mesh& mesh, const std::vector<uint32_t>& ends,
                                   StressRng& rng, bool sharp_only, std::string& what) {
  std::string tags;
  const uint32_t corners = rng.chance(0.4) ? rng.below(3) + 1 : 0;
  for (uint32_t c = 0; c < corners; ++c) {
    const uint32_t v =
        !ends.empty() && rng.chance(0.7) ? rng.pick(ends) : rng.below(mesh.positions.size());
    tags += "t corner 1/1/0 " + std::to_string(v) + " " +
            formatSharpness(stressSharpness(rng, sharp_only)) + "\n";
  }
  const uint32_t holes = rng.chance(0.3) ? rng.below(3) + 1 : 0;
  for (uint32_t h = 0; h < holes; ++h)
    tags += "t hole 1/0/0 " + std::to_string(rng.below(mesh.faceCount())) + "\n";
  static const std::vector<int> kBoundaries = {1, 1, 2, 0};  // OBJ values
  static const char* const kBoundaryNames[] = {"none", "edge-and-corner", "edge-only"};
  const int boundary = rng.pick(kBoundaries);
  tags += "t interpolateboundary 1/0/0 " + std::to_string(boundary) + "\n";
  const bool chaikin = rng.chance(0.2);
  if (chaikin) tags += "t creasemethod 0/0/1 chaikin\n";
  what += ", " + std::to_string(corners) + " corner tags, " + std::to_string(holes) +
          " holes, boundary " + kBoundaryNames[boundary] + (chaikin ? ", chaikin" : "");
  return tags;
}

// The base mesh's own tags (refined with it) as OBJ lines, kept half the time.
inline std::string ownTags(const mesh::SubdivisionTags& tags) {
  std::string text;
  for (uint32_t f : tags.holes) text += "t hole 1/0/0 " + std::to_string(f) + "\n";
  for (const mesh::Crease& c : tags.creases) {
    text += "t crease 2/1/0 " + std::to_string(c.v0) + " " + std::to_string(c.v1) + " " +
            formatSharpness(c.sharpness) + "\n";
  }
  for (const mesh::Corner& c : tags.corners) {
    text +=
        "t corner 1/1/0 " + std::to_string(c.vertex) + " " + formatSharpness(c.sharpness) + "\n";
  }
  if (tags.smooth_triangles) text += "t smoothtriangles 0/0/1 catmark\n";
  return text;
}

inline std::string objOf(const mesh::Mesh& mesh) {
  std::string obj;
  char line[128];
  for (const mesh::Vec3d& p : mesh.positions) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    obj += line;
  }
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    obj += "f";
    for (uint32_t v : mesh.facePositions(f)) {
      obj += ' ';
      obj += std::to_string(v + 1);
    }
    obj += "\n";
  }
  return obj;
}

// Shape `seed` over `bases` (stressBases()).
inline StressShape generateStressShape(const std::vector<StressBase>& bases, uint64_t seed) {
  StressRng rng(seed);
  const StressBase& base = bases[rng.below(bases.size())];
  int levels = int(rng.below(3));
  while (levels > 0 && base.mesh.face_offsets.back() << (2 * (levels - 1)) > kStressMaxRefinedFaces)
    --levels;
  // Refined by Far (prepareCreases' uniform refinement with the full last level), which
  // carries the base's tags: creases with their refined sharpness, corners, holes.
  mesh::Mesh shaped = base.mesh;
  if (levels > 0) {
    try {
      shaped = prepareCreases(base.mesh, "stress", 0, levels).control;
    } catch (const UnsupportedInput&) {
      levels = 0;  // OpenSubdiv refuses the base (non-manifold): use it as it is
    }
  }
  const bool keep_own = rng.chance(0.5);
  const bool sharp_only = rng.chance(0.4);
  StressShape shape;
  shape.seed = seed;
  std::string what = "seed " + std::to_string(seed) + ": " + base.name + " refined " +
                     std::to_string(levels) + "x (" + std::to_string(shaped.faceCount()) +
                     " faces)" + (keep_own ? ", own tags kept" : "") +
                     (sharp_only ? ", infinitely sharp tags" : "");
  std::vector<uint32_t> ends;  // of the generated crease tags, twice per tag
  std::string tags =
      (keep_own ? ownTags(shaped.tags) : "") + stressCreaseTags(shaped, rng, sharp_only, ends);
  what += ", " + std::to_string(ends.size() / 2) + " crease tags";
  tags += stressOtherTags(shaped, ends, rng, sharp_only, what);
  shape.obj = objOf(shaped) + tags;
  shape.description = what;
  shape.mesh = mesh::loadObjText(shape.obj, "stress_" + std::to_string(seed) + ".obj");
  return shape;
}

// A shape from an OBJ file (a failing shape written out, edited by hand while hunting).
inline StressShape loadStressShape(const std::string& path, uint64_t seed) {
  StressShape shape;
  shape.seed = seed;
  shape.description = "seed " + std::to_string(seed) + ": " + path;
  std::ifstream in(path);
  shape.obj.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  shape.mesh = mesh::loadObjText(shape.obj, path);
  return shape;
}

}  // namespace tb::techniques::testing
