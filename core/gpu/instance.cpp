#include "core/gpu/instance.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasInstanceLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const VkLayerProperties& layer : layers) {
    if (std::strcmp(layer.layerName, name) == 0) return true;
  }
  return false;
}

VKAPI_ATTR VkBool32 VKAPI_CALL countMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                            VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                            void* user) {
  auto* counts = static_cast<Instance::MessageCounts*>(user);
  if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
    counts->errors.fetch_add(1);
    std::fprintf(stderr, "[vulkan validation error] %s\n", data->pMessage);
  } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    counts->warnings.fetch_add(1);
    std::fprintf(stderr, "[vulkan validation warning] %s\n", data->pMessage);
  }
  return VK_FALSE;  // never abort the call that triggered the message
}

}  // namespace

bool validationRequested(Validation validation) {
  if (validation != Validation::kAuto) return validation == Validation::kOn;
  if (const char* env = std::getenv("TB_VK_VALIDATION"); env && *env) {
    return std::string(env) != "0";
  }
#ifdef NDEBUG
  return false;
#else
  return true;
#endif
}

Expected<std::unique_ptr<Instance>> Instance::create(Validation validation) {
  uint32_t loader_version = VK_API_VERSION_1_0;
  vkEnumerateInstanceVersion(&loader_version);
  if (loader_version < VK_API_VERSION_1_3) {
    return Expected<std::unique_ptr<Instance>>::failure(
        "Vulkan loader " + std::to_string(VK_API_VERSION_MAJOR(loader_version)) + "." +
        std::to_string(VK_API_VERSION_MINOR(loader_version)) + " is older than the 1.3 needed");
  }
  const bool validate = validationRequested(validation) && hasInstanceLayer(kValidationLayer);

  auto app = vkStruct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "tessbench";
  app.apiVersion = VK_API_VERSION_1_3;
  auto messenger_info = vkStruct<VkDebugUtilsMessengerCreateInfoEXT>(
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  messenger_info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                   VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = countMessage;

  std::unique_ptr<Instance> instance(new Instance);
  messenger_info.pUserData = instance->counts_.get();
  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  auto info = vkStruct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;
  if (validate) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = extensions;
    info.pNext = &messenger_info;  // also catches errors in vkCreateInstance itself
  }
  if (VkResult r = vkCreateInstance(&info, nullptr, &instance->instance_); r != VK_SUCCESS) {
    return Expected<std::unique_ptr<Instance>>::failure(
        std::string("no usable Vulkan driver: vkCreateInstance returned ") + vkResultName(r));
  }
  if (validate) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance->instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create_messenger) {
      create_messenger(instance->instance_, &messenger_info, nullptr, &instance->messenger_);
    }
  }
  return instance;
}

Instance::~Instance() {
  if (messenger_ != VK_NULL_HANDLE) {
    auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
  }
  if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
}

}  // namespace tb::gpu
