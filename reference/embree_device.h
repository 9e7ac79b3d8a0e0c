// Internal: the process-wide Embree device, and turning Embree's per-thread error
// code into an exception.
#pragma once

#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "core/mesh/vec.h"

namespace tb::ref {

// Created on first use and kept for the life of the process (a device owns Embree's
// thread pool, so one per object would be wasteful). Thread-safe.
RTCDevice sharedEmbreeDevice();

// Throws InputError(source, element, "Embree failed: ...") when the calling thread's
// last Embree call on the shared device failed.
void throwOnEmbreeError(const std::string& source, const std::string& element);

// Adds one triangle geometry of `positions` (as floats, padded to 16 bytes as Embree loads
// them) and `triangles` (position indices, already checked in range) to `scene`, which the
// caller commits. Nothing is added for no triangles. share_triangles: Embree reads
// `triangles` in place (the caller keeps them alive as long as the scene) instead of a copy.
void attachTriangleGeometry(RTCScene scene, std::span<const mesh::Vec3d> positions,
                            std::span<const std::array<uint32_t, 3>> triangles,
                            bool share_triangles = false);

}  // namespace tb::ref
