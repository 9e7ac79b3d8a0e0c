#include "reference/limit_tessellation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <string>

#include "core/mesh/input_error.h"
#include "reference/face_domain.h"

namespace tb::ref {
namespace {

// Vertex and triangle counts of one face's grid.
struct FaceGrid {
  bool triangular = false;  // Loop triangle
  int sub_faces = 1;
  int segments = 1;  // per side of each (sub-)face
  size_t vertices() const {
    const size_t n = size_t(segments);
    return triangular ? (n + 1) * (n + 2) / 2 : size_t(sub_faces) * (n + 1) * (n + 1);
  }
  size_t triangles() const {
    const size_t n = size_t(segments);
    return triangular ? n * n : size_t(sub_faces) * 2 * n * n;
  }
};

FaceGrid faceGrid(const LimitSurface& surface, size_t face, int rate) {
  FaceGrid grid;
  if (!surface.hasLimitSurface(face)) {
    grid.sub_faces = 0;
    return grid;
  }
  const int size = int(surface.mesh().faceSize(face));
  grid.triangular = surface.scheme() == osd::Scheme::kLoop;
  grid.sub_faces = subFaceCount(surface.scheme(), size);
  grid.segments = hasSubFaces(surface.scheme(), size) ? (rate + 1) / 2 : rate;
  return grid;
}

class FaceWriter {
 public:
  FaceWriter(LimitTessellation* out, const LimitFace& face, size_t first_vertex,
             size_t first_triangle)
      : out_(out), face_(face), vertex_(first_vertex), triangle_(first_triangle) {}

  uint32_t vertex(mesh::Vec2d uv) {
    const LimitPoint point = face_.evaluate(uv.x, uv.y);
    out_->positions[vertex_] = point.position;
    out_->normals[vertex_] = point.normal;
    out_->vertex_face[vertex_] = uint32_t(face_.index());
    out_->vertex_uv[vertex_] = uv;
    return uint32_t(vertex_++);
  }
  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    out_->triangles[triangle_] = {a, b, c};
    out_->triangle_face[triangle_++] = uint32_t(face_.index());
  }

 private:
  LimitTessellation* out_;
  const LimitFace& face_;
  size_t vertex_, triangle_;
};

// (n+1)^2 grid over the unit square of (s,t), mapped to face (u,v) by `to_uv`.
template <class ToUv>
void writeQuadGrid(FaceWriter* writer, int n, ToUv to_uv) {
  std::vector<uint32_t> ids(size_t(n + 1) * size_t(n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      ids[size_t(j) * size_t(n + 1) + size_t(i)] =
          writer->vertex(to_uv(double(i) / n, double(j) / n));
    }
  }
  auto at = [&](int i, int j) { return ids[size_t(j) * size_t(n + 1) + size_t(i)]; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      writer->triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      writer->triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

void writeTriangleGrid(FaceWriter* writer, int n) {
  std::vector<uint32_t> ids;
  std::vector<size_t> row_start(size_t(n) + 2, 0);  // first id index of row j (v = j/n)
  for (int j = 0; j <= n; ++j) {
    row_start[size_t(j)] = ids.size();
    for (int i = 0; i + j <= n; ++i) ids.push_back(writer->vertex({double(i) / n, double(j) / n}));
  }
  auto at = [&](int i, int j) { return ids[row_start[size_t(j)] + size_t(i)]; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i + j < n; ++i) {
      writer->triangle(at(i, j), at(i + 1, j), at(i, j + 1));
      if (i + j < n - 1) writer->triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
}

}  // namespace

LimitTessellation tessellateLimit(const LimitSurface& surface, int rate,
                                  std::span<const uint8_t> faces_wanted) {
  if (rate < 1 || rate > kMaxTessellationRate) {
    throw mesh::InputError(surface.mesh().source, "option 'rate'",
                           "tessellation rate " + std::to_string(rate) + " is outside [1, " +
                               std::to_string(kMaxTessellationRate) + "]");
  }
  const size_t faces = surface.faceCount();
  std::vector<FaceGrid> grids(faces);
  std::vector<size_t> first_vertex(faces + 1, 0), first_triangle(faces + 1, 0);
  LimitTessellation out;
  for (size_t f = 0; f < faces; ++f) {
    if (!faces_wanted.empty() && faces_wanted[f] == 0) {
      grids[f].sub_faces = 0;  // left out: no vertices, no triangles, not counted as skipped
    } else {
      grids[f] = faceGrid(surface, f, rate);
      out.faces_skipped += grids[f].sub_faces == 0;
    }
    first_vertex[f + 1] = first_vertex[f] + (grids[f].sub_faces ? grids[f].vertices() : 0);
    first_triangle[f + 1] = first_triangle[f] + (grids[f].sub_faces ? grids[f].triangles() : 0);
  }
  out.positions.resize(first_vertex[faces]);
  out.normals.resize(first_vertex[faces]);
  out.vertex_face.resize(first_vertex[faces]);
  out.vertex_uv.resize(first_vertex[faces]);
  out.triangles.resize(first_triangle[faces]);
  out.triangle_face.resize(first_triangle[faces]);

  const osd::Scheme scheme = surface.scheme();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, faces), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t f = r.begin(); f != r.end(); ++f) {
      const FaceGrid& grid = grids[f];
      if (grid.sub_faces == 0) continue;
      const LimitFace face = surface.face(f);
      FaceWriter writer(&out, face, first_vertex[f], first_triangle[f]);
      if (grid.triangular) {
        writeTriangleGrid(&writer, grid.segments);
        continue;
      }
      const int size = face.faceSize();
      for (int k = 0; k < grid.sub_faces; ++k) {
        writeQuadGrid(&writer, grid.segments, [&](double s, double t) {
          return subFaceToFaceUv(scheme, size, k, {s, t});
        });
      }
    }
  });
  return out;
}

}  // namespace tb::ref
