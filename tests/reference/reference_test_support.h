// Helpers shared by the reference tests: loading the bundled OpenSubdiv shapes and
// sampling face domains with points clustered towards the corners.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "reference/face_domain.h"
#include "tests/test_support.h"

namespace tb::ref::testing {

// Names (without folder) of the bundled OpenSubdiv shapes starting with `prefix`, sorted.
inline std::vector<std::string> bundledShapes(const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& entry :
       std::filesystem::directory_iterator(tb::testing::assetPath("opensubdiv"))) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(prefix) && name.ends_with(".obj")) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

inline mesh::Mesh loadShape(const std::string& name) {
  return mesh::loadObjFile(tb::testing::assetPath("opensubdiv/" + name));
}

// x in [0,1] -> [0,1], cubic clustering at both ends: 4x^3 below 1/2, mirrored above.
inline double clusterTowardEnds(double x) {
  return x < 0.5 ? 4 * x * x * x : 1 - 4 * (1 - x) * (1 - x) * (1 - x);
}

// A g x g grid over [0,1]^2 in normalised (sub-)face coordinates, clustered towards
// the corners.
inline std::vector<mesh::Vec2d> clusteredSubFacePoints(int g) {
  std::vector<mesh::Vec2d> points;
  for (int j = 0; j < g; ++j) {
    for (int i = 0; i < g; ++i) {
      points.push_back(
          {clusterTowardEnds(double(i) / (g - 1)), clusterTowardEnds(double(j) / (g - 1))});
    }
  }
  return points;
}

// clusteredSubFacePoints on every sub-face, as face (u,v); Loop triangles keep the
// points with s + t <= 1.
inline std::vector<mesh::Vec2d> clusteredFacePoints(osd::Scheme scheme, int face_size, int g) {
  std::vector<mesh::Vec2d> points;
  for (int k = 0; k < subFaceCount(scheme, face_size); ++k) {
    for (const mesh::Vec2d& st : clusteredSubFacePoints(g)) {
      if (scheme == osd::Scheme::kLoop && st.x + st.y > 1) continue;
      points.push_back(subFaceToFaceUv(scheme, face_size, k, st));
    }
  }
  return points;
}

}  // namespace tb::ref::testing
