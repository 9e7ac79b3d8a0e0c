// The body of phong.tesc's main, shared with the compute path (phong.comp): reads the
// triangle's corners by index (canonical order, see techniques/phong/phong.cpp), normalises
// the normals as phong.cpp's evaluateFloat does and writes tb_phong_p, tb_phong_n,
// tb_phong_edge_n and tb_phong_perm (phong_surface.glsl). Included inside a function.
  const uint base = tbPatchIndex() * 15u;
  for (uint i = 0u; i < 3u; ++i) {
    tb_phong_p[i] = positions[records[base + 3u + i]].xyz;
    tb_phong_n[i] = tbNormalize(normals[records[base + 6u + i]].xyz);
  }
  for (uint k = 0u; k < 6u; ++k) {
    tb_phong_edge_n[k] = tbNormalize(normals[records[base + 9u + k]].xyz);
  }
  tb_phong_perm = uvec3(records[base + 0u], records[base + 1u], records[base + 2u]);
