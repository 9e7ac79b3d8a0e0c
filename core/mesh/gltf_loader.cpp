#include "core/mesh/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/mesh/gltf_accessor.h"
#include "core/mesh/input_error.h"
#include "core/mesh/normals.h"

namespace tb::mesh {
namespace {

using Matrix = std::array<double, 16>;  // column-major, as glTF writes it
constexpr Matrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) sum += a[k * 4 + r] * b[c * 4 + k];
      m[c * 4 + r] = sum;
    }
  }
  return m;
}

// A node's local matrix: `matrix`, or translation · rotation · scale (§3.5.3).
Matrix localMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Matrix m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  Matrix m = kIdentity;
  if (node.rotation.size() == 4) {
    const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2],
                 w = node.rotation[3];
    m = {1 - 2 * (y * y + z * z),
         2 * (x * y + z * w),
         2 * (x * z - y * w),
         0,
         2 * (x * y - z * w),
         1 - 2 * (x * x + z * z),
         2 * (y * z + x * w),
         0,
         2 * (x * z + y * w),
         2 * (y * z - x * w),
         1 - 2 * (x * x + y * y),
         0,
         0,
         0,
         0,
         1};
  }
  if (node.scale.size() == 3) {
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) m[c * 4 + r] *= node.scale[size_t(c)];
    }
  }
  if (node.translation.size() == 3) {
    for (int r = 0; r < 3; ++r) m[12 + r] = node.translation[size_t(r)];
  }
  return m;
}

struct MeshInstance {
  int mesh;
  Matrix world;
};

// Every mesh of the default scene (scene 0 when none is named; the root nodes when the
// file has no scene) with its node's world matrix, in depth-first node order.
class SceneWalk {
 public:
  SceneWalk(const tinygltf::Model& model, const std::string& file) : model_(model), file_(file) {
    on_path_.assign(model.nodes.size(), 0);
  }

  std::vector<MeshInstance> run() {
    for (int root : roots()) visit(root, kIdentity);
    return instances_;
  }

 private:
  std::vector<int> roots() const {
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (size_t(scene) >= model_.scenes.size()) {
        throw InputError(file_, "scene", std::to_string(scene) + " does not exist");
      }
      return model_.scenes[size_t(scene)].nodes;
    }
    std::vector<uint8_t> child(model_.nodes.size(), 0);
    for (const tinygltf::Node& node : model_.nodes) {
      for (int c : node.children) {
        if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = 1;
      }
    }
    std::vector<int> result;
    for (size_t n = 0; n < child.size(); ++n) {
      if (!child[n]) result.push_back(int(n));
    }
    return result;
  }

  void visit(int index, const Matrix& parent) {
    const std::string element = "node " + std::to_string(index);
    if (index < 0 || size_t(index) >= model_.nodes.size()) {
      throw InputError(file_, element, "does not exist");
    }
    if (on_path_[size_t(index)]) throw InputError(file_, element, "is its own ancestor (a cycle)");
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    const Matrix world = multiply(parent, localMatrix(node));
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model_.meshes.size()) {
        throw InputError(file_, element, "mesh " + std::to_string(node.mesh) + " does not exist");
      }
      instances_.push_back({node.mesh, world});
    }
    on_path_[size_t(index)] = 1;
    for (int child : node.children) visit(child, world);
    on_path_[size_t(index)] = 0;
  }

  const tinygltf::Model& model_;
  const std::string& file_;
  std::vector<uint8_t> on_path_;
  std::vector<MeshInstance> instances_;
};

// Positions welded as they arrive: bitwise-equal coordinates share one index (first seen
// first), and with a tolerance a position also joins the first earlier one within it.
class PositionWeld {
 public:
  PositionWeld(double tolerance, std::vector<Vec3d>* positions)
      : tolerance_(tolerance), positions_(positions) {}

  uint32_t add(const Vec3d& p) {
    const Key key = {std::bit_cast<uint64_t>(p.x), std::bit_cast<uint64_t>(p.y),
                     std::bit_cast<uint64_t>(p.z)};
    if (auto it = exact_.find(key); it != exact_.end()) return it->second;
    uint32_t index = tolerance_ > 0 ? near(p) : UINT32_MAX;
    if (index == UINT32_MAX) {
      index = uint32_t(positions_->size());
      positions_->push_back(p);
      if (tolerance_ > 0) cells_[cell(p)].push_back(index);
    }
    exact_.emplace(key, index);
    return index;
  }

