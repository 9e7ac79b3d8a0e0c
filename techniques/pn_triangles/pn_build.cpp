#include "techniques/pn_triangles/pn_build.h"

#include <bit>
#include <utility>

#include "shaders/common/layout/bindings.h"
#include "shaders/pn_triangles/pn_layout.h"

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
  static_assert(techniques::kRecordWords == gpu::layout::kTbPnRecordWords);
  std::vector<uint32_t> records;
  records.reserve(build.records.size() * techniques::kRecordWords);
  for (const techniques::TriangleRecord& r : build.records) {
    gpu::layout::TbPnRecord record{};
    for (int i = 0; i < 3; ++i) {
      record.perm[i] = r.perm[i];
      record.position[i] = r.position[i];
      record.normal[i] = r.normal[i];
      record.geometry_normal[i] = r.geometry_normal[i];
      record.flags[i] = r.flags[i];
      record.other_normal[i][0] = r.other_normal[i][0];
      record.other_normal[i][1] = r.other_normal[i][1];
      record.edge_scale[i] = float(r.edge_scale[i]);
    }
    gpu::layout::appendWords(records, record);
  }
  constexpr uint32_t first = TB_BINDING_FIRST_TECHNIQUE;  // buffers[b - first] is binding b's
  std::vector<std::vector<uint32_t>> buffers(TB_PN_BINDING_RECORDS - first + 1);
  buffers[TB_PN_BINDING_POSITIONS - first] = vec4s(mesh.positions);
  buffers[TB_PN_BINDING_NORMALS - first] = vec4s(build.normals);
  buffers[TB_PN_BINDING_RECORDS - first] = std::move(records);
  return buffers;
}

}  // namespace tb::pn_triangles
