#version 460
// Curved PN triangles (Vlachos et al. 2001): one invocation builds the 10 geometry
// control points and 6 normal coefficients (pn_build.glsl, shared with the compute path).
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#define TB_SURFACE_BUILD
#include "pn_surface.glsl"

layout(vertices = 1) out;

layout(location = 0) patch out vec3 tb_pn_b[10];  // corners 0..2, edge e end k at 3 + 2e + k, centre 9
layout(location = 10) patch out vec3 tb_pn_n[6];   // corner normals 0..2, edge normals 3..5
layout(location = 16) patch out uvec3 tb_pn_perm;  // canonical label -> gl_TessCoord component

#define TB_BUILD_FUNCTION void main()  // the body is main's
#define TB_BUILD_EPILOGUE tbWriteHarnessLevels();
#include "pn_build.glsl"
