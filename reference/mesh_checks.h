// Internal: validation and tag helpers shared by the Bfr reference, the Embree
// cross-check and the distance field, so each rule is written and worded once.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"

namespace tb::ref {

// OpenSubdiv treats sharpness >= 10 as infinite (Sdc::Crease::SHARPNESS_INFINITE).
inline constexpr double kInfiniteSharpness = 10.0;

// Throws InputError(source, "vertex i", ...) for the first non-finite coordinate.
void checkFinitePositions(std::span<const mesh::Vec3d> positions, const std::string& source);

// Throws InputError(source, "triangle t", ...) for the first corner index that is not below
// `vertex_count`.
void checkTriangleCorners(std::span<const std::array<uint32_t, 3>> triangles, size_t vertex_count,
                          const std::string& source);

// Throws InputError(mesh.source, "face i", "index out of range ...").
void checkFaceIndex(const mesh::Mesh& mesh, size_t face);

// Throws InputError naming the face when (u,v) is outside its domain (face_domain.h).
void checkInsideFaceDomain(const mesh::Mesh& mesh, size_t face, osd::Scheme scheme, mesh::Vec2d uv);

// Crease sharpness per unoriented edge (v0 < v1); a repeated tag keeps the last
// value, as OpenSubdiv's Far does.
std::map<std::pair<uint32_t, uint32_t>, double> creaseSharpnessByEdge(const mesh::Mesh& mesh);

}  // namespace tb::ref
