#include "harness/pictures/crack_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/gpu/render_target.h"
#include "harness/lod/edge_pattern_levels.h"

namespace tb::pictures {
namespace {

constexpr const char* kEdgePattern = "edge_pattern";

std::string keyOf(const results::MetricRow& row, const char* key) {
  const auto it = row.keys.find(key);
  return it == row.keys.end() ? std::string() : it->second;
}

std::optional<double> metricOf(const results::MetricRow& row, const char* name) {
  for (const results::Metric& m : row.metrics) {
    if (m.name == name) return m.value;
  }
  return std::nullopt;
}

// Whether the point p (world) is in front of, or close behind, the triangle drawn at pixel
// (x, y): along the ray from the eye through p, its distance against the triangle's plane.
bool seenAt(const SurfaceErrorMesh& mesh, uint32_t id, const mesh::Vec3d& eye, const mesh::Vec3d& p,
            double tolerance) {
  if (id == gpu::RenderTarget::kNoId) return true;
  const auto& tri = mesh.triangles[id];
  const mesh::Vec3d& a = mesh.positions[tri[0]];
  const mesh::Vec3d n = cross(mesh.positions[tri[1]] - a, mesh.positions[tri[2]] - a);
  const double distance = length(p - eye);
  if (!(distance > 0)) return true;
  const mesh::Vec3d ray = (1.0 / distance) * (p - eye);
  const double facing = dot(n, ray);
  if (std::abs(facing) <= 1e-12 * length(n)) return true;  // seen edge-on
  return distance <= dot(n, a - eye) / facing + tolerance;
}

// Pixels within `outer` of (cx, cy) and beyond `inner`, in `colour`.
void markRing(RgbImage* image, double cx, double cy, double inner, double outer, Rgb colour) {
  const int64_t x0 = int64_t(std::floor(cx - outer)), x1 = int64_t(std::ceil(cx + outer));
  const int64_t y0 = int64_t(std::floor(cy - outer)), y1 = int64_t(std::ceil(cy + outer));
  for (int64_t y = y0; y <= y1; ++y) {
    for (int64_t x = x0; x <= x1; ++x) {
      const double dx = double(x) + 0.5 - cx, dy = double(y) + 0.5 - cy;
      const double d2 = dx * dx + dy * dy;
      if (d2 <= outer * outer && d2 >= inner * inner) image->setClipped(x, y, colour);
    }
  }
}

mesh::Vec3d midpoint(const measures::UnequalPair& pair) {
  return {0.5 * (double(pair.a.x) + pair.b.x), 0.5 * (double(pair.a.y) + pair.b.y),
          0.5 * (double(pair.a.z) + pair.b.z)};
}

}  // namespace

std::string CrackRow::text() const {
  return "cpu_float, " + spacing + ", level " + level + (levels.empty() ? "" : ", " + levels);
}

std::optional<CrackRow> worstCpuCrackRow(const results::Record& record) {
  std::optional<CrackRow> worst;
  for (const results::MeasureResult& measure : record.measures) {
    if (measure.measure != "cracks" || measure.status != results::MeasureStatus::kOk) continue;
    for (const results::MetricRow& row : measure.rows) {
      if (row.status != results::MeasureStatus::kOk || keyOf(row, "backend") != "cpu_float" ||
          !keyOf(row, "displacement").empty()) {
        continue;
      }
      const double points = metricOf(row, "points_not_equal").value_or(0);
      const double gap = metricOf(row, "max_gap_world").value_or(0);
      if (points <= 0 || (worst && !(gap > worst->max_gap_world))) continue;
      worst = CrackRow{keyOf(row, "spacing"), keyOf(row, "level"), keyOf(row, "levels"),
                       uint64_t(points), gap};
    }
  }
  return worst;
}

std::vector<measures::UnequalPair> crackPairsOf(const techniques::SurfacePatches& patches,
                                                const CrackRow& row) {
  tess::Spacing spacing;
  if (!tess::parseSpacing(row.spacing, &spacing)) {
    throw std::invalid_argument("crack picture: unknown spacing \"" + row.spacing + "\"");
  }
  size_t parsed = 0;
  const float level = std::stof(row.level, &parsed);
  if (parsed != row.level.size() || !(level > 0)) {
    throw std::invalid_argument("crack picture: level \"" + row.level + "\"");
  }
  std::vector<tess::Levels> levels;
  if (row.levels == kEdgePattern) {
    levels = lod::edgePatternLevels(patches, spacing, level);
  } else if (row.levels.empty()) {
    tess::Levels uniform;
    uniform.outer = {level, level, level, level};
    uniform.inner = {level, level};
    levels.assign(patches.patchCount(), uniform);
  } else {
    throw std::invalid_argument("crack picture: levels \"" + row.levels + "\"");
  }
  return measures::unequalPairs(patches, spacing, levels);
}

CrackPicture composeCrackPicture(const RgbImage& shaded, const SurfaceErrorMesh& mesh,
                                 const view::View& view, uint32_t size_px,
                                 std::span<const uint32_t> triangle_ids,
                                 std::span<const measures::UnequalPair> pairs) {
  if (shaded.width_px != size_px || shaded.height_px != size_px ||
      triangle_ids.size() != size_t(size_px) * size_px) {
    throw std::invalid_argument("composeCrackPicture: the picture or the IDs are not size_px");
  }
  CrackPicture picture;
  picture.image = shaded;
  const mesh::Vec3d eye{view.eye[0], view.eye[1], view.eye[2]};
  const double tolerance = kCrackDepthTolerance * mesh::diagonalOf(mesh.bounds);
  const measures::UnequalPair* worst = nullptr;
  std::vector<std::array<double, 2>> visible;  // drawn after the hidden ones, over them
  for (const measures::UnequalPair& pair : pairs) {
    const mesh::Vec3d p = midpoint(pair);
    const view::ProjectedPoint s = view::projectToPixels(view, p.x, p.y, p.z);
    if (!(s.clip_w > 0) || s.x_px < 0 || s.y_px < 0 || s.x_px >= size_px || s.y_px >= size_px) {
      ++picture.points_outside;
      continue;
    }
    if (worst == nullptr || pair.gap > worst->gap) worst = &pair;
    // Seen when some pixel of its 3 x 3 neighbourhood shows no surface in front of it.
    bool seen = false;
    const int64_t px = int64_t(s.x_px), py = int64_t(s.y_px);
    for (int64_t y = std::max<int64_t>(py - 1, 0); y <= std::min<int64_t>(py + 1, size_px - 1);
         ++y) {
      for (int64_t x = std::max<int64_t>(px - 1, 0); x <= std::min<int64_t>(px + 1, size_px - 1);
           ++x) {
        seen =
            seen || seenAt(mesh, triangle_ids[size_t(y) * size_px + size_t(x)], eye, p, tolerance);
      }
    }
    ++(seen ? picture.points_visible : picture.points_hidden);
    if (seen) {
      visible.push_back({s.x_px, s.y_px});
    } else {
      markRing(&picture.image, s.x_px, s.y_px, 0, kCrackHiddenRadiusPx, kCrackHidden);
    }
  }
  for (const auto& [x, y] : visible)
    markRing(&picture.image, x, y, 0, kCrackDotRadiusPx, kCrackMark);
  if (worst != nullptr) {
    const mesh::Vec3d p = midpoint(*worst);
    const view::ProjectedPoint s = view::projectToPixels(view, p.x, p.y, p.z);
    markRing(&picture.image, s.x_px, s.y_px, kCrackWorstRadiusPx - 1.5, kCrackWorstRadiusPx,
             kCrackMark);
  }
  for (size_t i = 0; i < picture.image.rgb.size(); i += 3) {
    picture.marked_pixels += picture.image.rgb[i] == kCrackMark.r &&
                             picture.image.rgb[i + 1] == kCrackMark.g &&
                             picture.image.rgb[i + 2] == kCrackMark.b;
  }
  return picture;
}

}  // namespace tb::pictures
