// What phong.tesc's main runs, shared with the compute path (phong.comp): reads the
// triangle's corners by index (canonical order, see techniques/phong/phong.cpp), normalises
// the normals as phong.cpp's evaluateFloat does and writes tb_phong_p, tb_phong_n,
// tb_phong_edge_n and tb_phong_perm (phong_surface.glsl). Defines the function
// TB_BUILD_FUNCTION names (with its return type): void main() in the TCS, ending in
// TB_BUILD_EPILOGUE; on the compute path the surface's builder, whose locals
// TB_BUILD_PROLOGUE declares and whose return TB_BUILD_EPILOGUE is.
#ifndef TB_PHONG_BUILD_GLSL
#define TB_PHONG_BUILD_GLSL

TB_BUILD_FUNCTION {
#ifdef TB_BUILD_PROLOGUE
  TB_BUILD_PROLOGUE
#endif
  const uint base = tbPatchIndex() * kTbPhongRecordWords;
  for (uint i = 0u; i < 3u; ++i) {
    tb_phong_p[i] = positions[records[base + kTbPhongPosition + i]].xyz;
    tb_phong_n[i] = tbNormalize(normals[records[base + kTbPhongNormal + i]].xyz);
  }
  for (uint k = 0u; k < 6u; ++k) {
    tb_phong_edge_n[k] = tbNormalize(normals[records[base + kTbPhongEdgeNormal + k]].xyz);
  }
  tb_phong_perm = uvec3(records[base + 0u], records[base + 1u], records[base + 2u]);
  TB_BUILD_EPILOGUE
}

#endif
