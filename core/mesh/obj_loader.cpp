#include "core/mesh/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/mesh/input_error.h"
#include "core/mesh/normals.h"

namespace tb::mesh {
namespace {

std::string readWholeFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path, "", "cannot open the file (missing or unreadable)");
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad()) throw InputError(path, "", "read error");
  return contents.str();
}

BoundaryInterpolation boundaryFromObjTag(int value, const std::string& source) {
  // OBJ tag values are not the Sdc enum: 0 none, 1 edge-and-corner, 2 edge-only.
  switch (value) {
    case 0:
      return BoundaryInterpolation::kNone;
    case 1:
      return BoundaryInterpolation::kEdgeAndCorner;
    case 2:
      return BoundaryInterpolation::kEdgeOnly;
    default:
      throw InputError(source, "tag 'interpolateboundary'",
                       "value " + std::to_string(value) + " is not 0, 1 or 2");
  }
}

// tinyobjloader parses numbers itself, into floats: one the scan accepted can still come
// out infinite there (a mantissa of 300 digits and a negative exponent). `what` names the
// element, numbered from 1 as in OBJ; `width` is the element's number of values.
void requireFinite(const std::vector<tinyobj::real_t>& values, size_t width, const char* what,
                   const std::string& source) {
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw InputError(source, std::string(what) + " " + std::to_string(i / width + 1),
                       "is not finite as tinyobjloader reads it (a 32-bit float)");
    }
  }
}

void readTags(const std::vector<tinyobj::tag_t>& tags, const std::string& source,
              SubdivisionTags* out) {
  for (const auto& tag : tags) {
    for (float value : tag.floatValues) {
      if (!std::isfinite(value)) {
        throw InputError(source, "tag '" + tag.name + "'",
                         "has a value that is not finite as tinyobjloader reads it (a float)");
      }
    }
    if (tag.name == "crease") {
      for (size_t i = 0; i + 1 < tag.intValues.size(); i += 2) {
        // One sharpness for all pairs, or one per pair (both occur in OpenSubdiv's shapes).
        const size_t pair = i / 2;
        const double sharpness = tag.floatValues.empty()         ? 0.0
                                 : pair < tag.floatValues.size() ? tag.floatValues[pair]
                                                                 : tag.floatValues.back();
        out->creases.push_back(
            {uint32_t(tag.intValues[i]), uint32_t(tag.intValues[i + 1]), sharpness});
      }
    } else if (tag.name == "corner") {
      for (size_t i = 0; i < tag.intValues.size(); ++i) {
        const double sharpness = tag.floatValues.empty()      ? 0.0
                                 : i < tag.floatValues.size() ? tag.floatValues[i]
                                                              : tag.floatValues.back();
        out->corners.push_back({uint32_t(tag.intValues[i]), sharpness});
      }
    } else if (tag.name == "hole") {
      for (int face : tag.intValues) out->holes.push_back(uint32_t(face));
    } else if (tag.name == "interpolateboundary" && !tag.intValues.empty()) {
      out->boundary = boundaryFromObjTag(tag.intValues[0], source);
      out->boundary_from_tag = true;
    } else if (tag.name == "facevaryingpropagatecorners" && !tag.intValues.empty()) {
      out->fvar_propagate_corners = tag.intValues[0];
    } else if (tag.name == "smoothtriangles") {
      out->smooth_triangles = true;
    } else if (tag.name == "creasemethod" && !tag.stringValues.empty()) {
      out->crease_method = tag.stringValues[0];
    }
  }
}

}  // namespace

Mesh loadObjText(std::string_view text, const std::string& source_name,
                 const LoadOptions& options) {
  const std::vector<uint32_t> face_lines = validateObjText(text, source_name);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning, error;
  std::istringstream stream{std::string(text)};
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, nullptr,
                                   /*triangulate=*/false);
  if (!ok || !error.empty()) {
    std::string first_line = error.substr(0, error.find('\n'));
    throw InputError(source_name, "", "tinyobjloader: " + first_line);
  }

  requireFinite(attrib.vertices, 3, "vertex position", source_name);
  requireFinite(attrib.normals, 3, "vertex normal", source_name);
  requireFinite(attrib.texcoords, 2, "texture coordinate", source_name);

  Mesh mesh;
  mesh.source = source_name;
  for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
    mesh.positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
  }
  for (size_t i = 0; i + 2 < attrib.normals.size(); i += 3) {
    mesh.normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
  }
  for (size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2) {
    mesh.uvs.push_back({attrib.texcoords[i], attrib.texcoords[i + 1]});
  }

  std::vector<uint32_t> face_positions;
  std::vector<int32_t> face_normals, face_uvs;
  for (const auto& shape : shapes) {
    size_t corner = 0;
    for (unsigned char size : shape.mesh.num_face_vertices) {
      face_positions.clear();
      face_normals.clear();
      face_uvs.clear();
      for (unsigned k = 0; k < size; ++k, ++corner) {
        const auto& index = shape.mesh.indices[corner];
        face_positions.push_back(uint32_t(index.vertex_index));
        face_normals.push_back(index.normal_index);
        face_uvs.push_back(index.texcoord_index);
      }
      const size_t face = mesh.faceCount();
      mesh.addFace(face_positions, face_normals, face_uvs,
                   face < face_lines.size() ? face_lines[face] : 0);
    }
  }
  if (mesh.faceCount() != face_lines.size()) {
    throw InputError(source_name, "",
                     "tinyobjloader read " + std::to_string(mesh.faceCount()) +
                         " faces where the file has " + std::to_string(face_lines.size()));
  }
  // tinyobjloader gives every shape the tags seen so far; the last one has them all.
  if (!shapes.empty()) readTags(shapes.back().mesh.tags, source_name, &mesh.tags);

  const bool any_missing_normal =
      mesh.normals.empty() || std::any_of(mesh.corner_normals.begin(), mesh.corner_normals.end(),
                                          [](int32_t n) { return n < 0; });
  if (options.compute_missing_normals && any_missing_normal) {
    assignAngleWeightedNormals(&mesh);
  }
  return mesh;
}

Mesh loadObjFile(const std::string& path, const LoadOptions& options) {
  const std::string text = readWholeFile(path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError(path, "", "the file is empty");
  }
  return loadObjText(text, path, options);
}

}  // namespace tb::mesh
