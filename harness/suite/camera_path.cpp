#include "harness/suite/camera_path.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/mesh/input_error.h"
#include "core/view/camera.h"
#include "harness/suite/asset_catalog.h"

namespace tb::suite {

view::CameraPath testOrbitPath(const mesh::Aabb& bounds) {
  constexpr uint32_t kWidthPx = 640, kHeightPx = 480;
  constexpr double kDegree = std::numbers::pi / 180;
  const mesh::Vec3d centre = 0.5 * (bounds.min + bounds.max);
  // At least a small radius, so a flat or point-like asset still gets a valid camera.
  const double radius = std::max(0.5 * length(bounds.max - bounds.min), 1e-3);
  const double distance = 2.5 * radius;
  view::CameraPath path{"test_orbit", {}};
  for (double azimuth_deg : {0.0, 120.0, 240.0}) {
    const double azimuth = azimuth_deg * kDegree, elevation = 20 * kDegree;
    const mesh::Vec3d eye =
        centre + distance * mesh::Vec3d{std::cos(elevation) * std::sin(azimuth),
                                        std::sin(elevation),
                                        std::cos(elevation) * std::cos(azimuth)};
    // Near and far planes just outside the bounding sphere (distance is 2.5 radii).
    path.views.push_back(view::perspectiveView({.eye = eye,
                                                .target = centre,
                                                .fov_y_rad = 60 * kDegree,
                                                .width_px = kWidthPx,
                                                .height_px = kHeightPx,
                                                .near_plane = distance - 1.01 * radius,
                                                .far_plane = distance + 1.01 * radius}));
  }
  return path;
}

namespace {
namespace fs = std::filesystem;

// The bundled paths' folder: assets/cameras (the asset catalogue reads only *.obj, so the
// paths here are never taken for assets).
fs::path camerasDirectory() { return fs::path(assetsDirectory()) / "cameras"; }
}  // namespace

std::vector<std::string> bundledCameraPaths() {
  std::vector<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(camerasDirectory(), error), end; !error && it != end;
       it.increment(error)) {
    if (it->is_regular_file() && it->path().extension() == ".json") {
      names.push_back(it->path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

CameraPathSpec resolveCameraPath(const std::string& name_or_path) {
  const std::vector<std::string> bundled = bundledCameraPaths();
  if (std::find(bundled.begin(), bundled.end(), name_or_path) != bundled.end()) {
    // Named relative to the assets folder, wherever the checkout is, so results and
    // messages do not depend on it.
    return loadCameraPath((camerasDirectory() / (name_or_path + ".json")).string(),
                          "assets/cameras/" + name_or_path + ".json");
  }
  if (fs::is_regular_file(name_or_path)) return loadCameraPath(name_or_path, name_or_path);
  std::string names;
  for (const std::string& name : bundled) names += (names.empty() ? "" : ", ") + name;
  throw mesh::InputError(name_or_path, "",
                         "no such file, and not a bundled camera path (bundled: " + names + ")");
}

}  // namespace tb::suite
