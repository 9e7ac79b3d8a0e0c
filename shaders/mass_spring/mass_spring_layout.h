// The mass-spring passes' records, for shaders/mass_spring/*.comp and
// techniques/mass_spring/mass_spring_gpu.cpp alike (shaders/common/layout/tb_layout.h).
#ifndef TB_MASS_SPRING_LAYOUT_H
#define TB_MASS_SPRING_LAYOUT_H

#include "../common/layout/tb_layout.h"

#ifdef __cplusplus
namespace tb::gpu::layout::mass_spring {
using layout::uint;
using layout::vec4;
#endif

// A spring in colour-major order (gs_colour*.comp); a, b may carry kAnchorBit.
struct Spring {
  uint a;
  uint b;
  float rest;
  float weight;
};
// One end of a spring, per vertex (jacobi.comp).
struct End {
  uint other;
  float rest;
  float weight;
  uint pad;
};
// A render vertex's tetrahedron binding (render.comp).
struct Binding {
  uint v0;
  uint v1;
  uint v2;
  float w0;
  float w1;
  float w2;
  float volume;
  uint pad;
};
// A blast (verlet.comp): centre xyz, radius, speed and the step it fires on.
struct Blast {
  vec4 centre;
  float radius;
  float speed;
  uint step;
  uint pad;
};

#ifdef __cplusplus
static_assert(sizeof(Spring) == 16 && sizeof(End) == 16 && sizeof(Binding) == 32);
static_assert(sizeof(Blast) == 32 && offsetof(Blast, radius) == 16);
}  // namespace tb::gpu::layout::mass_spring
#endif

#endif
