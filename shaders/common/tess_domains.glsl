// The compute tessellator's three domains: a GLSL port of core/tess/triangle_domain.cpp,
// quad_domain.cpp and tessellator.cpp (isoline), with the CPU model's point order and
// triangle order (its rings outwards-in, each ring's edges in order). Rings are stitched as
// soon as the inner one is placed; points and triangles go to separate buffers, so the
// interleaving does not change either order. See tess_stitch.glsl for what the including
// shader declares.
#ifndef TB_TESS_DOMAINS_GLSL
#define TB_TESS_DOMAINS_GLSL

#include "tess_stitch.glsl"

bool g_tb_point_mode = false;  // points only, no primitives

// ---- triangle (triangle_domain.cpp) ----

// Boundary ring: edges u = 0 (v falling), v = 0 (u rising), w = 0 (u falling).
TbRing tbTriangleBoundary(TbRingPlan plan) {
  TbRing ring = tbMakeRing(kTbRingClosed, g_tb_point_count, 3, ivec4(0));
  for (int e = 0; e < 3; ++e) {
    const int last = tbPlanOuter(plan, e).point_count - 1;
    ring.count[e] = last;
    for (int p = 0; p < last; ++p) {
      const uint t = tbPlacePoint(tbPlanOuter(plan, e), e == 1 ? p : last - p);
      const uint u = e == 0 ? 0u : t;
      const uint v = e == 0 ? t : (e == 1 ? 0u : kFxOne - t);
      tbAddPoint(u, v);
    }
  }
  tbCloseRing(ring);
  return ring;
}

// Inner ring r: at 2/3 of place(r) across each edge, shifted by half of that along it.
TbRing tbTriangleInnerRing(TbEdgeSpacing inner, int r) {
  const int end = inner.point_count - 1 - r;
  TbRing ring = tbMakeRing(kTbRingClosed, g_tb_point_count, 3, ivec4(end - r, end - r, end - r, 0));
  const uint perp = (tbPlacePoint(inner, r) * kFxTwoThirds + kFxHalf) >> 16;
  const uint shift = (perp + 1u) / 2u;
  for (int e = 0; e < 3; ++e) {
    for (int p = r; p < end; ++p) {
      const uint along = tbPlacePoint(inner, e == 1 ? p : end - (p - r)) - shift;
      if (e == 0) {
        tbAddPoint(perp, along);
      } else if (e == 1) {
        tbAddPoint(along, perp);
      } else {
        tbAddPoint(along, kFxOne - along - perp);
      }
    }
  }
  tbCloseRing(ring);
  return ring;
}

// An even inside level's centre point, stitched as a ring whose every row is that point.
TbRing tbTriangleCentre() {
  return tbMakeRing(kTbRingCentre, tbAddPoint(kFxOneThird, kFxOneThird), 3, ivec4(0));
}

void tbTessellateTriangle(TbRingPlan plan) {
  if (plan.minimal) {
    tbAddPoint(0u, kFxOne);
    tbAddPoint(0u, 0u);
    tbAddPoint(kFxOne, 0u);
    if (!g_tb_point_mode) tbAddTriangle(0u, 1u, 2u);
    return;
  }
  // Rings inside the boundary: 1 .. point_count / 2 - 1, then an even level's centre point.
  const TbEdgeSpacing inner = plan.inner0;
  const int full_rings = inner.point_count / 2;
  const int rings = full_rings + (inner.odd ? 0 : 1);
  TbRing outside = tbTriangleBoundary(plan);
  for (int r = 1; r < rings; ++r) {
    const TbRing ring = r < full_rings ? tbTriangleInnerRing(inner, r) : tbTriangleCentre();
    if (!g_tb_point_mode) tbStitchRings(r, outside, ring, plan);
    outside = ring;
  }
  // An odd level ends in a ring of three points: one triangle.
  if (inner.odd && !g_tb_point_mode) {
    tbAddTriangle(outside.base, outside.base + uint(outside.start.y),
                  outside.base + uint(outside.start.z));
  }
}

// ---- quad (quad_domain.cpp) ----

// Edges u = 0 and v = 1 run against their axis; edges 0 and 2 run along v, 1 and 3 along u.
bool tbRunsForward(int edge) { return edge == 1 || edge == 2; }
int tbAlongAxis(int edge) { return (edge + 1) & 1; }

// Boundary ring from (0, 1): u = 0 (v falling), v = 0, u = 1, v = 1.
TbRing tbQuadBoundary(TbRingPlan plan) {
  TbRing ring = tbMakeRing(kTbRingClosed, g_tb_point_count, 4, ivec4(0));
  for (int e = 0; e < 4; ++e) {
    const int last = tbPlanOuter(plan, e).point_count - 1;
    ring.count[e] = last;
    const uint fixed_coordinate = (e == 2 || e == 3) ? kFxOne : 0u;
    for (int p = 0; p < last; ++p) {
      const uint t = tbPlacePoint(tbPlanOuter(plan, e), tbRunsForward(e) ? p : last - p);
      if (tbAlongAxis(e) == 1) {
        tbAddPoint(fixed_coordinate, t);
      } else {
        tbAddPoint(t, fixed_coordinate);
      }
    }
  }
  tbCloseRing(ring);
  return ring;
}

