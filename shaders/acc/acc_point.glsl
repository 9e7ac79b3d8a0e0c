// One acc.tesc invocation's work, shared with the compute path (acc.comp): geometry control
// point TB_INVOCATION (gl_InvocationID there) from its corner vertex's 1-ring into b_out,
// and for a corner point of an interior corner its limit tangents into tangent_next_out and
// tangent_prev_out. Included inside a function, so the TCS compiles as before it was shared.
  const uint j = uint(TB_INVOCATION);
  const Corner owner = loadCorner(kOwnerCorner[j]);
  b_out[TB_INVOCATION] = controlPoint(owner, kOwnerRole[j]);
  if (kTangentPatches != 0u && kOwnerRole[j] == 0u && !owner.boundary) {
    tangent_next_out[TB_INVOCATION] = cornerTangent(owner, owner.slot);
    tangent_prev_out[TB_INVOCATION] = cornerTangent(owner, owner.slot + 1u);
  }
