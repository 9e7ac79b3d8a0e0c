// SPIR-V compiled at build time from the GLSL under shaders/ (see shaders/CMakeLists.txt).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tb::gpu {

// relative_path is relative to shaders/, e.g. "gpu/tess_capture.tese", or a name a
// plug-in registered ("flat/flat.tese"). Returns the SPIR-V words, or an empty span when
// no such shader was embedded or registered.
std::span<const uint32_t> embeddedShader(std::string_view relative_path);

// Every embedded and registered shader's path, sorted.
std::vector<std::string_view> embeddedShaderPaths();

// Adds a plug-in's shader (techniques/plugin.h, PluginHost::addShader) under `path`;
// false, and nothing added, when the path is taken. Called while loading plug-ins, before
// any run: lookups do not lock.
bool registerShader(std::string path, std::vector<uint32_t> words);

// True when `relative_path` is a plug-in's shader (registerShader), not one built in.
bool isRegisteredShader(std::string_view relative_path);

}  // namespace tb::gpu
