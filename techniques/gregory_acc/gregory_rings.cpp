#include "techniques/gregory_acc/gregory_rings.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace tb::gregory_acc {

void add(Stencil& into, const Stencil& s, double scale) {
  for (const auto& [index, weight] : s) into[index] += weight * scale;
}

void add(Stencil& into, uint32_t index, double weight) { into[index] += weight; }

double cosTurn(uint32_t k, uint32_t n) {
  if ((4 * k) % n == 0) {
    const uint32_t q = (4 * k / n) % 4;
    return q == 0 ? 1.0 : (q == 2 ? -1.0 : 0.0);
  }
  return std::cos(2.0 * std::numbers::pi * double(k) / double(n));
}

double sinTurn(uint32_t k, uint32_t n) {
  if ((4 * k) % n == 0) {
    const uint32_t q = (4 * k / n) % 4;
    return q == 1 ? 1.0 : (q == 3 ? -1.0 : 0.0);
  }
  return std::sin(2.0 * std::numbers::pi * double(k) / double(n));
}

uint64_t directedKey(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

VertexFrame vertexFrame(uint32_t v, const Ring& ring, TangentMask mask) {
  const uint32_t n = ring.valence();
  const double dn = double(n);
  VertexFrame frame;
  // Limit position: (n^2 v + 4 sum e_i + sum d_i) / (n (n + 5)).
  add(frame.position, v, dn * dn / (dn * (dn + 5)));
  for (uint32_t i = 0; i < n; ++i) {
    add(frame.position, ring.neighbour[i], 4.0 / (dn * (dn + 5)));
    add(frame.position, ring.diagonal[i], 1.0 / (dn * (dn + 5)));
  }
  // Tangents: sum_i cos_i (a e_i) + (cos_i + cos_{i+1}) d_i (sin likewise), times
  // 1 / (2 (n + 5) n lambda), lambda = (5 + c + sqrt((c + 9)(c + 1))) / 16 the subdominant
  // eigenvalue, c = cos(2 pi/n). kExactLimit: a = 1 + c + sqrt((1 + c)(9 + c)), the
  // Catmull-Clark limit tangent mask (Halstead et al. 1993), so the edge points span the
  // limit tangent plane. kPaper: a = 4 (1 + c), what averaging the ACC face
  // points f_i = (n v + 2 e_i + 2 e_{i+1} + d_i)/(n + 5) gives (OpenSubdiv Far's Gregory
  // basis); not the limit tangent plane for n != 4. Both are equal at n = 4.
  const double c = cosTurn(1, n);
  const double root = std::sqrt((c + 9) * (c + 1));
  const double scale = 16.0 / (dn * (c + 5 + root)) / (2 * (dn + 5));
  const double a = mask == TangentMask::kExactLimit ? 1 + c + root : 4 * (1 + c);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t ip = (i + 1) % n;
    add(frame.e0, ring.neighbour[i], scale * a * cosTurn(i, n));
    add(frame.e1, ring.neighbour[i], scale * a * sinTurn(i, n));
    add(frame.e0, ring.diagonal[i], scale * (cosTurn(i, n) + cosTurn(ip, n)));
    add(frame.e1, ring.diagonal[i], scale * (sinTurn(i, n) + sinTurn(ip, n)));
  }
  return frame;
}

VertexFrame boundaryFrame(uint32_t v, const Ring& ring) {
  const uint32_t k = ring.faces();
  const double dk = double(k);
  const uint32_t b0 = ring.neighbour.front(), b1 = ring.neighbour.back();
  VertexFrame frame;
  add(frame.position, v, 4.0 / 6);
  add(frame.position, b0, 1.0 / 6);
  add(frame.position, b1, 1.0 / 6);
  add(frame.e0, b0, 1.0 / 6);
  add(frame.e0, b1, -1.0 / 6);
  // k = 1: cos(pi) = -1 exactly, sin(pi) = 1.2e-16 (its terms are dropped by emit).
  const double c = std::cos(std::numbers::pi / dk), s = std::sin(std::numbers::pi / dk);
  const double den = 3 * dk + c;
  add(frame.e1, v, -4 * s / den / 3);
  const double alpha_ends = -((1 + 2 * c) * std::sqrt(1 + c)) / (den * std::sqrt(1 - c));
  add(frame.e1, b0, alpha_ends / 3);
  add(frame.e1, b1, alpha_ends / 3);
  for (uint32_t x = 0; x < k; ++x) {
    const double sx = std::sin(std::numbers::pi * double(x) / dk);
    const double sx1 = x + 1 == k ? 0.0 : std::sin(std::numbers::pi * double(x + 1) / dk);
    if (x > 0) add(frame.e1, ring.neighbour[x], 4 * sx / den / 3);
    add(frame.e1, ring.diagonal[x], (sx + sx1) / den / 3);
  }
  return frame;
}

