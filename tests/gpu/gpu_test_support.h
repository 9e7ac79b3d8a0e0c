// One Vulkan context per test binary (creating a lavapipe device takes ~0.1 s), and the
// skip that every GPU test takes when no usable device exists: a skip, never a failure.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/gpu/context.h"

namespace tb::gpu::testing {

// The shared context, or nullptr with *reason set.
inline Context* sharedContext(std::string* reason) {
  static Expected<std::unique_ptr<Context>> context = Context::create();
  if (!context) {
    *reason = context.error();
    return nullptr;
  }
  return context.value().get();
}

}  // namespace tb::gpu::testing

// Declares `Context& context` or skips the test with the reason no device is usable.
#define TB_GPU_CONTEXT_OR_SKIP(context)                                                        \
  std::string tb_gpu_skip_reason;                                                              \
  ::tb::gpu::Context* tb_gpu_context = ::tb::gpu::testing::sharedContext(&tb_gpu_skip_reason); \
  if (tb_gpu_context == nullptr)                                                               \
    GTEST_SKIP() << "no usable Vulkan device: " << tb_gpu_skip_reason;                         \
  ::tb::gpu::Context& context = *tb_gpu_context
