#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/queue_families.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool envFlag(const char* name) {
  const char* v = std::getenv(name);
  return v && std::strcmp(v, "0") != 0 && *v != '\0';
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

// The features shadelgraph relies on, checked one by one so a missing one is named.
struct FeatureChain {
  VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  FeatureChain() {
    core.pNext = &v12;
    v12.pNext = &v13;
  }
  FeatureChain(const FeatureChain&) = delete;
};

std::vector<std::string> missingFeatures(const FeatureChain& f) {
  std::vector<std::string> missing;
  auto need = [&](VkBool32 v, const char* name) {
    if (!v) missing.emplace_back(name);
  };
  need(f.core.features.shaderInt64, "VkPhysicalDeviceFeatures::shaderInt64");
  need(f.core.features.fragmentStoresAndAtomics, "VkPhysicalDeviceFeatures::fragmentStoresAndAtomics");
  // gl_PrimitiveID in fragment shaders (the triangle-ID debug layer, forward).
  need(f.core.features.geometryShader, "VkPhysicalDeviceFeatures::geometryShader");
  need(f.v12.timelineSemaphore, "VkPhysicalDeviceVulkan12Features::timelineSemaphore");
  need(f.v12.bufferDeviceAddress, "VkPhysicalDeviceVulkan12Features::bufferDeviceAddress");
  need(f.v12.shaderBufferInt64Atomics, "VkPhysicalDeviceVulkan12Features::shaderBufferInt64Atomics");
  need(f.v12.hostQueryReset, "VkPhysicalDeviceVulkan12Features::hostQueryReset");
  need(f.v12.scalarBlockLayout, "VkPhysicalDeviceVulkan12Features::scalarBlockLayout");
  need(f.v13.synchronization2, "VkPhysicalDeviceVulkan13Features::synchronization2");
  need(f.v13.dynamicRendering, "VkPhysicalDeviceVulkan13Features::dynamicRendering");
  // glslang's SPIR-V 1.6 output declares workgroup sizes with LocalSizeId.
  need(f.v13.maintenance4, "VkPhysicalDeviceVulkan13Features::maintenance4");
  return missing;
}

}  // namespace

ContextOptions ContextOptions::fromEnvironment() {
  ContextOptions o;
  o.validation = envFlag("SG_VALIDATION");
  o.synchronizationValidation = o.validation;
  if (const char* d = std::getenv("SG_DEVICE")) o.deviceFilter = d;
  return o;
}

Context::Context(const ContextOptions& options) {
  try {
    createInstance(options);
    pickPhysicalDevice(options);
    createDevice(options);
  } catch (...) {
    destroy();
    throw;
  }
}

Context::~Context() { destroy(); }

