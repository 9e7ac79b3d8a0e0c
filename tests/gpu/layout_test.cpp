// The shared host/device layouts (shaders/common/layout/*.h): each block's member offsets and
// array strides read from the embedded SPIR-V (OpMemberDecorate Offset, OpDecorate
// ArrayStride, OpName / OpMemberName, Binding) equal the C++ structs' offsetof / sizeof. The
// control, gpu/test_layout_mismatch.comp (a field added on the GLSL side only), must be
// rejected by the same comparison. A field added on the C++ side only fails to build: the
// Layout.CppOnlyFieldFailsToBuild ctest (tests/gpu/CMakeLists.txt).
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "shaders/common/layout/capture_layout.h"
#include "shaders/common/layout/cull_layout.h"
#include "shaders/common/layout/displace_layout.h"
#include "shaders/common/layout/factor_layout.h"
#include "shaders/common/layout/levels_layout.h"
#include "shaders/embedded_shaders.h"
#include "shaders/mass_spring/mass_spring_layout.h"

namespace tb::gpu::layout {
namespace {

// SPIR-V 1.6 opcodes and decorations.
constexpr uint32_t kOpName = 5, kOpMemberName = 6, kOpTypeArray = 28, kOpTypeRuntimeArray = 29,
                   kOpTypeStruct = 30, kOpTypePointer = 32, kOpVariable = 59, kOpDecorate = 71,
                   kOpMemberDecorate = 72;
constexpr uint32_t kArrayStride = 6, kBinding = 33, kOffset = 35;

std::string literal(const uint32_t* w) { return reinterpret_cast<const char*>(w); }

// What the comparison needs of a module: names, member offsets, strides, bindings.
struct Reflection {
  std::map<uint32_t, std::string> names;
  std::map<std::pair<uint32_t, uint32_t>, std::string> member_names;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> offsets;
  std::map<uint32_t, std::vector<uint32_t>> struct_members;
  std::map<uint32_t, uint32_t> stride, element, binding, pointee, variable_type;