TbRing tbQuadInnerRing(TbRingPlan plan, int r) {
  const ivec2 end = ivec2(plan.inner0.point_count - 1 - r, plan.inner1.point_count - 1 - r);
  TbRing ring = tbMakeRing(kTbRingClosed, g_tb_point_count, 4, ivec4(0));
  for (int e = 0; e < 4; ++e) {
    const int along = tbAlongAxis(e);
    const int across = 1 - along;
    ring.count[e] = end[along] - r;
    const uint offset = tbPlacePoint(tbPlanInner(plan, across), e < 2 ? r : end[across]);
    for (int p = r; p < end[along]; ++p) {
      const uint t =
          tbPlacePoint(tbPlanInner(plan, along), tbRunsForward(e) ? p : end[along] - (p - r));
      if (along == 1) {
        tbAddPoint(offset, t);
      } else {
        tbAddPoint(t, offset);
      }
    }
  }
  tbCloseRing(ring);
  return ring;
}

// The middle row (v = 0.5, low u to high u) or column (u = 0.5, high v to low v) of an even
// inside level on the shorter axis.
TbRing tbQuadMiddleLine(TbRingPlan plan, int start, bool row) {
  const TbEdgeSpacing s = row ? plan.inner0 : plan.inner1;
  const int last = s.point_count - 1 - start;
  const TbRing ring = tbMakeRing(row ? kTbRingMiddleRow : kTbRingMiddleColumn, g_tb_point_count,
                                 4, ivec4(last - start + 1, 0, 0, 0));
  for (int p = start; p <= last; ++p) {
    if (row) {
      tbAddPoint(tbPlacePoint(s, p), kFxHalf);
    } else {
      tbAddPoint(kFxHalf, tbPlacePoint(s, last - (p - start)));
    }
  }
  return ring;
}

void tbTessellateQuad(TbRingPlan plan) {
  if (plan.minimal) {
    tbAddPoint(0u, 0u);
    tbAddPoint(kFxOne, 0u);
    tbAddPoint(kFxOne, kFxOne);
    tbAddPoint(0u, kFxOne);
    if (!g_tb_point_mode) {
      tbAddTriangle(0u, 1u, 3u);
      tbAddTriangle(1u, 2u, 3u);
    }
    return;
  }
  const int n_u = plan.inner0.point_count;
  const int n_v = plan.inner1.point_count;
  const bool even_u = !plan.inner0.odd;
  const bool even_v = !plan.inner1.odd;
  const bool u_longer = n_u > n_v;
  const int full_rings = min(n_u, n_v) / 2;

  // Rings inside the boundary: 1 .. full_rings - 1, then the middle line of an even level
  // on the shorter axis.
  const bool middle_row = u_longer && even_v, middle_column = !u_longer && even_u;
  const int rings = full_rings + (middle_row || middle_column ? 1 : 0);
  TbRing last = tbQuadBoundary(plan);
  for (int r = 1; r < rings; ++r) {
    const TbRing ring =
        r < full_rings ? tbQuadInnerRing(plan, r) : tbQuadMiddleLine(plan, full_rings, middle_row);
    if (!g_tb_point_mode) tbStitchRings(r, last, ring, plan);
    last = ring;
  }
  if (g_tb_point_mode) return;
  // An odd inside level on the shorter axis leaves a two-row strip inside the last ring, its
  // long sides stitched straight across with the high side as the inside row.
  if (u_longer && !even_v) {
    const TbRow inside = tbReversedRow(last, 3);
    tbStitch(inside, tbRow(last, 1), tbRegularStrip(false, kTbInsideToOutside, inside));
  } else if (!u_longer && !even_u) {
    const int diagonals = even_v ? kTbInsideToOutside : kTbInsideToOutsideExceptMiddle;
    const TbRow inside = tbReversedRow(last, 2);
    tbStitch(inside, tbRow(last, 0), tbRegularStrip(false, diagonals, inside));
  }
}

// ---- isoline (tessellator.cpp) ----

// Line by line from v = 0, each from u = 0 to u = 1; 2 index words a segment.
void tbTessellateIsoline(TbIsolinePlan plan) {
  const int per_line = plan.detail.point_count;
  for (int line = 0; line < plan.line_count; ++line) {
    const uint v = tbPlacePoint(plan.density, line);
    for (int p = 0; p < per_line; ++p) {
      const uint index = tbAddPoint(tbPlacePoint(plan.detail, p), v);
      if (p > 0 && !g_tb_point_mode) {
        if (TB_TESS_WRITE) {
          tbStoreIndex(2u * g_tb_triangle_count, index - 1u);
          tbStoreIndex(2u * g_tb_triangle_count + 1u, index);
        }
        ++g_tb_triangle_count;
      }
    }
  }
}

// One patch: culling, pow2 rounding, the plan, then the domain. Returns false when culled.
bool tbTessellatePatch(uint domain, uint spacing, vec4 outer, vec2 inner) {
  g_tb_point_count = 0u;
  g_tb_triangle_count = 0u;
  if (spacing == kTbSpacingPow2) tbPow2Levels(domain, outer, inner);
  const int edges = domain == kTbDomainTriangle ? 3 : (domain == kTbDomainQuad ? 4 : 2);
  for (int e = 0; e < edges; ++e) {
    if (!tbAboveZero(outer[e])) return false;
  }
  if (domain == kTbDomainIsoline) {
    tbTessellateIsoline(tbPlanIsoline(spacing, outer));
  } else if (domain == kTbDomainTriangle) {
    tbTessellateTriangle(tbPlanRings(spacing, outer, inner, false));
  } else {
    tbTessellateQuad(tbPlanRings(spacing, outer, inner, true));
  }
  return true;
}

#endif
