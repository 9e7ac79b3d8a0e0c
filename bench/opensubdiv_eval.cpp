#include "bench/opensubdiv_eval.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>

#include <algorithm>
#include <stdexcept>

#include "core/osd/topology_refiner_builder.h"

namespace tb::bench {
namespace {

namespace Bfr = OpenSubdiv::Bfr;
namespace Far = OpenSubdiv::Far;

constexpr size_t kValuesPerPoint = 9;  // position, du, dv

std::unique_ptr<Far::TopologyRefiner> quadRefiner(const mesh::Mesh& mesh) {
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.faceSize(f) != 4) {
      throw std::runtime_error(mesh.source + ": face " + std::to_string(f) +
                               " is not a quad; the OpenSubdiv rows take quad meshes only");
    }
  }
  return osd::buildTopologyRefiner(mesh, osd::Scheme::kCatmullClark);
}

// Results of every point of every face: position, du, dv, face-major.
class PointBuffer : public OsdEvaluation {
 public:
  PointBuffer(size_t faces, const std::vector<mesh::Vec2d>& uv)
      : uv_(uv), values_(faces * uv.size() * kValuesPerPoint) {}
  mesh::Vec3d position(size_t face, size_t i) const override { return at(face, i, 0); }
  mesh::Vec3d du(size_t face, size_t i) const override { return at(face, i, 3); }
  mesh::Vec3d dv(size_t face, size_t i) const override { return at(face, i, 6); }

 protected:
  size_t faces() const { return values_.size() / (uv_.size() * kValuesPerPoint); }
  const std::vector<mesh::Vec2d> uv_;
  std::vector<double> values_;

 private:
  mesh::Vec3d at(size_t face, size_t i, size_t offset) const {
    const double* v = &values_[(face * uv_.size() + i) * kValuesPerPoint + offset];
    return {v[0], v[1], v[2]};
  }
};

class BfrSurfaces final : public PointBuffer {
 public:
  BfrSurfaces(const mesh::Mesh& mesh, const std::vector<mesh::Vec2d>& uv, int approx_level)
      : PointBuffer(mesh.faceCount(), uv), refiner_(quadRefiner(mesh)) {
    Bfr::SurfaceFactory::Options options;
    options.SetApproxLevelSmooth(approx_level);
    options.SetApproxLevelSharp(std::max(approx_level, 6));
    const Bfr::RefinerSurfaceFactory<> factory(*refiner_, options);
    std::vector<double> positions;
    for (const mesh::Vec3d& p : mesh.positions) positions.insert(positions.end(), {p.x, p.y, p.z});
    const Bfr::Surface<double>::PointDescriptor xyz(3);
    surfaces_.resize(mesh.faceCount());
    patch_points_.resize(mesh.faceCount());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      if (!factory.InitVertexSurface<double>(int(f), &surfaces_[f])) {
        throw std::runtime_error(mesh.source + ": Bfr has no surface for face " +
                                 std::to_string(f));
      }
      patch_points_[f].resize(size_t(surfaces_[f].GetNumPatchPoints()) * 3);
      surfaces_[f].PreparePatchPoints(positions.data(), xyz, patch_points_[f].data(), xyz);
    }
  }

  int64_t evaluateAll() override {
    const Bfr::Surface<double>::PointDescriptor xyz(3);
    double* out = values_.data();
    for (size_t f = 0; f < surfaces_.size(); ++f) {
      const Bfr::Surface<double>& surface = surfaces_[f];
      const double* patch_points = patch_points_[f].data();
      for (const mesh::Vec2d& p : uv_) {
        const double uv[2] = {p.x, p.y};
        surface.Evaluate(uv, patch_points, xyz, out, out + 3, out + 6);
        out += kValuesPerPoint;
      }
    }
    return int64_t(surfaces_.size() * uv_.size());
  }

 private:
  std::unique_ptr<Far::TopologyRefiner> refiner_;
  std::vector<Bfr::Surface<double>> surfaces_;
  std::vector<std::vector<double>> patch_points_;
};

// A point as Far's refiners and stencil tables want it.
struct FarPoint {
  double x = 0, y = 0, z = 0;
  void Clear(void* = nullptr) { x = y = z = 0; }
  void AddWithWeight(const FarPoint& p, double w) {
    x += w * p.x;
    y += w * p.y;
    z += w * p.z;
  }
};

std::unique_ptr<Far::TopologyRefiner> adaptiveRefiner(const mesh::Mesh& mesh, int isolation) {
  std::unique_ptr<Far::TopologyRefiner> refiner = quadRefiner(mesh);
  Far::TopologyRefiner::AdaptiveOptions adaptive(isolation);
  adaptive.useInfSharpPatch = true;
  refiner->RefineAdaptive(adaptive);
  return refiner;
}

