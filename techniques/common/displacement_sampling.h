// How a displaced surface reads its map (docs/derivations/displacement.md): the
// texel lookup in a per-patch tile, the owner rule of watertight sampling (seed 000) and the
// displacement direction, templated on the scalar so one code path is the double evaluation
// and the float twin of shaders/common/displace.glsl (same operations, same order).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "core/displacement/displacement_map.h"
#include "core/mesh/vec.h"
#include "techniques/batch_eval.h"

namespace tb::techniques {

enum class DisplacementSampling {
  kNaive,       // bilinear at the patch's own (u, v) in its own tile
  kWatertight,  // shared corners and edges read their owner's tile at the owner's (u, v)
};
const char* samplingName(DisplacementSampling sampling);  // "naive", "watertight"

// Who owns the shared boundary of one patch: the patch with the lowest index among those
// that share a corner (same control-mesh position) or an edge (same two positions). A
// patch owns what no lower patch shares, including boundary edges of an open mesh.
struct BoundaryOwners {
  struct Corner {
    uint32_t patch = 0;   // the owner (a SurfacePatches patch, which is also its tile)
    uint32_t corner = 0;  // the owner's local corner at the same position
  };
  struct Edge {
    uint32_t patch = 0;     // the owner
    uint32_t edge = 0;      // the owner's local edge (corner edge to corner edge + 1)
    bool reversed = false;  // the owner runs the edge the other way: t_owner = 1 - t
  };
  std::array<Corner, 4> corners{};  // 3 used by a triangle patch
  std::array<Edge, 4> edges{};
};

// The tile constants the lookup needs, from the map's DisplacementTiles.
struct TileGeometry {
  uint32_t resolution = 0;  // interior texels per side (tile_size - 2 border)
  uint32_t border = 0;
  uint32_t tile_size = 0;
  uint32_t tiles_per_row = 0;
};
TileGeometry tileGeometryOf(const displacement::DisplacementMap& map);

// A point of one patch's domain in the tile's (u, v): quads (u, v) = gl_TessCoord.xy, the
// baker's convention; triangles (u, v) = the weights of corners 0 and 1.
template <class T>
struct TileCoord {
  uint32_t tile = 0;
  T u{}, v{};
};

// The local corner of `coord` (quads: (0,0), (1,0), (1,1), (0,1); triangles: weight 1), or -1.
template <class T>
int domainCorner(PatchDomain domain, const std::array<T, 3>& c) {
  if (domain == PatchDomain::kTriangle) {
    for (int k = 0; k < 3; ++k) {
      if (c[k] == T(1)) return k;
    }
    return -1;
  }
  if ((c[0] == T(0) || c[0] == T(1)) && (c[1] == T(0) || c[1] == T(1))) {
    if (c[1] == T(0)) return c[0] == T(0) ? 0 : 1;
    return c[0] == T(1) ? 2 : 3;
  }
  return -1;
}

// The local edge `coord` lies on strictly between corners (-1 inside), and its parameter t
// from corner e (t = 0) to corner e + 1 (t = 1); exact for tessellator coordinates.
template <class T>
int domainEdge(PatchDomain domain, const std::array<T, 3>& c, T* t) {
  if (domain == PatchDomain::kTriangle) {
    for (int e = 0; e < 3; ++e) {
      if (c[(e + 2) % 3] == T(0)) {
        *t = c[(e + 1) % 3];
        return e;
      }
    }
    return -1;
  }
  if (c[1] == T(0)) return *t = c[0], 0;
  if (c[0] == T(1)) return *t = c[1], 1;
  if (c[1] == T(1)) return *t = T(1) - c[0], 2;
  if (c[0] == T(0)) return *t = T(1) - c[1], 3;
  return -1;
}

// The tile (u, v) of local corner `corner` of a patch of `domain`.
template <class T>
void cornerUv(PatchDomain domain, uint32_t corner, T* u, T* v) {
  static constexpr int kQuad[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  static constexpr int kTriangle[3][2] = {{1, 0}, {0, 1}, {0, 0}};
  const int* uv = domain == PatchDomain::kQuad ? kQuad[corner] : kTriangle[corner];
  *u = T(uv[0]);
  *v = T(uv[1]);
}

// The tile (u, v) at parameter t of local edge `edge`; exact (t and 1 - t are multiples of
// 2^-16 for tessellator points).
template <class T>
void edgeUv(PatchDomain domain, uint32_t edge, T t, T* u, T* v) {
  if (domain == PatchDomain::kQuad) {
    switch (edge) {
      case 0:
        *u = t, *v = T(0);
        return;
      case 1:
        *u = T(1), *v = t;
        return;
      case 2:
        *u = T(1) - t, *v = T(1);
        return;
      default:
        *u = T(0), *v = T(1) - t;
        return;
    }
  }
  std::array<T, 3> w{T(0), T(0), T(0)};
  w[edge] = T(1) - t;
  w[(edge + 1) % 3] = t;
  *u = w[0];
  *v = w[1];
}

// Continuous texel coordinates of (u, v) in a tile, the baker's texel centres
// (harness/bake/baker.h texelParameter: the first and last interior texels on the edges):
// x = u (r - 1) + border, y = (tile_size - 1 - border) - v (r - 1), then bilinear between the
// four texels around (x, y) (clamped to the tile). Returns channel values in out[0..channels).
template <class T>
void sampleTile(const displacement::DisplacementMap& map, const TileGeometry& g, uint32_t tile, T u,
                T v, uint32_t channels, T* out) {
  const T step = T(g.resolution) - T(1);
  const T left = T(g.border);
  const T top = (T(g.tile_size) - T(1)) - T(g.border);
  const T x = u * step + left;
  const T y = top - v * step;
  using std::floor;
  const T last = T(g.tile_size) - T(2);
  T x0 = floor(x), y0 = floor(y);
  x0 = x0 < T(0) ? T(0) : (x0 > last ? last : x0);
  y0 = y0 < T(0) ? T(0) : (y0 > last ? last : y0);
  const T fx = x - x0, fy = y - y0;
  const T gx = T(1) - fx, gy = T(1) - fy;
  const uint32_t tx = (tile % g.tiles_per_row) * g.tile_size + uint32_t(x0);
  const uint32_t ty = (tile / g.tiles_per_row) * g.tile_size + uint32_t(y0);
  for (uint32_t c = 0; c < channels; ++c) {
    const T a = T(map.at(tx, ty, c)), b = T(map.at(tx + 1, ty, c));
    const T d = T(map.at(tx, ty + 1, c)), e = T(map.at(tx + 1, ty + 1, c));
    const T upper = a * gx + b * fx;
    const T lower = d * gx + e * fx;
    out[c] = upper * gy + lower * fy;
  }
}

// Where patch `patch` (of `domain`, owning `owners`) reads the map at `coord`: its own tile at
// its own (u, v), or, with watertight sampling on a shared corner or edge, the owner's tile at
// the owner's (u, v). `domain_of(q)` gives patch q's domain.
template <class T, class DomainOf>
TileCoord<T> lookupCoord(uint32_t patch, PatchDomain domain, const BoundaryOwners& owners,
                         DisplacementSampling sampling, const std::array<T, 3>& coord,
                         DomainOf domain_of) {
  TileCoord<T> at{patch, coord[0], coord[1]};
  if (sampling == DisplacementSampling::kNaive) return at;
  if (const int k = domainCorner(domain, coord); k >= 0) {
    const BoundaryOwners::Corner& owner = owners.corners[k];
    at.tile = owner.patch;
    cornerUv(domain_of(owner.patch), owner.corner, &at.u, &at.v);
    return at;
  }
  T t{};
  if (const int e = domainEdge(domain, coord, &t); e >= 0) {
    const BoundaryOwners::Edge& owner = owners.edges[e];
    at.tile = owner.patch;
    edgeUv(domain_of(owner.patch), owner.edge, owner.reversed ? T(1) - t : t, &at.u, &at.v);
  }
  return at;
}

// The unit displacement direction of a scalar map at `coord`: the patch's corner
// directions (one per control-mesh position, shared by every patch there) interpolated and
// normalised. On a corner it is that corner's direction; on an edge the blend of the edge's
// two end directions in the owner's order (start (1 - t) + end t), so both patches of a
// shared edge compute it with the same operands in the same order; inside, bilinear (quads)
// or barycentric (triangles).
template <class T>
mesh::Vec3T<T> displacementDirection(PatchDomain domain, const BoundaryOwners& owners,
                                     const std::array<mesh::Vec3T<T>, 4>& corner_dirs,
                                     const std::array<T, 3>& coord) {
  if (const int k = domainCorner(domain, coord); k >= 0) return corner_dirs[k];
  const uint32_t corners = domain == PatchDomain::kQuad ? 4 : 3;
  T t{};
  if (const int e = domainEdge(domain, coord, &t); e >= 0) {
    const BoundaryOwners::Edge& owner = owners.edges[e];
    const mesh::Vec3T<T>& from = corner_dirs[e];
    const mesh::Vec3T<T>& to = corner_dirs[(e + 1) % corners];
    const T s = owner.reversed ? T(1) - t : t;
    const mesh::Vec3T<T>& start = owner.reversed ? to : from;
    const mesh::Vec3T<T>& end = owner.reversed ? from : to;
    return normalize(start * (T(1) - s) + end * s);
  }
  if (domain == PatchDomain::kQuad) {
    const T u = coord[0], v = coord[1];
    const mesh::Vec3T<T> lower = corner_dirs[0] * (T(1) - u) + corner_dirs[1] * u;
    const mesh::Vec3T<T> upper = corner_dirs[3] * (T(1) - u) + corner_dirs[2] * u;
    return normalize(lower * (T(1) - v) + upper * v);
  }
  return normalize((corner_dirs[0] * coord[0] + corner_dirs[1] * coord[1]) +
                   corner_dirs[2] * coord[2]);
}

}  // namespace tb::techniques
