#include "core/gpu/context.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <optional>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

// Fence wait limit; a batch of large patches on lavapipe takes well under a second.
constexpr uint64_t kFenceTimeoutNs = 120'000'000'000ull;

struct Candidate {
  VkPhysicalDevice physical_device;
  uint32_t queue_family;
  DeviceInfo info;
  int rank;  // higher is preferred
};

int typeRank(const std::string& type) {
  if (type == "discrete_gpu") return 4;
  if (type == "integrated_gpu") return 3;
  if (type == "virtual_gpu") return 2;
  if (type == "cpu") return 1;
  return 0;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::optional<uint32_t> graphicsComputeFamily(VkPhysicalDevice physical_device) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, families.data());
  constexpr VkQueueFlags kWanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & kWanted) == kWanted) return i;
  }
  return std::nullopt;
}

// Devices with a graphics+compute queue whose name contains `name_filter`, best first.
std::vector<Candidate> candidates(VkInstance instance, const std::string& name_filter,
                                  std::string* all_names) {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::vector<Candidate> found;
  for (VkPhysicalDevice device : devices) {
    const std::optional<uint32_t> family = graphicsComputeFamily(device);
    if (!family) continue;
    DeviceInfo info = queryDeviceInfo(device, *family);
    *all_names += (all_names->empty() ? "" : ", ") + info.device_name;
    if (lower(info.device_name).find(lower(name_filter)) == std::string::npos) continue;
    const int rank = typeRank(info.device_type);
    found.push_back({device, *family, std::move(info), rank});
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const Candidate& a, const Candidate& b) { return a.rank > b.rank; });
  return found;
}

VkDevice createDevice(const Candidate& chosen) {
  const DeviceFeatures& f = chosen.info.features;
  auto xfb = vkStruct<VkPhysicalDeviceTransformFeedbackFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT);
  xfb.transformFeedback = f.transform_feedback;
  auto v13 = vkStruct<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  v13.dynamicRendering = f.dynamic_rendering;
  v13.maintenance4 = f.maintenance4;
  auto features2 =
      vkStruct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  VkPhysicalDeviceFeatures& core = features2.features;
  core.tessellationShader = f.tessellation_shader;
  core.geometryShader = f.geometry_shader;
  core.pipelineStatisticsQuery = f.pipeline_statistics_query;
  core.vertexPipelineStoresAndAtomics = f.vertex_pipeline_stores_and_atomics;
  core.shaderFloat64 = f.shader_float64;

  std::vector<const char*> extensions;
  void** next = &features2.pNext;
  if (f.dynamic_rendering || f.maintenance4) {
    *next = &v13;
    next = &v13.pNext;
  }
  if (f.transform_feedback) {
    *next = &xfb;
    next = &xfb.pNext;
    extensions.push_back(VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME);
  }
  auto pgq = vkStruct<VkPhysicalDevicePrimitivesGeneratedQueryFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PRIMITIVES_GENERATED_QUERY_FEATURES_EXT);
  if (f.primitives_generated_query) {
    pgq.primitivesGeneratedQuery = VK_TRUE;
    pgq.primitivesGeneratedQueryWithRasterizerDiscard = VK_TRUE;
    *next = &pgq;
    next = &pgq.pNext;
    extensions.push_back(VK_EXT_PRIMITIVES_GENERATED_QUERY_EXTENSION_NAME);
  }
  auto pep = vkStruct<VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR);
  if (f.pipeline_executable_info) {
    pep.pipelineExecutableInfo = VK_TRUE;
    *next = &pep;
    next = &pep.pNext;
    extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
  }

  const float priority = 1.0f;
  auto queue_info = vkStruct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue_info.queueFamilyIndex = chosen.queue_family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  auto info = vkStruct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  info.pNext = &features2;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkDevice device = VK_NULL_HANDLE;
  vkCheck(vkCreateDevice(chosen.physical_device, &info, nullptr, &device), "vkCreateDevice");
  return device;
}

}  // namespace

