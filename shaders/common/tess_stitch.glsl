// The compute tessellator's output and strip triangulation: a GLSL port of
// core/tess/domains.h (point writer, ring rows) and core/tess/stitch.cpp (regular and
// transition strips in the D3D11 reference tessellator's order). The CPU model keeps rows
// as index lists; here a ring is its first point index plus per-edge point counts, and a
// row is (ring, edge, reversed), so index j of a row is computed, never stored.
//
// The including shader declares, before the include:
//   TB_TESS_WRITE            a bool: write points and indices (else only count them)
//   tbStorePoint(n, u, v)    stores patch-local point n at 16.16 (u, v)
//   tbStoreIndex(k, i)       stores index word k (patch-local) = patch-local point i
#ifndef TB_TESS_STITCH_GLSL
#define TB_TESS_STITCH_GLSL

#include "tess_spacing.glsl"

uint g_tb_point_count = 0u;     // points added so far, this patch
uint g_tb_triangle_count = 0u;  // triangles added so far, this patch
bool g_tb_ccw = true;           // layout(ccw): the reference order; else two vertices swap

uint tbAddPoint(uint u, uint v) {
  if (TB_TESS_WRITE) tbStorePoint(g_tb_point_count, u, v);
  return g_tb_point_count++;
}

void tbAddTriangle(uint a, uint b, uint c) {
  if (TB_TESS_WRITE) {
    const uint k = 3u * g_tb_triangle_count;
    tbStoreIndex(k, a);
    tbStoreIndex(k + 1u, g_tb_ccw ? b : c);
    tbStoreIndex(k + 2u, g_tb_ccw ? c : b);
  }
  ++g_tb_triangle_count;
}

// Ring kinds: a closed ring of edges (row e = edge e's points, then the next edge's first
// point); a triangle's centre point (every row is that point); the middle row or column of
// an even quad inside level (quad_domain.cpp middleLine: a line walked forward and back).
const int kTbRingClosed = 0;
const int kTbRingCentre = 1;
const int kTbRingMiddleRow = 2;
const int kTbRingMiddleColumn = 3;

struct TbRing {
  int kind;
  uint base;    // patch-local index of the ring's first point
  int edges;    // 3 or 4 (closed rings)
  ivec4 count;  // closed: points per edge without its end corner; lines: count.x points
  ivec4 start;  // closed: each edge's first point, from base (tbCloseRing)
};

TbRing tbMakeRing(int kind, uint base, int edges, ivec4 count) {
  return TbRing(kind, base, edges, count, ivec4(0));
}

// Fills the edge starts once the counts are known. No loop: lavapipe (Mesa 22.3, gallivm)
// caps the iterations of all loops nested in one outermost loop at 65535 and silently leaves
// the loop, so a kernel keeps its per-triangle work loop-free.
void tbCloseRing(inout TbRing ring) {
  ring.start = ivec4(0, ring.count.x, ring.count.x + ring.count.y,
                     ring.count.x + ring.count.y + ring.count.z);
}

struct TbRow {
  TbRing ring;
  int edge;
  bool reversed;
};

TbRow tbRow(TbRing ring, int edge) { return TbRow(ring, edge, false); }
TbRow tbReversedRow(TbRing ring, int edge) { return TbRow(ring, edge, true); }

// A line ring's row: 0 = its first point, 1 = forward, 2 = its last point, 3 = backward
// (the middle row); the middle column is the same shifted by one edge.
int tbLineRowShape(TbRow row) {
  return row.ring.kind == kTbRingMiddleRow ? row.edge : (row.edge + 1) & 3;
}

int tbRowLength(TbRow row) {
  if (row.ring.kind == kTbRingCentre) return 1;
  if (row.ring.kind == kTbRingClosed) return row.ring.count[row.edge] + 1;
  return (tbLineRowShape(row) & 1) == 1 ? row.ring.count.x : 1;
}

// Patch-local point index of entry j of the row.
uint tbRowAt(TbRow row, int j) {
  if (row.reversed) j = tbRowLength(row) - 1 - j;
  const TbRing ring = row.ring;
  if (ring.kind == kTbRingCentre) return ring.base;
  if (ring.kind == kTbRingClosed) {
    const int offset = ring.start[row.edge];
    if (j < ring.count[row.edge]) return ring.base + uint(offset + j);
    return row.edge + 1 == ring.edges ? ring.base : ring.base + uint(offset + j);
  }
  const int last = ring.count.x - 1;
  switch (tbLineRowShape(row)) {
    case 0:
      return ring.base;
    case 1:
      return ring.base + uint(j);
    case 2:
      return ring.base + uint(last);
    default:
      return ring.base + uint(last - j);
  }
}

// stitch.cpp StripWalker: each step emits one triangle and advances one row.
struct TbWalk {
  TbRow inside;
  TbRow outside;
  int in_pos;
  int out_pos;
};

uint tbIn(TbWalk w, int d) { return tbRowAt(w.inside, w.in_pos + d); }
uint tbOut(TbWalk w, int d) { return tbRowAt(w.outside, w.out_pos + d); }