 private:
  using Key = std::array<uint64_t, 3>;
  using Cell = std::array<int64_t, 3>;
  Cell cell(const Vec3d& p) const {
    return {int64_t(std::floor(p.x / tolerance_)), int64_t(std::floor(p.y / tolerance_)),
            int64_t(std::floor(p.z / tolerance_))};
  }
  // The lowest-numbered position within the tolerance, UINT32_MAX when none.
  uint32_t near(const Vec3d& p) const {
    const Cell c = cell(p);
    uint32_t best = UINT32_MAX;
    for (int64_t dx = -1; dx <= 1; ++dx) {
      for (int64_t dy = -1; dy <= 1; ++dy) {
        for (int64_t dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells_.end()) continue;
          for (uint32_t q : it->second) {
            if (q < best && length((*positions_)[q] - p) <= tolerance_) best = q;
          }
        }
      }
    }
    return best;
  }

  double tolerance_;
  std::vector<Vec3d>* positions_;
  std::map<Key, uint32_t> exact_;
  std::map<Cell, std::vector<uint32_t>> cells_;
};

Vec3d transformPoint(const Matrix& m, const double* p) {
  return {m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
          m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
          m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]};
}

double determinant3(const Matrix& m) {
  return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
         m[8] * (m[1] * m[6] - m[5] * m[2]);
}

// A normal through the inverse transpose of the upper 3x3: its cofactor matrix over the
// determinant, not renormalised (the techniques normalise, as for OBJ normals), so an
// identity transform gives the file's normal bit for bit.
Vec3d transformNormal(const Matrix& m, const double* n) {
  const Vec3d c0{m[0], m[1], m[2]}, c1{m[4], m[5], m[6]}, c2{m[8], m[9], m[10]};
  const Vec3d r0 = cross(c1, c2), r1 = cross(c2, c0), r2 = cross(c0, c1);
  const double det = dot(c0, r0);
  const Vec3d v = r0 * n[0] + r1 * n[1] + r2 * n[2];
  return det == 0 ? normalize(v) : v * (1.0 / det);
}

std::string primitiveName(const tinygltf::Model& model, int mesh, size_t p) {
  const std::string& name = model.meshes[size_t(mesh)].name;
  return "mesh " + std::to_string(mesh) + (name.empty() ? "" : " (" + name + ")") + " primitive " +
         std::to_string(p);
}

int attribute(const tinygltf::Primitive& primitive, const char* name) {
  auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? -1 : it->second;
}

bool finite(const Vec3d& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// One primitive's accessors, read and checked against each other (in the file's space).
struct PrimitiveData {
  std::vector<double> positions, normals, uvs;  // 3, 3 and 2 per vertex; normals, uvs optional
  std::vector<uint32_t> indices;                // 3 per triangle
  size_t vertices = 0;
};

PrimitiveData readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                            const GltfPlace& place) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1) {
    throw InputError(place.file, place.element,
                     "mode " + std::to_string(primitive.mode) +
                         " is not TRIANGLES (4); points, lines, strips and fans are not read");
  }
  const int position_accessor = attribute(primitive, "POSITION");
  if (position_accessor < 0) {
    throw InputError(place.file, place.element, "has no POSITION attribute");
  }
  PrimitiveData data;
  data.positions = readGltfAccessor(model, position_accessor, 3, "POSITION", place);
  data.vertices = data.positions.size() / 3;
  const int normal_accessor = attribute(primitive, "NORMAL");
  const int uv_accessor = attribute(primitive, "TEXCOORD_0");
  if (normal_accessor >= 0) {
    data.normals = readGltfAccessor(model, normal_accessor, 3, "NORMAL", place);
  }
  if (uv_accessor >= 0) data.uvs = readGltfAccessor(model, uv_accessor, 2, "TEXCOORD_0", place);
  if ((normal_accessor >= 0 && data.normals.size() != data.positions.size()) ||
      (uv_accessor >= 0 && data.uvs.size() / 2 != data.vertices)) {
    throw InputError(place.file, place.element,
                     "NORMAL and TEXCOORD_0 need as many elements as POSITION (" +
                         std::to_string(data.vertices) + ")");
  }
  if (primitive.indices >= 0) {
    data.indices = readGltfIndices(model, primitive.indices, place);
  } else {
    data.indices.resize(data.vertices);
    for (size_t i = 0; i < data.vertices; ++i) data.indices[i] = uint32_t(i);
  }
  if (data.indices.size() % 3 != 0) {
    throw InputError(
        place.file, place.element,
        std::to_string(data.indices.size()) + " indices is not a whole number of triangles");
  }
  return data;
}

