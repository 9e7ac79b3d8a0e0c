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
// ends a shader's loops silently after 65,535 iterations between them all
// (LP_MAX_TGSI_LOOP_ITERATIONS), so the per-triangle work stays loop-free.
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

// A strip between two rows is a sequence of triangles, each a template: three vertices, each
// (row, step) in 2 bits (bit 1: the outside row, bit 0: one past its cursor), then which
// cursors advance (bit 6: inside, bit 7: outside). The stitch.cpp walker's moves:
const uint kTbI0 = 0u, kTbI1 = 1u, kTbO0 = 2u, kTbO1 = 3u;
const uint kTbNone = 0xffffffffu;
const uint kTbAdvanceOutside = kTbO0 | kTbO1 << 2 | kTbI0 << 4 | 2u << 6;
const uint kTbAdvanceInside = kTbI0 | kTbO0 << 2 | kTbI1 << 4 | 1u << 6;
// Quads as two templates each: split along inside -> outside + 1 (inside triangle first, or
// outside first as in the odd centre strip), or along outside -> inside + 1.
const uint kTbFromInsideA = kTbI0 | kTbO0 << 2 | kTbO1 << 4;
const uint kTbFromInsideB = kTbI0 | kTbO1 << 2 | kTbI1 << 4 | 3u << 6;
const uint kTbFromInsideOutsideFirstA = kTbO0 | kTbO1 << 2 | kTbI0 << 4;
const uint kTbFromOutsideA = kTbO0 | kTbI1 << 2 | kTbI0 << 4;
const uint kTbFromOutsideB = kTbO0 | kTbO1 << 2 | kTbI1 << 4 | 3u << 6;
// The middle of a transition: both odd (a quad), the outside odd (one triangle).
const uint kTbMiddleOddA = kTbI0 | kTbO0 << 2 | kTbI1 << 4;
const uint kTbMiddleOddB = kTbI1 | kTbO0 << 2 | kTbO1 << 4 | 3u << 6;
const uint kTbMiddleOutsideOdd = kTbI0 | kTbO0 << 2 | kTbO1 << 4 | 2u << 6;

// stitch.h Diagonals.
const int kTbInsideToOutside = 0;
const int kTbInsideToOutsideExceptMiddle = 1;
const int kTbMirrored = 2;

// One strip: stitch.cpp stitchRegular (transition false) or stitchTransition (true).
struct TbStrip {
  bool transition;
  bool trapezoid;  // regular: rows two apart, one corner triangle at each end
  int diagonals;   // regular
  int inside_length;
  int inside_half;   // transition: positions on each half before the middle
  int outside_half;  // transition
  bool inside_odd;   // transition
  bool outside_odd;  // transition
};

TbStrip tbRegularStrip(bool trapezoid, int diagonals, TbRow inside) {
  return TbStrip(false, trapezoid, diagonals, tbRowLength(inside), 0, 0, false, false);
}

TbStrip tbTransitionStrip(TbEdgeSpacing inside, TbEdgeSpacing outside) {
  return TbStrip(true, false, 0, 0, inside.half_points - (inside.odd ? 1 : 0),
                 outside.half_points - (outside.odd ? 1 : 0), inside.odd, outside.odd);
}

// stitch.cpp rulerPosition: the half-edge position step 1..32 of the ruler order reveals.
int tbRulerPosition(int step) {
  if (step == 1) return 32;
  const int k = step - 1;
  const int s = findLSB(k);
  return (1 << (4 - s)) + (k >> (s + 1));
}

int tbStripSlots(TbStrip strip) { return strip.transition ? 132 : 2 * strip.inside_length; }