Stencil twist(const Ring& ring, uint32_t i) {
  const uint32_t n = ring.valence();
  Stencil r;
  add(r, ring.neighbour[(i + 1) % n], 1.0 / 3);
  add(r, ring.neighbour[(i + n - 1) % n], -1.0 / 3);
  add(r, ring.diagonal[i], 1.0 / 6);
  add(r, ring.diagonal[(i + n - 1) % n], -1.0 / 6);
  return r;
}

std::string prefix(const mesh::Mesh& mesh) { return "gregory_acc: " + mesh.source + ": "; }

Stencil composed(const Stencil& over_refined, const RefinedMesh& refined, double scale) {
  Stencil out;
  for (const auto& [index, weight] : over_refined)
    add(out, refined.stencils[index], weight * scale);
  return out;
}

VertexFrame refinedFrame(uint32_t v, const Ring& refined_ring, const RefinedMesh& refined,
                         TangentMask mask) {
  const VertexFrame local = vertexFrame(v, refined_ring, mask);
  const double c = cosTurn(1, refined_ring.valence());
  const double scale = 16.0 / (5 + c + std::sqrt((c + 9) * (c + 1)));
  return {composed(local.position, refined, 1.0), composed(local.e0, refined, scale),
          composed(local.e1, refined, scale)};
}

VertexFrame refinedCreaseFrame(uint32_t v, const Ring& sector, const Ring& whole_refined,
                               const RefinedMesh& refined) {
  const uint32_t b0 = sector.neighbour.front(), b1 = sector.neighbour.back();
  const uint32_t k = sector.faces();
  // The sector in the refined ring: from the edge point of (v, b0), k faces counter-clockwise.
  const uint32_t first = whole_refined.indexOf(refined.edgePoint(v, b0));
  assert(first != UINT32_MAX && whole_refined.faces() >= k);
  Ring local;
  local.boundary = true;
  for (uint32_t x = 0; x <= k; ++x)
    local.neighbour.push_back(whole_refined.neighbour[(first + x) % whole_refined.valence()]);
  for (uint32_t x = 0; x < k; ++x)
    local.diagonal.push_back(whole_refined.diagonal[(first + x) % whole_refined.faces()]);
  // The crease rules' refined points over the input's vertices, where refineOnce differs.
  const std::unordered_map<uint32_t, Stencil> crease_point = {
      {v, Stencil{{v, 6.0 / 8}, {b0, 1.0 / 8}, {b1, 1.0 / 8}}},
      {local.neighbour.front(), Stencil{{v, 0.5}, {b0, 0.5}}},
      {local.neighbour.back(), Stencil{{v, 0.5}, {b1, 0.5}}}};
  const auto over_input = [&](const Stencil& over_refined, double scale) {
    Stencil out;
    for (const auto& [index, weight] : over_refined) {
      const auto own = crease_point.find(index);
      add(out, own != crease_point.end() ? own->second : refined.stencils[index], weight * scale);
    }
    return out;
  };
  // Tangents in the refined faces' half-size parameter: times 1 / lambda = 2 (boundary).
  const VertexFrame frame = boundaryFrame(v, local);
  return {over_input(frame.position, 1.0), over_input(frame.e0, 2.0), over_input(frame.e1, 2.0)};
}

Stencil faceDiagonal(std::span<const uint32_t> fv, uint32_t k) {
  const size_t size = fv.size();
  Stencil d;
  if (size == 4) {
    add(d, fv[(k + 2) % 4], 1.0);
    return d;
  }
  // 4 c - v - e_i - e_{i+1}, c = the mean of the face's vertices.
  for (uint32_t i = 0; i < size; ++i) add(d, fv[i], 4.0 / double(size));
  for (uint32_t i : {k, uint32_t((k + 1) % size), uint32_t((k + size - 1) % size)}) {
    add(d, fv[i], -1.0);
  }
  return d;
}

