#version 460
// One control point per patch; the TCS needs no data from it.
void main() { gl_Position = vec4(0.0); }