void Context::destroy() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (immediatePool_) vkDestroyCommandPool(device_, immediatePool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

void Context::createInstance(const ContextOptions& options) {
  validation_ = options.validation;
  if (validation_ && !hasLayer(kValidationLayer))
    throw GpuError("validation requested but VK_LAYER_KHRONOS_validation is not installed "
                   "(Debian package vulkan-validationlayers)");

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "shadelgraph";
  app.pEngineName = "shadelgraph";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers;
  std::vector<const char*> extensions{VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  if (validation_) layers.push_back(kValidationLayer);
  for (const auto& e : options.instanceExtensions) extensions.push_back(e.c_str());

  VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &ValidationLog::callback;
  messengerInfo.pUserData = &validationLog_;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (validation_) {
    // The messenger in pNext also catches messages from instance creation itself.
    info.pNext = &messengerInfo;
    if (options.synchronizationValidation) messengerInfo.pNext = &features;
  }
  const VkResult created = vkCreateInstance(&info, nullptr, &instance_);
  if (created == VK_ERROR_EXTENSION_NOT_PRESENT)
    throw GpuError("the Vulkan instance lacks an extension asked for (" + [&] {
      std::string names;
      for (const auto& e : options.instanceExtensions) names += (names.empty() ? "" : ", ") + e;
      return names;
    }() + ")");
  SG_VK(created);

  if (validation_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    messengerInfo.pNext = nullptr;
    SG_VK(create(instance_, &messengerInfo, nullptr, &messenger_));
  }
  setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
      vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
}

void Context::pickPhysicalDevice(const ContextOptions& options) {
  uint32_t count = 0;
  SG_VK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  SG_VK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
  if (devices.empty()) throw GpuError("no Vulkan device found (install mesa-vulkan-drivers for lavapipe)");

  // Prefer a discrete GPU, then integrated, then anything (lavapipe is a CPU device).
  auto rank = [](VkPhysicalDeviceType t) {
    switch (t) {
      case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
      case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
      case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
      default: return 3;
    }
  };
  std::string rejected;
  int bestRank = 99;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    if (!options.deviceFilter.empty() && std::string(p.deviceName).find(options.deviceFilter) == std::string::npos)
      continue;
    if (p.apiVersion < VK_API_VERSION_1_3) {
      rejected += std::string(" ") + p.deviceName + " (Vulkan < 1.3);";
      continue;
    }
    FeatureChain f;
    vkGetPhysicalDeviceFeatures2(d, &f.core);
    auto missing = missingFeatures(f);
    if (!missing.empty()) {
      rejected += std::string(" ") + p.deviceName + " (missing " + missing.front() + ");";
      continue;
    }
    if (rank(p.deviceType) < bestRank) {
      bestRank = rank(p.deviceType);
      physicalDevice_ = d;
      properties_ = p;
    }
  }
  if (!physicalDevice_) throw GpuError("no usable Vulkan 1.3 device:" + (rejected.empty() ? std::string(" none matched SG_DEVICE") : rejected));
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(physicalDevice_, &properties);
  subgroupSize_ = subgroup.subgroupSize;
}

void Context::createDevice(const ContextOptions& options) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice_, &count, families.data());

  const auto choice = chooseQueueFamilies(families);
  if (!choice) throw GpuError(std::string(properties_.deviceName) + " has no graphics+compute queue family");
  const uint32_t graphics = choice->graphics, compute = choice->compute, transfer = choice->transfer;

  std::vector<VkDeviceQueueCreateInfo> queueInfos;
  float priority = 1.0f;
  for (const uint32_t family : choice->distinct()) {
    VkDeviceQueueCreateInfo q{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    q.queueFamilyIndex = family;
    q.queueCount = 1;
    q.pQueuePriorities = &priority;
    queueInfos.push_back(q);
  }

  FeatureChain enable;
  enable.core.features.shaderInt64 = VK_TRUE;
  enable.core.features.fragmentStoresAndAtomics = VK_TRUE;
  enable.core.features.geometryShader = VK_TRUE;
  {
    VkPhysicalDeviceFeatures available{};
    vkGetPhysicalDeviceFeatures(physicalDevice_, &available);
    // Exact occlusion-query counts where the device has them (passes::OverdrawProbe asks the same).
    enable.core.features.occlusionQueryPrecise = available.occlusionQueryPrecise;
  }
  enable.v12.timelineSemaphore = VK_TRUE;
  enable.v12.bufferDeviceAddress = VK_TRUE;
  enable.v12.shaderBufferInt64Atomics = VK_TRUE;
  enable.v12.hostQueryReset = VK_TRUE;
  enable.v12.scalarBlockLayout = VK_TRUE;
  enable.v13.synchronization2 = VK_TRUE;
  enable.v13.dynamicRendering = VK_TRUE;
  enable.v13.maintenance4 = VK_TRUE;

  // Calibrated timestamps put GPU and CPU times of a trace on one clock.
  std::vector<const char*> deviceExtensions;
  bool calibrate = false;
  {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> available(n);
    vkEnumerateDeviceExtensionProperties(physicalDevice_, nullptr, &n, available.data());
    for (const auto& e : available) calibrate |= std::strcmp(e.extensionName, VK_EXT_CALIBRATED_TIMESTAMPS_EXTENSION_NAME) == 0;
    const auto domainsOf = reinterpret_cast<PFN_vkGetPhysicalDeviceCalibrateableTimeDomainsEXT>(
        vkGetInstanceProcAddr(instance_, "vkGetPhysicalDeviceCalibrateableTimeDomainsEXT"));
    bool device = false, monotonic = false;
    if (calibrate && domainsOf) {
      uint32_t domainCount = 0;
      domainsOf(physicalDevice_, &domainCount, nullptr);
      std::vector<VkTimeDomainEXT> domains(domainCount);
      domainsOf(physicalDevice_, &domainCount, domains.data());
      for (const auto d : domains) {
        device |= d == VK_TIME_DOMAIN_DEVICE_EXT;
        monotonic |= d == VK_TIME_DOMAIN_CLOCK_MONOTONIC_EXT;
      }
    }
    calibrate = calibrate && device && monotonic;
    if (calibrate) deviceExtensions.push_back(VK_EXT_CALIBRATED_TIMESTAMPS_EXTENSION_NAME);
    for (const auto& wanted : options.deviceExtensions) {
      const bool present = std::any_of(available.begin(), available.end(), [&](const VkExtensionProperties& e) {
        return wanted == e.extensionName;
      });
      if (!present) throw GpuError(std::string(properties_.deviceName) + " does not support " + wanted);
      deviceExtensions.push_back(wanted.c_str());
    }
  }

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &enable.core;
  info.enabledExtensionCount = static_cast<uint32_t>(deviceExtensions.size());
  info.ppEnabledExtensionNames = deviceExtensions.data();
  info.queueCreateInfoCount = static_cast<uint32_t>(queueInfos.size());
  info.pQueueCreateInfos = queueInfos.data();
  SG_VK(vkCreateDevice(physicalDevice_, &info, nullptr, &device_));

  if (calibrate)
    calibratedTimestamps_ =
        reinterpret_cast<PFN_vkGetCalibratedTimestampsEXT>(vkGetDeviceProcAddr(device_, "vkGetCalibratedTimestampsEXT"));

  const uint32_t familyOf[3] = {graphics, compute, transfer};
  for (int i = 0; i < 3; ++i) {
    queues_[i].family = familyOf[i];
    vkGetDeviceQueue(device_, queues_[i].family, 0, &queues_[i].queue);
  }

  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = queues_[0].family;
  SG_VK(vkCreateCommandPool(device_, &pool, nullptr, &immediatePool_));
}

