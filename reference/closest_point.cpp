#include "reference/closest_point.h"

#include <algorithm>

namespace tb::ref {
namespace {

// Closest point of segment [a, b] as the weight t of b (a + t (b - a)).
double segmentParameter(const mesh::Vec3d& p, const mesh::Vec3d& a, const mesh::Vec3d& b) {
  const mesh::Vec3d ab = b - a;
  const double len2 = dot(ab, ab);
  return len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
}

TrianglePoint closestOnEdges(const mesh::Vec3d& p, const mesh::Vec3d& a, const mesh::Vec3d& b,
                             const mesh::Vec3d& c) {
  const double t_ab = segmentParameter(p, a, b);
  const double t_bc = segmentParameter(p, b, c);
  const double t_ca = segmentParameter(p, c, a);
  const TrianglePoint candidates[3] = {
      {a + (b - a) * t_ab, {1 - t_ab, t_ab, 0}},
      {b + (c - b) * t_bc, {0, 1 - t_bc, t_bc}},
      {c + (a - c) * t_ca, {t_ca, 0, 1 - t_ca}},
  };
  const TrianglePoint* best = &candidates[0];
  for (const TrianglePoint& candidate : candidates) {
    const mesh::Vec3d d = candidate.point - p, e = best->point - p;
    if (dot(d, d) < dot(e, e)) best = &candidate;
  }
  return *best;
}

}  // namespace

TrianglePoint closestPointOnTriangle(const mesh::Vec3d& p, const mesh::Vec3d& a,
                                     const mesh::Vec3d& b, const mesh::Vec3d& c) {
  const mesh::Vec3d ab = b - a, ac = c - a;
  const mesh::Vec3d normal = cross(ab, ac);
  if (!(dot(normal, normal) > 0)) return closestOnEdges(p, a, b, c);

  // Vertex region of a: p projects before a on both edges leaving it.
  const mesh::Vec3d ap = p - a;
  const double ab_ap = dot(ab, ap), ac_ap = dot(ac, ap);
  if (ab_ap <= 0 && ac_ap <= 0) return {a, {1, 0, 0}};

  // Vertex region of b.
  const mesh::Vec3d bp = p - b;
  const double ab_bp = dot(ab, bp), ac_bp = dot(ac, bp);
  if (ab_bp >= 0 && ac_bp <= ab_bp) return {b, {0, 1, 0}};

  // Edge region of ab: the signed area (scaled) opposite c is non-positive.
  const double area_c = ab_ap * ac_bp - ab_bp * ac_ap;
  if (area_c <= 0 && ab_ap >= 0 && ab_bp <= 0) {
    const double t = ab_ap / (ab_ap - ab_bp);
    return {a + ab * t, {1 - t, t, 0}};
  }

  // Vertex region of c.
  const mesh::Vec3d cp = p - c;
  const double ab_cp = dot(ab, cp), ac_cp = dot(ac, cp);
  if (ac_cp >= 0 && ab_cp <= ac_cp) return {c, {0, 0, 1}};

  // Edge region of ac.
  const double area_b = ab_cp * ac_ap - ab_ap * ac_cp;
  if (area_b <= 0 && ac_ap >= 0 && ac_cp <= 0) {
    const double t = ac_ap / (ac_ap - ac_cp);
    return {a + ac * t, {1 - t, 0, t}};
  }

  // Edge region of bc.
  const double area_a = ab_bp * ac_cp - ab_cp * ac_bp;
  const double along_b = ac_bp - ab_bp, along_c = ab_cp - ac_cp;
  if (area_a <= 0 && along_b >= 0 && along_c >= 0) {
    const double t = along_b / (along_b + along_c);
    return {b + (c - b) * t, {0, 1 - t, t}};
  }

  // Face region: barycentrics from the three scaled areas.
  const double total = area_a + area_b + area_c;
  if (!(total > 0)) return closestOnEdges(p, a, b, c);
  const double v = area_b / total, w = area_c / total;
  return {a + ab * v + ac * w, {1 - v - w, v, w}};
}

}  // namespace tb::ref