// The template of slot `slot` of a regular strip: the opening corner, two per quad, the
// closing corner.
uint tbRegularSlot(TbStrip strip, int slot) {
  const int quads = strip.inside_length - 1;
  if (slot == 0 || slot == 2 * quads + 1) return strip.trapezoid ? kTbAdvanceOutside : kTbNone;
  const int q = (slot - 1) / 2;
  const bool first = ((slot - 1) & 1) == 0;
  bool from_outside = false, outside_first = false;
  if (strip.diagonals == kTbInsideToOutsideExceptMiddle) {
    from_outside = q == strip.inside_length / 2 - 1;
    outside_first = !from_outside;
  } else if (strip.diagonals == kTbMirrored) {
    from_outside = q < strip.inside_length / 2;
  }
  if (from_outside) return first ? kTbFromOutsideA : kTbFromOutsideB;
  if (!first) return kTbFromInsideB;
  return outside_first ? kTbFromInsideOutsideFirstA : kTbFromInsideA;
}

// The template of slot `slot` of a transition strip: the opening corner, the first half in
// ruler order (inside then outside per step), the middle (two slots), the second half
// (steps reversed, outside then inside), the closing corner.
uint tbTransitionSlot(TbStrip strip, int slot) {
  if (slot == 0 || slot == 131) return strip.outside_half > 0 ? kTbAdvanceOutside : kTbNone;
  if (slot == 65 || slot == 66) {
    if (strip.inside_odd && strip.outside_odd) return slot == 65 ? kTbMiddleOddA : kTbMiddleOddB;
    if (slot == 66) return kTbNone;
    if (strip.outside_odd) return kTbMiddleOutsideOdd;
    return strip.inside_odd ? kTbAdvanceInside : kTbNone;
  }
  const bool second_half = slot > 66;
  const int k = second_half ? slot - 67 : slot - 1;
  const int position = tbRulerPosition(second_half ? 32 - k / 2 : k / 2 + 1);
  const bool inside_move = ((k & 1) == 0) != second_half;
  if (inside_move) return position < strip.inside_half ? kTbAdvanceInside : kTbNone;
  return position < strip.outside_half ? kTbAdvanceOutside : kTbNone;
}

// Emits the strip between two rows, from their starts. One emitting site for every strip
// kind keeps the inlined kernel small (lavapipe compiles it at pipeline creation).
void tbStitch(TbRow inside, TbRow outside, TbStrip strip) {
  ivec2 cursor = ivec2(0);  // inside, outside
  const int slots = tbStripSlots(strip);
  for (int slot = 0; slot < slots; ++slot) {
    const uint t = strip.transition ? tbTransitionSlot(strip, slot) : tbRegularSlot(strip, slot);
    if (t == kTbNone) continue;
    uint v[3];
    for (int i = 0; i < 3; ++i) {
      const uint code = (t >> (2 * i)) & 3u;
      const bool out_row = (code & 2u) != 0u;
      const int j = (out_row ? cursor.y : cursor.x) + int(code & 1u);
      v[i] = tbRowAt(out_row ? outside : inside, j);
    }
    tbAddTriangle(v[0], v[1], v[2]);
    cursor += ivec2((t >> 6) & 1u, (t >> 7) & 1u);
  }
}

// Stitches ring `inside` (ring index r >= 1) to the ring outside it, edge by edge: the
// first ring by the transition rule, the others as mirrored trapezoids. Edge e's inside
// spacing: the triangle's one inside level; a quad's along that edge (edges 0 and 2 run
// along v, 1 and 3 along u).
void tbStitchRings(int r, TbRing outside, TbRing inside, TbRingPlan plan) {
  for (int e = 0; e < outside.edges; ++e) {
    const TbEdgeSpacing along = (outside.edges == 4 && (e & 1) == 0) ? plan.inner1 : plan.inner0;
    const TbStrip strip = r == 1 ? tbTransitionStrip(along, tbPlanOuter(plan, e))
                                 : tbRegularStrip(true, kTbMirrored, tbRow(inside, e));
    tbStitch(tbRow(inside, e), tbRow(outside, e), strip);
  }
}

#endif
