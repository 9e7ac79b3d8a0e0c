// One text for a block both GLSL (std430) and C++ read: glslang preprocesses a layout header
// to the very declarations it replaced; C++ gets structs in tb::gpu::layout with the std430
// sizes and offsets, which the headers static_assert and LayoutSelfTest checks against SPIR-V.
#ifndef TB_LAYOUT_H
#define TB_LAYOUT_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tb::gpu::layout {

using uint = uint32_t;
struct alignas(8) uvec2 {
  uint32_t x, y;
};
struct alignas(16) vec4 {
  float x, y, z, w;
};
struct alignas(16) uvec4 {
  uint32_t x, y, z, w;
};
struct alignas(16) mat4 {
  float m[16];  // column-major, as GLSL's
};

// Appends `block`'s bytes to `words` (the upload the shader reads).
template <typename T>
void appendWords(std::vector<uint32_t>& words, const T& block) {
  static_assert(sizeof(T) % 4 == 0);
  const size_t at = words.size();
  words.resize(at + sizeof(T) / 4);
  std::memcpy(words.data() + at, &block, sizeof(T));
}

// The 32-bit words of a block type.
template <typename T>
inline constexpr size_t kWordsOf = sizeof(T) / 4;

}  // namespace tb::gpu::layout

#define TB_LAYOUT_NAMESPACE_BEGIN namespace tb::gpu::layout {
#define TB_LAYOUT_NAMESPACE_END }
// A storage block: GLSL's `layout(std430, set, binding) [access] buffer Name`, C++'s struct.
#ifndef TB_LAYOUT_TEST_CPP_FIELD
#define TB_BUFFER(name, set_, binding_) struct name
#else  // Layout.CppOnlyFieldFailsToBuild: a C++-only leading field the static_asserts catch
namespace tb::gpu::layout {
struct TbCppOnlyField {
  float cpp_only_field;
};
}  // namespace tb::gpu::layout
#define TB_BUFFER(name, set_, binding_) struct name : TbCppOnlyField
#endif
#define TB_READONLY_BUFFER(name, set_, binding_) TB_BUFFER(name, set_, binding_)
#define TB_WRITEONLY_BUFFER(name, set_, binding_) TB_BUFFER(name, set_, binding_)
#define TB_INSTANCE(name)
// A trailing runtime array: GLSL's `type name[]`; C++ has none (the block is its fixed part).
#define TB_RUNTIME_ARRAY(type, name) static constexpr int name##_is_runtime_array = 1
#else
#define TB_LAYOUT_NAMESPACE_BEGIN
#define TB_LAYOUT_NAMESPACE_END
#define TB_BUFFER(name, set_, binding_) layout(std430, set = set_, binding = binding_) buffer name
#define TB_READONLY_BUFFER(name, set_, binding_) \
  layout(std430, set = set_, binding = binding_) readonly buffer name
#define TB_WRITEONLY_BUFFER(name, set_, binding_) \
  layout(std430, set = set_, binding = binding_) writeonly buffer name
#define TB_INSTANCE(name) name
#define TB_RUNTIME_ARRAY(type, name) type name[]
#endif

#endif