  explicit Reflection(std::span<const uint32_t> spirv) {
    for (size_t i = 5; i < spirv.size(); i += spirv[i] >> 16) {
      const uint32_t op = spirv[i] & 0xffff, count = spirv[i] >> 16;
      const uint32_t* w = &spirv[i];
      if (op == kOpName) names[w[1]] = literal(w + 2);
      if (op == kOpMemberName) member_names[{w[1], w[2]}] = literal(w + 3);
      if (op == kOpMemberDecorate && w[3] == kOffset) offsets[{w[1], w[2]}] = w[4];
      if (op == kOpDecorate && w[2] == kArrayStride) stride[w[1]] = w[3];
      if (op == kOpDecorate && w[2] == kBinding) binding[w[1]] = w[3];
      if (op == kOpTypeArray || op == kOpTypeRuntimeArray) element[w[1]] = w[2];
      if (op == kOpTypePointer) pointee[w[1]] = w[3];
      if (op == kOpVariable) variable_type[w[2]] = w[1];
      if (op == kOpTypeStruct) struct_members[w[1]].assign(w + 2, w + count);
    }
  }
  // The laid-out struct named `name` (glslang may also emit an unlaid-out copy).
  uint32_t structNamed(const std::string& name) const {
    for (const auto& [id, members] : struct_members) {
      const auto n = names.find(id);
      if (n != names.end() && n->second == name && offsets.count({id, 0})) return id;
    }
    return 0;
  }
};

// One C++ member: its offset and, for an array, its element size (0 otherwise).
struct CppMember {
  std::string name;
  size_t offset, stride;
};
template <typename M>
constexpr size_t strideOf() {
  return std::is_array_v<M> ? sizeof(std::remove_extent_t<M>) : 0;
}
#define TB_MEMBER(T, m) \
  CppMember { #m, offsetof(T, m), strideOf < decltype(T::m)>() }

struct CppBlock {
  std::string name;
  size_t size;  // sizeof: the ArrayStride of an array of it (checked for a plain struct)
  std::vector<CppMember> members;  // a block's runtime array: offset sizeof, its stride
  int binding = -1;                // a block's (-1: a plain struct)
};

void compareMembers(const Reflection& r, uint32_t id, const CppBlock& block,
                    std::vector<std::string>* out) {
  std::map<std::string, const CppMember*> cpp;
  for (const CppMember& m : block.members) cpp[m.name] = &m;
  const std::vector<uint32_t>& types = r.struct_members.at(id);
  for (uint32_t m = 0; m < types.size(); ++m) {
    const auto name = r.member_names.find({id, m});
    const std::string member = name == r.member_names.end() ? std::to_string(m) : name->second;
    const std::string where = block.name + "." + member;
    const auto it = cpp.find(member);
    if (it == cpp.end()) {
      out->push_back(where + ": in the shader only");
      continue;
    }
    const auto offset = r.offsets.find({id, m});
    if (offset == r.offsets.end() || offset->second != it->second->offset) {
      out->push_back(where + ": offset " +
                     (offset == r.offsets.end() ? "?" : std::to_string(offset->second)) +
                     " in SPIR-V, " + std::to_string(it->second->offset) + " in C++");
    }
    const auto stride = r.stride.find(types[m]);
    const size_t spirv_stride = stride == r.stride.end() ? 0 : stride->second;
    if (spirv_stride != it->second->stride) {
      out->push_back(where + ": array stride " + std::to_string(spirv_stride) + " in SPIR-V, " +
                     std::to_string(it->second->stride) + " in C++");
    }
    cpp.erase(it);
  }
  for (const auto& [member, m] : cpp) out->push_back(block.name + "." + member + ": in C++ only");
}

// The mismatches between `block` and the struct of that name in `spirv`; empty when equal.
std::vector<std::string> compare(std::span<const uint32_t> spirv, const CppBlock& block) {
  if (spirv.empty()) return {"no such shader"};
  const Reflection r(spirv);
  const uint32_t id = r.structNamed(block.name);
  if (id == 0) return {block.name + ": no laid-out struct of that name"};
  std::vector<std::string> out;
  compareMembers(r, id, block, &out);
  bool sized = block.binding >= 0;
  for (const auto& [array, element] : r.element) {
    if (element != id || !r.stride.count(array)) continue;
    sized = true;
    if (r.stride.at(array) != block.size) {
      out.push_back(block.name + ": array stride " + std::to_string(r.stride.at(array)) +
                    " in SPIR-V, sizeof " + std::to_string(block.size) + " in C++");
    }
  }
  if (!sized) out.push_back(block.name + ": no array of it to size it by");
  if (block.binding < 0) return out;
  bool bound = false;
  for (const auto& [variable, pointer] : r.variable_type) {
    const auto type = r.pointee.find(pointer);
    if (type == r.pointee.end() || type->second != id) continue;
    bound = true;
    const auto b = r.binding.find(variable);
    if (b == r.binding.end() || int(b->second) != block.binding) {
      out.push_back(block.name + ": bound at " +
                    (b == r.binding.end() ? "?" : std::to_string(b->second)) +
                    ", the C++ name says " + std::to_string(block.binding));
    }
  }
  if (!bound) out.push_back(block.name + ": no variable of it");
  return out;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& line : lines) s += line + "\n";
  return s;
}

CppBlock cullParams() {
  using T = TbCullParamsBlock;
  return {
      "TbCullParamsBlock",
      sizeof(T),
      {TB_MEMBER(T, planes), TB_MEMBER(T, eye), TB_MEMBER(T, global_margin), TB_MEMBER(T, policy),
       TB_MEMBER(T, pad0), TB_MEMBER(T, pad1), TB_MEMBER(T, chord_factors)},
      kBindingCullParams};
}

CppBlock cullPatch() {
  using T = TbCullPatch;
  return {"TbCullPatch",
          sizeof(T),
          {TB_MEMBER(T, corner_position), TB_MEMBER(T, corner_normal), TB_MEMBER(T, cone),
           TB_MEMBER(T, header), TB_MEMBER(T, tangent), TB_MEMBER(T, tangent_chord),
           TB_MEMBER(T, hull)}};
}

CppBlock factorParams() {
  using T = TbFactorParamsBlock;
  return {"TbFactorParamsBlock",
          sizeof(T),
          {TB_MEMBER(T, view_projection),
           TB_MEMBER(T, eye),
           TB_MEMBER(T, viewport_height_px),
           TB_MEMBER(T, projection_y_scale),
           TB_MEMBER(T, target),
           TB_MEMBER(T, pixel_scale),
           TB_MEMBER(T, min_scale),
           TB_MEMBER(T, roundness_span),
           TB_MEMBER(T, policy),
           TB_MEMBER(T, flags),
           TB_MEMBER(T, reduction),
           TB_MEMBER(T, spacing),
           TB_MEMBER(T, domain),
           TB_MEMBER(T, pad0),
           TB_MEMBER(T, error_scale),
           TB_MEMBER(T, near_w),
           TB_MEMBER(T, hull_w_scale),
           TB_MEMBER(T, pad1),
           TB_MEMBER(T, row_length_x),
           TB_MEMBER(T, inv_scale_x),
           TB_MEMBER(T, tan_half_x),
           TB_MEMBER(T, pad2),
           TB_MEMBER(T, row_length_y),
           TB_MEMBER(T, inv_scale_y),
           TB_MEMBER(T, tan_half_y),
           TB_MEMBER(T, pad3),
           TB_MEMBER(T, side_length),
           CppMember{"tb_transition", sizeof(T), sizeof(float)}},
          kBindingFactorParams};
}

CppBlock factorPatch() {
  using T = TbFactorPatch;
  return {"TbFactorPatch",
          sizeof(T),
          {TB_MEMBER(T, corner), TB_MEMBER(T, edge_sphere), TB_MEMBER(T, edge_m),
           TB_MEMBER(T, patch_sphere), TB_MEMBER(T, inner_ab), TB_MEMBER(T, pad)}};
}

CppBlock factorCorner() {
  using T = TbFactorCorner;
  return {"TbFactorCorner", sizeof(T), {TB_MEMBER(T, position), TB_MEMBER(T, normal)}};
}

CppBlock patchLevels() {
  using T = TbPatchLevels;
  return {"TbPatchLevels", sizeof(T), {TB_MEMBER(T, outer_bits), TB_MEMBER(T, inner_bits)}};
}

CppBlock capture() {
  using T = TbCapture;
  return {"TbCapture",
          sizeof(T),
          {TB_MEMBER(T, count), TB_MEMBER(T, capacity), TB_MEMBER(T, reserved0),
           TB_MEMBER(T, reserved1), CppMember{"words", sizeof(T), sizeof(uint32_t)}},
          kBindingCapture};
}

TEST(LayoutSelfTest, HarnessBlocksMatchTheirSpirv) {
  const auto tcs = embeddedShader("gpu/test_bilinear.tesc");
  const auto levels = embeddedShader("gpu/policy_levels.comp");
  for (const CppBlock& block :
       {cullParams(), cullPatch(), factorParams(), factorPatch(), factorCorner()}) {
    EXPECT_EQ(joined(compare(tcs, block)), "") << "gpu/test_bilinear.tesc";
    EXPECT_EQ(joined(compare(levels, block)), "") << "gpu/policy_levels.comp";
  }
  CppBlock levels_block = patchLevels();
  EXPECT_EQ(joined(compare(tcs, levels_block)), "");
  EXPECT_EQ(joined(compare(embeddedShader("gpu/test_bilinear.tese"), capture())), "");
}

// The mass-spring passes' records, each read by its own pass.
TEST(LayoutSelfTest, MassSpringRecordsMatchTheirSpirv) {
  using namespace mass_spring;
  const CppBlock spring{"Spring",
                        sizeof(Spring),
                        {TB_MEMBER(Spring, a), TB_MEMBER(Spring, b), TB_MEMBER(Spring, rest),
                         TB_MEMBER(Spring, weight)}};
  EXPECT_EQ(joined(compare(embeddedShader("mass_spring/gs_colour.comp"), spring)), "");
  EXPECT_EQ(joined(compare(embeddedShader("mass_spring/gs_colour_step.comp"), spring)), "");
  const CppBlock end{
      "End",
      sizeof(End),
      {TB_MEMBER(End, other), TB_MEMBER(End, rest), TB_MEMBER(End, weight), TB_MEMBER(End, pad)}};
  EXPECT_EQ(joined(compare(embeddedShader("mass_spring/jacobi.comp"), end)), "");
  using B = mass_spring::Binding;
  const CppBlock binding{
      "Binding",
      sizeof(B),
      {TB_MEMBER(B, v0), TB_MEMBER(B, v1), TB_MEMBER(B, v2), TB_MEMBER(B, w0), TB_MEMBER(B, w1),
       TB_MEMBER(B, w2), TB_MEMBER(B, volume), TB_MEMBER(B, pad)}};
  EXPECT_EQ(joined(compare(embeddedShader("mass_spring/render.comp"), binding)), "");
  const CppBlock blast{"Blast",
                       sizeof(Blast),
                       {TB_MEMBER(Blast, centre), TB_MEMBER(Blast, radius), TB_MEMBER(Blast, speed),
                        TB_MEMBER(Blast, step), TB_MEMBER(Blast, pad)}};
  EXPECT_EQ(joined(compare(embeddedShader("mass_spring/verlet.comp"), blast)), "");
}

// The word-indexed blocks: their one runtime array and their named binding.
TEST(LayoutSelfTest, WordBlocksAreBoundByName) {
  const CppBlock displace{"TbDisplacePatches", 0, {{"words", 0, 4}}, kBindingDisplacementPatches};
  EXPECT_EQ(joined(compare(embeddedShader("gpu/test_bilinear.tese#displaced"), displace)), "");
  const CppBlock records{"Patches", 0, {{"patch_words", 0, 4}}, kBindingTessPatchRecords};
  EXPECT_EQ(joined(compare(embeddedShader("gpu/tessellate.comp"), records)), "");
}

// The control: one field added on the GLSL side only shifts the members after it.
TEST(LayoutSelfTest, RejectsAFieldAddedOnTheGlslSideOnly) {
  const std::vector<std::string> found =
      compare(embeddedShader("gpu/test_layout_mismatch.comp"), cullParams());
  const std::string text = joined(found);
  EXPECT_NE(text.find("TbCullParamsBlock.glsl_only_field: in the shader only"), std::string::npos)
      << text;
  EXPECT_NE(text.find("TbCullParamsBlock.policy: offset 120 in SPIR-V, 116 in C++"),
            std::string::npos)
      << text;
}

// The control for the strides and bindings: the C++ table with a wrong one is rejected.
TEST(LayoutSelfTest, RejectsAWrongStrideOrBinding) {
  CppBlock block = cullParams();
  block.binding = kBindingCullPatches;
  block.members[0].stride = 32;
  const std::string text = joined(compare(embeddedShader("gpu/test_bilinear.tesc"), block));
  EXPECT_NE(text.find("planes: array stride 16 in SPIR-V, 32 in C++"), std::string::npos) << text;
  EXPECT_NE(text.find("bound at 4"), std::string::npos) << text;
}

}  // namespace
}  // namespace tb::gpu::layout