void tbAdvanceOutside(inout TbWalk w) {
  tbAddTriangle(tbOut(w, 0), tbOut(w, 1), tbIn(w, 0));
  ++w.out_pos;
}
void tbAdvanceInside(inout TbWalk w) {
  tbAddTriangle(tbIn(w, 0), tbOut(w, 0), tbIn(w, 1));
  ++w.in_pos;
}
void tbQuadDiagonalFromInside(inout TbWalk w, bool outside_first) {
  if (outside_first) {
    tbAddTriangle(tbOut(w, 0), tbOut(w, 1), tbIn(w, 0));
  } else {
    tbAddTriangle(tbIn(w, 0), tbOut(w, 0), tbOut(w, 1));
  }
  tbAddTriangle(tbIn(w, 0), tbOut(w, 1), tbIn(w, 1));
  ++w.in_pos;
  ++w.out_pos;
}
void tbQuadDiagonalFromOutside(inout TbWalk w) {
  tbAddTriangle(tbOut(w, 0), tbIn(w, 1), tbIn(w, 0));
  tbAddTriangle(tbOut(w, 0), tbOut(w, 1), tbIn(w, 1));
  ++w.in_pos;
  ++w.out_pos;
}

// stitch.h Diagonals.
const int kTbInsideToOutside = 0;
const int kTbInsideToOutsideExceptMiddle = 1;
const int kTbMirrored = 2;

// stitch.cpp stitchRegular: rows of equal length, or two apart (trapezoid).
void tbStitchRegular(bool trapezoid, int diagonals, TbRow inside, TbRow outside) {
  TbWalk w = TbWalk(inside, outside, 0, 0);
  const int inside_length = tbRowLength(inside);
  const int quads = inside_length - 1;
  if (trapezoid) tbAdvanceOutside(w);
  if (diagonals == kTbInsideToOutside) {
    for (int q = 0; q < quads; ++q) tbQuadDiagonalFromInside(w, false);
  } else if (diagonals == kTbInsideToOutsideExceptMiddle) {
    const int half_quads = inside_length / 2 - 1;
    for (int q = 0; q < half_quads; ++q) tbQuadDiagonalFromInside(w, true);
    tbQuadDiagonalFromOutside(w);
    for (int q = half_quads + 1; q < quads; ++q) tbQuadDiagonalFromInside(w, true);
  } else {
    const int half_quads = inside_length / 2;
    int q = 0;
    for (; q < half_quads; ++q) tbQuadDiagonalFromOutside(w);
    for (; q < quads; ++q) tbQuadDiagonalFromInside(w, false);
  }
  if (trapezoid) tbAdvanceOutside(w);
}

// stitch.cpp rulerPosition: the half-edge position step 1..32 of the ruler order reveals.
int tbRulerPosition(int step) {
  if (step == 1) return 32;
  const int k = step - 1;
  const int s = findLSB(k);
  return (1 << (4 - s)) + (k >> (s + 1));
}

// stitch.cpp stitchTransition: the first ring in, rows of any lengths, in ruler order.
void tbStitchTransition(TbRow inside, TbEdgeSpacing inside_spacing, TbRow outside,
                        TbEdgeSpacing outside_spacing) {
  TbWalk w = TbWalk(inside, outside, 0, 0);
  const bool inside_odd = inside_spacing.odd;
  const bool outside_odd = outside_spacing.odd;
  const int inside_half = inside_spacing.half_points - (inside_odd ? 1 : 0);
  const int outside_half = outside_spacing.half_points - (outside_odd ? 1 : 0);

  if (outside_half > 0) tbAdvanceOutside(w);
  for (int step = 1; step <= 32; ++step) {
    const int position = tbRulerPosition(step);
    if (position < inside_half) tbAdvanceInside(w);
    if (position < outside_half) tbAdvanceOutside(w);
  }
  if (inside_odd && outside_odd) {
    tbAddTriangle(tbIn(w, 0), tbOut(w, 0), tbIn(w, 1));
    tbAddTriangle(tbIn(w, 1), tbOut(w, 0), tbOut(w, 1));
    ++w.in_pos;
    ++w.out_pos;
  } else if (outside_odd) {
    tbAddTriangle(tbIn(w, 0), tbOut(w, 0), tbOut(w, 1));
    ++w.out_pos;
  } else if (inside_odd) {
    tbAdvanceInside(w);
  }
  for (int step = 32; step >= 1; --step) {
    const int position = tbRulerPosition(step);
    if (position < outside_half) tbAdvanceOutside(w);
    if (position < inside_half) tbAdvanceInside(w);
  }
  if (outside_half > 0) tbAdvanceOutside(w);
}

// Stitches ring `inside` (ring index r >= 1) to the ring outside it, edge by edge: the
// first ring by the transition rule, the others as mirrored trapezoids. Edge e's inside
// spacing: the triangle's one inside level; a quad's along that edge (edges 0 and 2 run
// along v, 1 and 3 along u).
void tbStitchRings(int r, TbRing outside, TbRing inside, TbRingPlan plan) {
  for (int e = 0; e < outside.edges; ++e) {
    if (r == 1) {
      const TbEdgeSpacing along = (outside.edges == 4 && (e & 1) == 0) ? plan.inner1 : plan.inner0;
      tbStitchTransition(tbRow(inside, e), along, tbRow(outside, e), tbPlanOuter(plan, e));
    } else {
      tbStitchRegular(true, kTbMirrored, tbRow(inside, e), tbRow(outside, e));
    }
  }
}

#endif
