#version 460
// gregory_acc TCS for quads: 20 Gregory control points per patch (gregory_stencil_tcs.glsl).
#extension GL_GOOGLE_include_directive : require
#define TB_GREGORY_POINTS 20
#include "gregory_stencil_tcs.glsl"
