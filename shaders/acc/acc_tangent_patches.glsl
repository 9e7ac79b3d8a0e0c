// acc.tesc invocation 0's work once every point is done, shared with the compute path
// (acc.comp): the two tangent patches (tu_out, tv_out) from b_out and the corner points'
// tangents. Included inside a function.
  vec3 b[16];
  for (int i = 0; i < 16; ++i) b[i] = b_out[i];
  vec3 tu[12], tv[12];
  for (int r = 0; r < 4; ++r) {
    for (int i = 0; i < 3; ++i) tu[3 * r + i] = (b[4 * r + i + 1] - b[4 * r + i]) * 3.0;
  }
  for (int r = 0; r < 3; ++r) {
    for (int i = 0; i < 4; ++i) tv[4 * r + i] = (b[4 * (r + 1) + i] - b[4 * r + i]) * 3.0;
  }
  if (kTangentPatches != 0u) {
    Corner c[4] = Corner[](loadCorner(0u), loadCorner(1u), loadCorner(2u), loadCorner(3u));
    float cosine[4];
    for (uint k = 0u; k < 4u; ++k) cosine[k] = W(c[k], 12u);
    // Limit tangents at interior corners (boundary corners keep the geometry's); corner k's
    // point is invocation 0, 3, 15, 12.
    if (!c[0].boundary) { tu[0] = tangent_next_out[0]; tv[0] = tangent_prev_out[0]; }
    if (!c[1].boundary) { tu[2] = -tangent_prev_out[3]; tv[3] = tangent_next_out[3]; }
    if (!c[2].boundary) { tu[11] = -tangent_next_out[15]; tv[11] = -tangent_prev_out[15]; }
    if (!c[3].boundary) { tu[9] = tangent_prev_out[12]; tv[8] = -tangent_next_out[12]; }
    vec3 x1, x2;
    crossTangents(cosine[0], cosine[1], tu[0], tu[1], tu[2], (b[5] - b[1]) * 3.0, (b[6] - b[2]) * 3.0, x1, x2);
    tv[1] = x1; tv[2] = x2;
    crossTangents(cosine[1], cosine[2], tv[3], tv[7], tv[11], (b[6] - b[7]) * 3.0, (b[10] - b[11]) * 3.0, x1, x2);
    tu[5] = -x1; tu[8] = -x2;
    crossTangents(cosine[3], cosine[2], tu[9], tu[10], tu[11], (b[9] - b[13]) * 3.0, (b[10] - b[14]) * 3.0, x1, x2);
    tv[9] = -x1; tv[10] = -x2;
    crossTangents(cosine[0], cosine[3], tv[0], tv[4], tv[8], (b[5] - b[4]) * 3.0, (b[9] - b[8]) * 3.0, x1, x2);
    tu[3] = x1; tu[6] = x2;
  }
  for (int i = 0; i < 12; ++i) {
    tu_out[i] = tu[i];
    tv_out[i] = tv[i];
  }