std::optional<int64_t> Context::hostMinusDeviceClockNs() const {
  if (!calibratedTimestamps_) return std::nullopt;
  const VkCalibratedTimestampInfoEXT infos[2] = {{VK_STRUCTURE_TYPE_CALIBRATED_TIMESTAMP_INFO_EXT, nullptr, VK_TIME_DOMAIN_DEVICE_EXT},
                                                 {VK_STRUCTURE_TYPE_CALIBRATED_TIMESTAMP_INFO_EXT, nullptr,
                                                  VK_TIME_DOMAIN_CLOCK_MONOTONIC_EXT}};
  uint64_t stamps[2] = {};
  uint64_t deviation = 0;
  if (calibratedTimestamps_(device_, 2, infos, stamps, &deviation) != VK_SUCCESS) return std::nullopt;
  const double deviceNs = double(stamps[0]) * double(properties_.limits.timestampPeriod);
  return int64_t(stamps[1]) - int64_t(deviceNs);
}

std::vector<uint32_t> Context::queueFamilies() const {
  std::vector<uint32_t> families;
  for (const auto& q : queues_)
    if (std::find(families.begin(), families.end(), q.family) == families.end()) families.push_back(q.family);
  return families;
}

std::string Context::driverDescription() const {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 p{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  p.pNext = &driver;
  vkGetPhysicalDeviceProperties2(physicalDevice_, &p);
  return std::string(driver.driverName) + " " + driver.driverInfo;
}

VkCommandBuffer beginOneTimeCommands(VkDevice device, VkCommandPool pool) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  SG_VK(vkAllocateCommandBuffers(device, &alloc, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  SG_VK(vkBeginCommandBuffer(cmd, &begin));
  return cmd;
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBuffer cmd = beginOneTimeCommands(device_, immediatePool_);
  record(cmd);
  SG_VK(vkEndCommandBuffer(cmd));
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  SG_VK(vkQueueSubmit2(queues_[0].queue, 1, &submit, VK_NULL_HANDLE));
  SG_VK(vkQueueWaitIdle(queues_[0].queue));
  vkFreeCommandBuffers(device_, immediatePool_, 1, &cmd);
}

void Context::setDebugName(VkObjectType type, uint64_t handle, const char* name) const {
  if (!setObjectName_ || !name) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name;
  setObjectName_(device_, &info);
}

}  // namespace sg::gpu
