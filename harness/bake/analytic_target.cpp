#include "harness/bake/analytic_target.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "core/mesh/bounds.h"
#include "core/mesh/input_error.h"
#include "reference/limit_surface.h"

namespace tb::bake {
namespace {

// Phases of the three sines, so h is not symmetric about the box centre.
constexpr double kPhase[3] = {0.3, 1.1, 2.3};

}  // namespace

double AnalyticDisplacement::height(const mesh::Vec3d& p) const {
  const double k = 2 * std::numbers::pi * frequency / diagonal;
  double sum = 0;
  for (int i = 0; i < 3; ++i) sum += std::sin(k * (p[i] - centre[i]) + kPhase[i]);
  return amplitude * sum / 3;
}

std::string AnalyticDisplacement::describe() const {
  return fmt::format(
      "h(p) = A (sin(2 pi f qx + {}) + sin(2 pi f qy + {}) + sin(2 pi f qz + {})) / 3, "
      "q = (p - c) / D, A = {:.17g}, f = {:.17g}, c = ({:.17g}, {:.17g}, {:.17g}), D = {:.17g}",
      kPhase[0], kPhase[1], kPhase[2], amplitude, frequency, centre.x, centre.y, centre.z,
      diagonal);
}

AnalyticDisplacement analyticDisplacementFor(const mesh::Mesh& mesh) {
  if (mesh.positions.empty()) throw mesh::InputError(mesh.source, "", "the mesh has no vertices");
  const mesh::Aabb box = mesh::boundsOf(mesh);
  const double diagonal = mesh::diagonalOf(box);
  if (!(diagonal > 0)) {
    throw mesh::InputError(mesh.source, "", "the bounding box has a zero diagonal");
  }
  AnalyticDisplacement h;
  h.centre = 0.5 * (box.min + box.max);
  h.diagonal = diagonal;
  h.amplitude = kAnalyticAmplitudeFraction * diagonal;
  h.frequency = kAnalyticFrequency;
  return h;
}

ref::LimitTessellation analyticTargetMesh(const mesh::Mesh& mesh, osd::Scheme scheme, int rate,
                                          const AnalyticDisplacement& displacement) {
  const ref::LimitSurface limit(mesh, scheme);
  ref::LimitTessellation target = ref::tessellateLimit(limit, rate);
  for (size_t i = 0; i < target.positions.size(); ++i) {
    const mesh::Vec3d p = target.positions[i];
    target.positions[i] = p + displacement.height(p) * target.normals[i];
  }
  return target;
}

void writeTriangleObj(const std::string& path, const ref::LimitTessellation& mesh,
                      const std::string& comment) {
  if (std::filesystem::exists(path)) {
    throw mesh::InputError(path, "", "the file exists already (never overwritten)");
  }
  const std::string partial = path + ".partial";
  std::FILE* file = std::fopen(partial.c_str(), "wx");
  if (file == nullptr) throw mesh::InputError(path, "", "cannot be written");
  bool ok = std::fprintf(file, "# %s\n", comment.c_str()) > 0;
  for (const mesh::Vec3d& p : mesh.positions) {
    ok = ok && std::fprintf(file, "v %.17g %.17g %.17g\n", p.x, p.y, p.z) > 0;
  }
  for (const ref::Triangle& t : mesh.triangles) {
    ok = ok && std::fprintf(file, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1) > 0;
  }
  ok = (std::fclose(file) == 0) && ok;
  std::error_code error;
  if (ok) std::filesystem::rename(partial, path, error);
  if (!ok || error) {
    std::filesystem::remove(partial, error);
    throw mesh::InputError(path, "", "cannot be written");
  }
}

}  // namespace tb::bake
