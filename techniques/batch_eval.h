// Batched evaluation of many domain points per patch (docs/ARCHITECTURE.md §2, "Batched
// evaluation"): the plain types of SurfacePatches::makeBatchPattern and evaluateBatch.
//
// A tessellation pattern visits the same domain points on every patch of one domain (a
// lattice of N segments per edge, or the tessellator's points at one set of levels). A
// technique whose patch is linear in its control points for a fixed (u, v) computes the
// basis weights of those points once, in a BatchPattern, and then evaluates each patch as
// a small dense product (weights x control points) over structure-of-arrays output.
// A pattern is read-only once made and may be shared by threads; each thread fills its
// own BatchPoints.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#include "core/mesh/vec.h"

namespace tb::techniques {

enum class PatchDomain { kTriangle, kQuad };

// Domain coordinates as the TES receives gl_TessCoord: triangles use barycentric
// (u, v, w) weighting corners 0, 1, 2; quads use (u, v, unused).
using DomainCoord = std::array<double, 3>;

// Points per block of a batched kernel: one AVX-512 register of doubles. Batched arrays
// are padded to a whole number of blocks.
inline constexpr size_t kBatchLanes = 8;

inline size_t batchBlocks(size_t points) { return (points + kBatchLanes - 1) / kBatchLanes; }

// Zero-filled doubles on 64-byte boundaries (one cache line, one AVX-512 load), so the
// batched kernels load and store whole aligned blocks.
class AlignedDoubles {
 public:
  AlignedDoubles() = default;
  explicit AlignedDoubles(size_t size) { resize(size); }
  AlignedDoubles(const AlignedDoubles& other) : AlignedDoubles(other.size_) {
    std::copy(other.begin(), other.end(), begin());
  }
  AlignedDoubles& operator=(const AlignedDoubles& other) {
    if (this != &other) {
      resize(other.size_);
      std::copy(other.begin(), other.end(), begin());
    }
    return *this;
  }
  AlignedDoubles(AlignedDoubles&&) noexcept = default;
  AlignedDoubles& operator=(AlignedDoubles&&) noexcept = default;

  // Keeps the storage when it is large enough; new or not, every value becomes 0.
  void resize(size_t size) {
    if (size > capacity_) {
      data_.reset(new (std::align_val_t(kAlignment)) double[size]);
      capacity_ = size;
    }
    size_ = size;
    std::fill(begin(), end(), 0.0);
  }
  size_t size() const { return size_; }
  double* data() { return data_.get(); }
  const double* data() const { return data_.get(); }
  double& operator[](size_t i) { return data_[i]; }
  double operator[](size_t i) const { return data_[i]; }
  double* begin() { return data_.get(); }
  double* end() { return data_.get() + size_; }
  const double* begin() const { return data_.get(); }
  const double* end() const { return data_.get() + size_; }

  static constexpr size_t kAlignment = 64;  // bytes

 private:
  struct AlignedDelete {
    void operator()(double* p) const { ::operator delete[](p, std::align_val_t(kAlignment)); }
  };
  std::unique_ptr<double[], AlignedDelete> data_;
  size_t size_ = 0, capacity_ = 0;
};

// What a batched evaluation computes: the position alone, or with derivatives and normals.
enum class BatchOutput : uint8_t {
  kPositions,               // the position alone (screen-space error): no du, dv or normal
  kPositionAndDerivatives,  // position, du, dv: the work Bfr's Evaluate(P, Du, Dv) does
  kWithNormals,             // the same and the unit normal du x dv / |du x dv|
};

// The domain points of one tessellation pattern on patches of one domain, made once by
// SurfacePatches::makeBatchPattern and then used for any patch of that domain of the
// surface that made it. A technique with a batched kernel derives from it to hold the
// points' basis weights; the base class is what the per-point default needs.
class BatchPattern {
 public:
  BatchPattern(PatchDomain domain, std::vector<DomainCoord> coords, BatchOutput output)
      : domain_(domain), coords_(std::move(coords)), output_(output) {}
  virtual ~BatchPattern() = default;
  BatchPattern(const BatchPattern&) = delete;
  BatchPattern& operator=(const BatchPattern&) = delete;

  PatchDomain domain() const { return domain_; }
  const std::vector<DomainCoord>& coords() const { return coords_; }
  size_t pointCount() const { return coords_.size(); }
  BatchOutput output() const { return output_; }
  // Double multiply-adds one point costs in the technique's batched kernel (position,
  // du and dv; the normal not counted): e.g. 120 for acc's bicubic position with two
  // bi-quadratic-cubic tangent patches. 0 for the per-point default, which has no count.
  virtual double multiplyAddsPerPoint() const { return 0; }

 private:
  PatchDomain domain_;
  std::vector<DomainCoord> coords_;
  BatchOutput output_;
};

// The points of one patch from a batched evaluation, structure of arrays: component c
// (0 x, 1 y, 2 z) of point i is position[c][i]. Arrays hold at least `count` values.
//
// Derivatives are per unit of the domain coordinates: on a quad du = ∂P/∂u and dv = ∂P/∂v
// (Bfr's Du, Dv on the same face); on a triangle du is the derivative towards corner 1
// and dv towards corner 2 (∂/∂v - ∂/∂u and ∂/∂w - ∂/∂u in barycentric (u, v, w)), which
// is Bfr's Du, Dv of a Loop triangle. On both, normal = du x dv / |du x dv|. A technique
// with tangent patches (acc) returns its tangent fields, whose cross product is its normal.
struct BatchPoints {
  size_t count = 0;              // points filled: the pattern's point count
  bool has_derivatives = false;  // du, dv filled (a batched kernel, unless kPositions)
  bool has_normals = false;      // normal filled (the per-point default, unless kPositions)
  std::array<AlignedDoubles, 3> position, du, dv, normal;

  // Sizes every array for `points` (padded to whole blocks) and clears the flags.
  void reset(size_t points) {
    count = points;
    has_derivatives = has_normals = false;
    const size_t padded = batchBlocks(points) * kBatchLanes;
    for (auto* field : {&position, &du, &dv, &normal}) {
      for (AlignedDoubles& component : *field) {
        if (component.size() != padded) component.resize(padded);
      }
    }
  }
  static mesh::Vec3d at(const std::array<AlignedDoubles, 3>& field, size_t i) {
    return {field[0][i], field[1][i], field[2][i]};
  }
  static void set(std::array<AlignedDoubles, 3>& field, size_t i, const mesh::Vec3d& value) {
    field[0][i] = value.x;
    field[1][i] = value.y;
    field[2][i] = value.z;
  }
};

// The lattice of `segments` segments per edge: on a quad (i/n, j/n) for 0 <= i, j <= n,
// (n + 1)^2 points, j-major; on a triangle the barycentric points (i/n, j/n, 1 - i/n - j/n)
// with i + j <= n, (n + 1)(n + 2)/2 points. Exact at the corners and on the edges.
inline std::vector<DomainCoord> latticeCoords(PatchDomain domain, int segments) {
  std::vector<DomainCoord> coords;
  const double n = segments;
  for (int j = 0; j <= segments; ++j) {
    const int i_end = domain == PatchDomain::kQuad ? segments : segments - j;
    for (int i = 0; i <= i_end; ++i) {
      const double u = i / n, v = j / n;
      coords.push_back(domain == PatchDomain::kQuad
                           ? DomainCoord{u, v, 0}
                           : DomainCoord{u, v, double(segments - i - j) / n});
    }
  }
  return coords;
}

}  // namespace tb::techniques
