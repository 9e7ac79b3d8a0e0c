#version 460
// Throughput probe: the cheapest TES that still depends on gl_TessCoord.
// Execution modes are rewritten per pipeline, as for tess_capture.tese.
layout(triangles, equal_spacing, ccw) in;

void main() { gl_Position = vec4(gl_TessCoord, 1.0); }
