// SPIR-V compiled at build time from the GLSL under shaders/ (see shaders/CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace tb::gpu {

// relative_path is relative to shaders/, e.g. "gpu/tess_capture.tese". Returns the
// SPIR-V words, or an empty span when no such shader was embedded.
std::span<const uint32_t> embeddedShader(std::string_view relative_path);

// Every embedded shader's relative path, sorted.
std::vector<std::string_view> embeddedShaderPaths();

}  // namespace tb::gpu