struct Builder {
  const tinygltf::Model& model;
  const std::string& file;
  PositionWeld weld;
  Mesh* mesh;
  bool any_normal_missing = false;

  void addPrimitive(const MeshInstance& instance, size_t p);

 private:
  // Welds the primitive's transformed positions and appends its normals and uvs; returns
  // each vertex's position index.
  std::vector<uint32_t> addVertices(const PrimitiveData& data, const Matrix& world,
                                    const GltfPlace& place);
  void addTriangles(const PrimitiveData& data, const std::vector<uint32_t>& welded,
                    int32_t normal_base, int32_t uv_base, bool mirrored, const GltfPlace& place);
};

std::vector<uint32_t> Builder::addVertices(const PrimitiveData& data, const Matrix& world,
                                           const GltfPlace& place) {
  auto refuse = [&](size_t v, const char* what) {
    throw InputError(file, place.element,
                     "vertex " + std::to_string(v) + ": " + what + " is not finite");
  };
  std::vector<uint32_t> welded(data.vertices);
  for (size_t v = 0; v < data.vertices; ++v) {
    const Vec3d p = transformPoint(world, &data.positions[3 * v]);
    if (!finite(p)) refuse(v, "POSITION");
    welded[v] = weld.add(p);
  }
  for (size_t v = 0; v < data.normals.size() / 3; ++v) {
    const Vec3d n = transformNormal(world, &data.normals[3 * v]);
    if (!finite(n)) refuse(v, "NORMAL");
    mesh->normals.push_back(n);
  }
  for (size_t v = 0; v < data.uvs.size() / 2; ++v) {
    if (!std::isfinite(data.uvs[2 * v]) || !std::isfinite(data.uvs[2 * v + 1])) {
      refuse(v, "TEXCOORD_0");
    }
    mesh->uvs.push_back({data.uvs[2 * v], 1.0 - data.uvs[2 * v + 1]});
  }
  return welded;
}

void Builder::addTriangles(const PrimitiveData& data, const std::vector<uint32_t>& welded,
                           int32_t normal_base, int32_t uv_base, bool mirrored,
                           const GltfPlace& place) {
  const size_t triangles = data.indices.size() / 3;
  size_t zero_area = 0;
  for (size_t t = 0; t < triangles; ++t) {
    std::array<uint32_t, 3> corner = {data.indices[3 * t], data.indices[3 * t + 1],
                                      data.indices[3 * t + 2]};
    if (mirrored) std::swap(corner[1], corner[2]);  // §3.7.4: a mirroring node reverses winding
    std::array<uint32_t, 3> pos{};
    std::array<int32_t, 3> normal_ids{}, uv_ids{};
    for (size_t k = 0; k < 3; ++k) {
      if (corner[k] >= data.vertices) {
        throw InputError(file, place.element,
                         "triangle " + std::to_string(t) + ": index " + std::to_string(corner[k]) +
                             " is past the " + std::to_string(data.vertices) + " vertices");
      }
      pos[k] = welded[corner[k]];
      normal_ids[k] = data.normals.empty() ? -1 : normal_base + int32_t(corner[k]);
      uv_ids[k] = data.uvs.empty() ? -1 : uv_base + int32_t(corner[k]);
    }
    if (pos[0] == pos[1] || pos[1] == pos[2] || pos[0] == pos[2]) {
      throw InputError(file, place.element,
                       "triangle " + std::to_string(t) + " has two corners at one position");
    }
    const Vec3d& a = mesh->positions[pos[0]];
    if (length(cross(mesh->positions[pos[1]] - a, mesh->positions[pos[2]] - a)) == 0) ++zero_area;
    mesh->addFace(pos, normal_ids, uv_ids, 0);
  }
  if (zero_area > 0 && zero_area == triangles) {
    throw InputError(file, place.element,
                     "every one of its " + std::to_string(zero_area) + " triangles has zero area");
  }
}

void Builder::addPrimitive(const MeshInstance& instance, size_t p) {
  const tinygltf::Primitive& primitive = model.meshes[size_t(instance.mesh)].primitives[p];
  const std::string element = primitiveName(model, instance.mesh, p);
  const GltfPlace place{file, element};
  const PrimitiveData data = readPrimitive(model, primitive, place);
  // glTF vertex i of this primitive is normal normal_base + i and uv uv_base + i.
  const int32_t normal_base = int32_t(mesh->normals.size()), uv_base = int32_t(mesh->uvs.size());
  const std::vector<uint32_t> welded = addVertices(data, instance.world, place);
  any_normal_missing = any_normal_missing || data.normals.empty();
  addTriangles(data, welded, normal_base, uv_base, determinant3(instance.world) < 0, place);
}

