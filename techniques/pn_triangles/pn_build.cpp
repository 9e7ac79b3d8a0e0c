#include "techniques/pn_triangles/pn_build.h"

#include <bit>

namespace tb::pn_triangles {

PnInput<float> recordInputFloat(const mesh::Mesh& mesh, const techniques::TriangleRecords& build,
                                const techniques::TriangleRecordOptions& options, size_t patch) {
  return recordInput<float>(mesh, build, options, patch,
                            [](const mesh::Vec3d& v) { return vecCast<float>(v); });
}

PnInput<double> recordInputDouble(const mesh::Mesh& mesh, const techniques::TriangleRecords& build,
                                  const techniques::TriangleRecordOptions& options, size_t patch) {
  return recordInput<double>(mesh, build, options, patch, [](const mesh::Vec3d& v) { return v; });
}

std::vector<std::vector<uint32_t>> pnStorageBuffers(const mesh::Mesh& mesh,
                                                    const techniques::TriangleRecords& build) {
  auto vec4s = [](const std::vector<mesh::Vec3d>& values) {
    std::vector<uint32_t> words;
    words.reserve(values.size() * 4 + 4);
    for (const mesh::Vec3d& v : values) {
      for (float x : {float(v.x), float(v.y), float(v.z), 1.0f}) {
        words.push_back(std::bit_cast<uint32_t>(x));
      }
    }
    if (words.empty()) words.assign(4, 0);  // a storage buffer may not be empty
    return words;
  };
  std::vector<uint32_t> records;
  records.reserve(build.records.size() * techniques::kRecordWords);
  for (const techniques::TriangleRecord& r : build.records) {
    for (uint32_t x : r.perm) records.push_back(x);
    for (uint32_t x : r.position) records.push_back(x);
    for (uint32_t x : r.normal) records.push_back(x);
    for (uint32_t x : r.geometry_normal) records.push_back(x);
    for (uint32_t x : r.flags) records.push_back(x);
    for (const auto& ends : r.other_normal) {
      for (uint32_t x : ends) records.push_back(x);
    }
    for (double s : r.edge_scale) records.push_back(std::bit_cast<uint32_t>(float(s)));
  }
  return {vec4s(mesh.positions), vec4s(build.normals), records};
}

}  // namespace tb::pn_triangles
