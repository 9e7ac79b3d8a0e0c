#include "core/gpu/spirv_patch.h"

#include "core/gpu/gpu_error.h"

namespace tb::gpu {
namespace {

// SPIR-V 1.6 specification, sections 2.3 (physical layout) and 3.6 (Execution Mode).
constexpr uint32_t kMagic = 0x07230203;
constexpr uint32_t kHeaderWords = 5;
constexpr uint32_t kOpExecutionMode = 16;
enum Mode : uint32_t {
  kSpacingEqual = 1,
  kSpacingFractionalEven = 2,
  kSpacingFractionalOdd = 3,
  kVertexOrderCw = 4,
  kVertexOrderCcw = 5,
  kPointMode = 10,
  kTriangles = 22,
  kQuads = 24,
  kIsolines = 25,
};

enum class ModeKind { kDomain, kSpacing, kOrder, kPoint, kOther };

ModeKind kindOf(uint32_t mode) {
  switch (mode) {
    case kTriangles:
    case kQuads:
    case kIsolines:
      return ModeKind::kDomain;
    case kSpacingEqual:
    case kSpacingFractionalEven:
    case kSpacingFractionalOdd:
      return ModeKind::kSpacing;
    case kVertexOrderCw:
    case kVertexOrderCcw:
      return ModeKind::kOrder;
    case kPointMode:
      return ModeKind::kPoint;
    default:
      return ModeKind::kOther;
  }
}

uint32_t domainMode(tess::Domain domain) {
  switch (domain) {
    case tess::Domain::kTriangle:
      return kTriangles;
    case tess::Domain::kQuad:
      return kQuads;
    case tess::Domain::kIsoline:
      return kIsolines;
  }
  return kTriangles;
}

uint32_t spacingMode(tess::Spacing spacing) {
  switch (spacing) {
    case tess::Spacing::kInteger:
    case tess::Spacing::kPow2:
      return kSpacingEqual;
    case tess::Spacing::kFractionalOdd:
      return kSpacingFractionalOdd;
    case tess::Spacing::kFractionalEven:
      return kSpacingFractionalEven;
  }
  return kSpacingEqual;
}

}  // namespace

std::vector<uint32_t> withTessModes(std::span<const uint32_t> spirv, const TessModes& modes) {
  if (spirv.size() < kHeaderWords || spirv[0] != kMagic) throw GpuError("not SPIR-V");
  std::vector<uint32_t> out(spirv.begin(), spirv.begin() + kHeaderWords);
  int seen[3] = {0, 0, 0};  // domain, spacing, order
  for (size_t i = kHeaderWords; i < spirv.size();) {
    const uint32_t word_count = spirv[i] >> 16;
    const uint32_t opcode = spirv[i] & 0xffff;
    if (word_count == 0 || i + word_count > spirv.size()) throw GpuError("truncated SPIR-V");
    const std::span<const uint32_t> instruction = spirv.subspan(i, word_count);
    i += word_count;
    if (opcode != kOpExecutionMode || word_count != 3) {
      out.insert(out.end(), instruction.begin(), instruction.end());
      continue;
    }
    const uint32_t entry_point = instruction[1];
    switch (kindOf(instruction[2])) {
      case ModeKind::kDomain:
        ++seen[0];
        out.insert(out.end(), {instruction[0], entry_point, domainMode(modes.domain)});
        if (modes.point_mode) out.insert(out.end(), {instruction[0], entry_point, kPointMode});
        break;
      case ModeKind::kSpacing:
        ++seen[1];
        out.insert(out.end(), {instruction[0], entry_point, spacingMode(modes.spacing)});
        break;
      case ModeKind::kOrder:
        ++seen[2];
        out.insert(out.end(),
                   {instruction[0], entry_point, modes.ccw ? kVertexOrderCcw : kVertexOrderCw});
        break;
      case ModeKind::kPoint:
        break;
      case ModeKind::kOther:
        out.insert(out.end(), instruction.begin(), instruction.end());
        break;
    }
  }
  if (seen[0] != 1 || seen[1] != 1 || seen[2] != 1) {
    throw GpuError("TES SPIR-V must declare one domain, one spacing and one vertex order");
  }
  return out;
}

}  // namespace tb::gpu