// Extensions that change nothing the reader takes (materials, texture transforms) or that
// it reads as it is (quantised attributes are accessors of integer components).
bool supportedExtension(const std::string& name) {
  return name == "KHR_mesh_quantization" || name == "KHR_texture_transform" ||
         name.rfind("KHR_materials_", 0) == 0;
}

Mesh buildMesh(const tinygltf::Model& model, const std::string& file,
               const GltfLoadOptions& options) {
  for (const std::string& name : model.extensionsRequired) {
    if (supportedExtension(name)) continue;
    for (size_t m = 0; m < model.meshes.size(); ++m) {
      for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
        if (model.meshes[m].primitives[p].extensions.count(name) != 0) {
          throw InputError(file, primitiveName(model, int(m), p),
                           "uses the required extension " + name + ", which tessbench cannot read");
        }
      }
    }
    throw InputError(file, "extensionsRequired",
                     name + " is required and tessbench cannot read it");
  }
  Mesh mesh;
  mesh.source = file;
  Builder builder{model, file, PositionWeld(options.weld_tolerance, &mesh.positions), &mesh};
  for (const MeshInstance& instance : SceneWalk(model, file).run()) {
    const auto& primitives = model.meshes[size_t(instance.mesh)].primitives;
    for (size_t p = 0; p < primitives.size(); ++p) builder.addPrimitive(instance, p);
  }
  if (mesh.faceCount() == 0) {
    throw InputError(file, "scene", "has no triangles (no TRIANGLES primitive in its nodes)");
  }
  // As for OBJ: a primitive without NORMAL gives the whole mesh smooth computed normals.
  if (builder.any_normal_missing && options.compute_missing_normals) {
    assignAngleWeightedNormals(&mesh);
  }
  return mesh;
}

// Images are never decoded: only geometry is read.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
  return true;
}

bool noFile(const std::string&, void*) { return false; }
std::string samePath(const std::string& path, void*) { return path; }
bool refuseRead(std::vector<unsigned char>*, std::string* err, const std::string& path, void*) {
  if (err != nullptr) *err += "external file '" + path + "' refused (bytes in memory)\n";
  return false;
}
bool refuseWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// tinygltf's errors and warnings come as lines; the first one says what broke.
std::string firstLine(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? std::string("tinygltf could not read it") : line;
}

Mesh parse(std::span<const uint8_t> bytes, const std::string& source, const std::string& base_dir,
           bool allow_files, const GltfLoadOptions& options) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skipImage, nullptr);
  if (!allow_files) loader.SetFsCallbacks({noFile, samePath, refuseRead, refuseWrite, nullptr});
  tinygltf::Model model;
  std::string error, warning;
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(),
                                                       unsigned(bytes.size()), base_dir)
                         : loader.LoadASCIIFromString(&model, &error, &warning,
                                                      reinterpret_cast<const char*>(bytes.data()),
                                                      unsigned(bytes.size()), base_dir);
  if (!ok) throw InputError(source, "", "tinygltf: " + firstLine(error));
  return buildMesh(model, source, options);
}

}  // namespace

Mesh loadGltfBytes(std::span<const uint8_t> bytes, const std::string& source_name,
                   const GltfLoadOptions& options) {
  if (bytes.empty()) throw InputError(source_name, "", "the file is empty");
  if (bytes.size() > 0xffffffffu) throw InputError(source_name, "", "is larger than 4 GiB");
  return parse(bytes, source_name, "", false, options);
}

Mesh loadGltfFile(const std::string& path, const GltfLoadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the file (missing or unreadable)");
  std::ostringstream contents;
  contents << in.rdbuf();
  const std::string text = contents.str();
  if (text.empty()) throw InputError(path, "", "the file is empty");
  if (text.size() > 0xffffffffu) throw InputError(path, "", "is larger than 4 GiB");
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  return parse({reinterpret_cast<const uint8_t*>(text.data()), text.size()}, path,
               base_dir.empty() ? "." : base_dir, true, options);
}

bool isGltfPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return extension == ".gltf" || extension == ".glb";
}

}  // namespace tb::mesh