class PatchMapEvaluation final : public PointBuffer {
 public:
  PatchMapEvaluation(const mesh::Mesh& mesh, const std::vector<mesh::Vec2d>& uv, int isolation)
      : PointBuffer(mesh.faceCount(), uv), refiner_(adaptiveRefiner(mesh, isolation)) {
    Far::PatchTableFactory::Options options(isolation);
    options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    options.SetPatchPrecision<double>();
    options.useInfSharpPatch = true;
    table_.reset(Far::PatchTableFactory::Create(*refiner_, options));
    // Every refined level, then the end caps' local points.
    const int refined = refiner_->GetNumVerticesTotal();
    points_.resize(size_t(refined + table_->GetNumLocalPoints()));
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      points_[i] = {mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z};
    }
    const Far::PrimvarRefinerReal<double> primvar(*refiner_);
    FarPoint* source = points_.data();
    for (int level = 1; level <= refiner_->GetMaxLevel(); ++level) {
      FarPoint* destination = source + refiner_->GetLevel(level - 1).GetNumVertices();
      primvar.Interpolate(level, source, destination);
      source = destination;
    }
    // (PatchTable::ComputeLocalPointValues assumes float stencils.)
    if (table_->GetNumLocalPoints() > 0) {
      const FarPoint* all = points_.data();
      FarPoint* local = points_.data() + refined;
      table_->GetLocalPointStencilTable<double>()->UpdateValues(all, local);
    }
    map_ = std::make_unique<Far::PatchMap>(*table_);
  }

  int64_t evaluateAll() override {
    double* out = values_.data();
    double w[3][20];
    for (size_t f = 0; f < faces(); ++f) {
      for (const mesh::Vec2d& p : uv_) {
        const Far::PatchTable::PatchHandle* handle = map_->FindPatch(int(f), p.x, p.y);
        table_->EvaluateBasis(*handle, p.x, p.y, w[0], w[1], w[2]);
        const Far::ConstIndexArray cvs = table_->GetPatchVertices(*handle);
        for (int q = 0; q < 3; ++q) {
          FarPoint sum;
          for (int k = 0; k < cvs.size(); ++k) sum.AddWithWeight(points_[size_t(cvs[k])], w[q][k]);
          out[3 * q] = sum.x;
          out[3 * q + 1] = sum.y;
          out[3 * q + 2] = sum.z;
        }
        out += kValuesPerPoint;
      }
    }
    return int64_t(faces() * uv_.size());
  }

 private:
  std::unique_ptr<Far::TopologyRefiner> refiner_;
  std::unique_ptr<Far::PatchTable> table_;
  std::unique_ptr<Far::PatchMap> map_;
  std::vector<FarPoint> points_;
};

class LimitStencilEvaluation final : public PointBuffer {
 public:
  LimitStencilEvaluation(const mesh::Mesh& mesh, const std::vector<mesh::Vec2d>& uv, int isolation)
      : PointBuffer(mesh.faceCount(), uv) {
    const std::unique_ptr<Far::TopologyRefiner> refiner = adaptiveRefiner(mesh, isolation);
    std::vector<double> s, t;
    for (const mesh::Vec2d& p : uv) {
      s.push_back(p.x);
      t.push_back(p.y);
    }
    using Factory = Far::LimitStencilTableFactoryReal<double>;
    Factory::LocationArrayVec locations(mesh.faceCount());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      locations[f].ptexIdx = int(f);  // a quad mesh's ptex faces are its faces
      locations[f].numLocations = int(uv.size());
      locations[f].s = s.data();
      locations[f].t = t.data();
    }
    table_.reset(Factory::Create(*refiner, locations));
    for (const mesh::Vec3d& p : mesh.positions) control_.push_back({p.x, p.y, p.z});
    for (int source : table_->GetControlIndices()) {
      if (source < 0 || size_t(source) >= control_.size()) {
        throw std::runtime_error("limit stencils refer to refined vertices");
      }
    }
  }

  int64_t evaluateAll() override {
    const std::vector<int>& sizes = table_->GetSizes();
    const std::vector<Far::Index>& offsets = table_->GetOffsets();
    const std::vector<Far::Index>& sources = table_->GetControlIndices();
    const double* weights[3] = {table_->GetWeights().data(), table_->GetDuWeights().data(),
                                table_->GetDvWeights().data()};
    double* out = values_.data();
    for (size_t i = 0; i < sizes.size(); ++i) {
      FarPoint sum[3];
      const size_t begin = size_t(offsets[i]), end = begin + size_t(sizes[i]);
      for (size_t k = begin; k < end; ++k) {
        const FarPoint& c = control_[size_t(sources[k])];
        for (int q = 0; q < 3; ++q) sum[q].AddWithWeight(c, weights[q][k]);
      }
      for (int q = 0; q < 3; ++q) {
        out[3 * q] = sum[q].x;
        out[3 * q + 1] = sum[q].y;
        out[3 * q + 2] = sum[q].z;
      }
      out += kValuesPerPoint;
    }
    return int64_t(sizes.size());
  }

  double multiplyAddsPerPoint() const override {
    return 9.0 * double(table_->GetControlIndices().size()) / double(table_->GetNumStencils());
  }

 private:
  std::unique_ptr<const Far::LimitStencilTableReal<double>> table_;
  std::vector<FarPoint> control_;
};

}  // namespace

std::unique_ptr<OsdEvaluation> makeBfrSurfaces(const mesh::Mesh& mesh,
                                               const std::vector<mesh::Vec2d>& uv,
                                               int approx_level) {
  return std::make_unique<BfrSurfaces>(mesh, uv, approx_level);
}

std::unique_ptr<OsdEvaluation> makePatchMap(const mesh::Mesh& mesh,
                                            const std::vector<mesh::Vec2d>& uv, int isolation) {
  return std::make_unique<PatchMapEvaluation>(mesh, uv, isolation);
}

std::unique_ptr<OsdEvaluation> makeLimitStencils(const mesh::Mesh& mesh,
                                                 const std::vector<mesh::Vec2d>& uv,
                                                 int isolation) {
  return std::make_unique<LimitStencilEvaluation>(mesh, uv, isolation);
}

}  // namespace tb::bench