Rings buildRings(const mesh::Mesh& mesh) {
  Rings out;
  out.rings.resize(mesh.positions.size());
  std::unordered_map<uint64_t, uint32_t> face_of_directed;  // (a -> b) -> face
  std::vector<std::vector<uint32_t>> vertex_faces(mesh.positions.size());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (uint32_t k = 0; k < fv.size(); ++k) {
      const uint32_t a = fv[k], b = fv[(k + 1) % fv.size()];
      if (!face_of_directed.emplace(directedKey(a, b), uint32_t(f)).second) {
        out.error = prefix(mesh) + "edge (" + std::to_string(a) + ", " + std::to_string(b) +
                    ") is used twice in the same direction (" + mesh::describeFace(mesh, f) +
                    "); faces must be consistently oriented";
        return out;
      }
      vertex_faces[a].push_back(uint32_t(f));
    }
  }
  for (uint32_t v = 0; v < mesh.positions.size(); ++v) {
    if (vertex_faces[v].empty()) continue;
    const uint32_t face_count = uint32_t(vertex_faces[v].size());
    Ring& ring = out.rings[v];
    // Start a boundary vertex's walk at the face after its boundary edge: the face
    // whose edge (v, neighbour) has no face on the other side (no directed edge w -> v).
    uint32_t start_face = vertex_faces[v].front();
    for (uint32_t f : vertex_faces[v]) {
      const auto fv = mesh.facePositions(f);
      for (uint32_t k = 0; k < fv.size(); ++k) {
        if (fv[k] == v && !face_of_directed.count(directedKey(fv[(k + 1) % fv.size()], v))) {
          start_face = f;
          ring.boundary = true;
          break;
        }
      }
      if (ring.boundary) break;
    }
    uint32_t f = start_face;
    for (uint32_t step = 0; step <= face_count; ++step) {
      const auto fv = mesh.facePositions(f);
      const size_t size = fv.size();
      uint32_t k = 0;
      while (fv[k] != v) ++k;
      ring.neighbour.push_back(fv[(k + 1) % size]);
      ring.diagonal.push_back(faceDiagonal(fv, k));
      ring.quads_only &= size == 4;
      const uint32_t last = fv[(k + size - 1) % size];
      const auto next = face_of_directed.find(directedKey(v, last));
      if (next == face_of_directed.end()) {
        ring.neighbour.push_back(last);  // the second boundary neighbour
        break;
      }
      f = next->second;
      if (f == start_face) break;
    }
    if (ring.faces() != face_count) {
      out.error = prefix(mesh) + "vertex " + std::to_string(v) +
                  " is non-manifold (its faces form more than one fan)";
      return out;
    }
    const uint32_t low = ring.boundary ? 1 : 3;
    if (ring.faces() < low || ring.faces() > kMaxValence) {
      out.error = prefix(mesh) + (ring.boundary ? "boundary vertex " : "vertex ") +
                  std::to_string(v) + (ring.boundary ? " has " : " has valence ") +
                  std::to_string(ring.faces()) + (ring.boundary ? " faces" : "") +
                  "; gregory_acc needs " + std::to_string(low) + ".." + std::to_string(kMaxValence);
      return out;
    }
  }
  return out;
}

std::vector<Ring> sectorsOf(uint32_t v, const Ring& whole,
                            const techniques::CreasePreparation& creases) {
  const techniques::SharpVertexKind kind = creases.vertex_kind[v];
  if (kind != techniques::SharpVertexKind::kCrease && kind != techniques::SharpVertexKind::kCorner)
    return {whole};
  const uint32_t n = whole.valence();
  std::vector<uint32_t> cuts;  // neighbour indices where a sector starts or ends, ascending
  for (uint32_t i = 0; i < n; ++i) {
    if (creases.isSharp(v, whole.neighbour[i]) || (whole.boundary && (i == 0 || i + 1 == n))) {
      cuts.push_back(i);
    }
  }
  Ring ring = whole;  // a closed ring rotated to start at a cut, then closed by repeating it
  if (!whole.boundary) {
    if (cuts.empty()) return {whole};  // not reached: crease and corner kinds have sharp edges
    std::rotate(ring.neighbour.begin(), ring.neighbour.begin() + cuts[0], ring.neighbour.end());
    std::rotate(ring.diagonal.begin(), ring.diagonal.begin() + cuts[0], ring.diagonal.end());
    const uint32_t shift = cuts[0];
    for (uint32_t& c : cuts) c -= shift;
    ring.neighbour.push_back(ring.neighbour.front());
    cuts.push_back(n);
  }
  std::vector<Ring> sectors;
  for (size_t s = 0; s + 1 < cuts.size(); ++s) {
    Ring sector;
    sector.boundary = true;
    sector.corner = kind == techniques::SharpVertexKind::kCorner;
    sector.quads_only = whole.quads_only;
    sector.neighbour.assign(ring.neighbour.begin() + cuts[s],
                            ring.neighbour.begin() + cuts[s + 1] + 1);
    sector.diagonal.assign(ring.diagonal.begin() + cuts[s], ring.diagonal.begin() + cuts[s + 1]);
    sectors.push_back(std::move(sector));
  }
  return sectors;
}

Stencil cornerEdgePoint(uint32_t v, const Ring& sector, uint32_t w) {
  const uint32_t k = sector.faces(), j = sector.indexOf(w);
  Stencil e;
  if (j == 0 || j == k) {
    add(e, v, 2.0 / 3);
    add(e, w, 1.0 / 3);
    return e;
  }
  const double phi = std::numbers::pi / (2.0 * double(k));
  const double a = std::sin(double(k - j) * phi) / 3, b = std::sin(double(j) * phi) / 3;
  add(e, v, 1.0 - a - b);
  add(e, sector.neighbour.front(), a);
  add(e, sector.neighbour.back(), b);
  return e;
}

Stencil pruned(const Stencil& s) {
  Stencil out;
  for (const auto& [index, weight] : s) {
    if (std::abs(weight) >= 1e-14) out.emplace(index, weight);
  }
  return out;
}

}  // namespace tb::gregory_acc
