#version 460
// Phong tessellation (Boubekeur & Alexa 2008): one invocation reads the triangle's corners
// by index and normalises the normals (phong_build.glsl, shared with the compute path); the
// `edge` variant also reads seed 003's per-edge normals.
#extension GL_GOOGLE_include_directive : require
#include "patch_program_tcs.glsl"
#define TB_SURFACE_BUILD
#include "phong_surface.glsl"

layout(vertices = 1) out;

layout(location = 0) patch out vec3 tb_phong_p[3];
layout(location = 3) patch out vec3 tb_phong_n[3];
layout(location = 6) patch out vec3 tb_phong_edge_n[6];
layout(location = 12) patch out uvec3 tb_phong_perm;

#define TB_BUILD_FUNCTION void main()  // the body is main's
#define TB_BUILD_EPILOGUE tbWriteHarnessLevels();
#include "phong_build.glsl"
