#version 460
// gregory_acc TCS for triangles: 15 control points per patch, P, Ep, Em and the two
// quartic interior points of each corner (gregory_stencil_tcs.glsl).
#extension GL_GOOGLE_include_directive : require
#define TB_GREGORY_POINTS 15
#include "gregory_stencil_tcs.glsl"