Expected<std::unique_ptr<Context>> Context::create(const ContextOptions& options) {
  using Result = Expected<std::unique_ptr<Context>>;
  Expected<std::unique_ptr<Instance>> instance = Instance::create(options.validation);
  if (!instance) return Result::failure(instance.error());

  std::string all_names;
  const std::vector<Candidate> found =
      candidates(instance.value()->handle(), options.device_name, &all_names);
  if (found.empty()) {
    if (all_names.empty()) {
      return Result::failure(
          "no Vulkan device with a graphics+compute queue "
          "(install mesa-vulkan-drivers for lavapipe)");
    }
    return Result::failure("no Vulkan device name contains '" + options.device_name +
                           "' (devices: " + all_names + ")");
  }
  const auto usable = std::find_if(found.begin(), found.end(), [&](const Candidate& c) {
    return firstMissingFeature(c.info.features, options.required).empty();
  });
  if (usable == found.end()) {
    return Result::failure("Vulkan device '" + found.front().info.device_name + "' lacks " +
                           firstMissingFeature(found.front().info.features, options.required));
  }

  std::unique_ptr<Context> context(new Context);
  context->instance_ = std::move(instance.value());
  context->physical_device_ = usable->physical_device;
  context->queue_family_ = usable->queue_family;
  context->info_ = usable->info;
  context->info_.validation_enabled = context->instance_->validationEnabled();
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(usable->physical_device, &properties);
  context->limits_ = properties.limits;
  vkGetPhysicalDeviceMemoryProperties(usable->physical_device, &context->memory_);
  try {
    context->device_ = createDevice(*usable);
    vkGetDeviceQueue(context->device_, context->queue_family_, 0, &context->queue_);

    auto pool_info = vkStruct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = context->queue_family_;
    VkCommandPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateCommandPool(context->device_, &pool_info, nullptr, &pool),
            "vkCreateCommandPool");
    context->command_pool_ = VkCommandPoolOwner(context->device_, pool);
    auto alloc =
        vkStruct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    vkCheck(vkAllocateCommandBuffers(context->device_, &alloc, &context->command_buffer_),
            "vkAllocateCommandBuffers");
    auto fence_info = vkStruct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VkFence fence = VK_NULL_HANDLE;
    vkCheck(vkCreateFence(context->device_, &fence_info, nullptr, &fence), "vkCreateFence");
    context->fence_ = VkFenceOwner(context->device_, fence);
  } catch (const GpuError& e) {
    return Result::failure("Vulkan device '" + usable->info.device_name + "': " + e.what());
  }
  return context;
}

Context::~Context() {
  if (device_ != VK_NULL_HANDLE) vkDeviceWaitIdle(device_);
  while (!attachments_.empty()) attachments_.pop_back();
  fence_.reset();
  command_pool_.reset();
  if (device_ != VK_NULL_HANDLE) vkDestroyDevice(device_, nullptr);
}

uint32_t Context::memoryType(uint32_t type_bits, VkMemoryPropertyFlags required,
                             VkMemoryPropertyFlags preferred) const {
  std::optional<uint32_t> fallback;
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags flags = memory_.memoryTypes[i].propertyFlags;
    if (!(type_bits & (1u << i)) || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (!fallback) fallback = i;
  }
  if (!fallback) throw GpuError("no Vulkan memory type with the required properties");
  return *fallback;
}

double Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  const std::lock_guard lock(submit_mutex_);
  vkCheck(vkResetCommandBuffer(command_buffer_, 0), "vkResetCommandBuffer");
  auto begin = vkStruct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkCheck(vkBeginCommandBuffer(command_buffer_, &begin), "vkBeginCommandBuffer");
  record(command_buffer_);
  vkCheck(vkEndCommandBuffer(command_buffer_), "vkEndCommandBuffer");

  VkFence fence = fence_.get();
  vkCheck(vkResetFences(device_, 1, &fence), "vkResetFences");
  auto submit = vkStruct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &command_buffer_;
  const auto start = std::chrono::steady_clock::now();
  vkCheck(vkQueueSubmit(queue_, 1, &submit, fence), "vkQueueSubmit");
  vkCheck(vkWaitForFences(device_, 1, &fence, VK_TRUE, kFenceTimeoutNs), "vkWaitForFences");
  const auto stop = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(stop - start).count();
}

void Context::requireFeatures(const DeviceFeatures& wanted, const char* user) const {
  const std::string missing = firstMissingFeature(info_.features, wanted);
  if (!missing.empty()) {
    throw GpuError(std::string(user) + " needs " + missing + ", which Vulkan device '" +
                   info_.device_name + "' lacks");
  }
}

std::string describeDevice(const DeviceInfo& info) {
  return info.device_name + " (" + info.driver_info + ", Vulkan " + info.api_version + ")";
}

std::vector<DeviceInfo> listDevices(std::string* reason) {
  Expected<std::unique_ptr<Instance>> instance = Instance::create(Validation::kOff);
  if (!instance) {
    *reason = instance.error();
    return {};
  }
  std::string all_names;
  std::vector<DeviceInfo> devices;
  for (Candidate& c : candidates(instance.value()->handle(), "", &all_names)) {
    devices.push_back(std::move(c.info));
  }
  if (devices.empty()) *reason = "no Vulkan device with a graphics+compute queue";
  return devices;
}

std::string describeDevice(const std::string& device_name) {
  ContextOptions options;
  options.device_name = device_name;
  options.required = {};  // describe whatever device there is; measures check features
  auto created = Context::create(options);
  if (!created) return "none: " + created.error();
  return describeDevice(created.value()->info());
}

}  // namespace tb::gpu
