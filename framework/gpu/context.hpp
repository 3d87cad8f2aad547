#pragma once
// The Vulkan instance, physical device and logical device, with the queues the
// render graph's logical queue classes map onto.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <shadelgraph/gpu/validation.hpp>

namespace sg::gpu {

struct ContextOptions {
  bool validation = false;                 // Khronos validation layer + messenger
  bool synchronizationValidation = false;  // sync validation (needs validation)
  std::string deviceFilter;                // substring of the device name; empty = best
  // Beyond what the context needs itself, e.g. a window's surface extensions
  // (instance) and VK_KHR_swapchain (device); a missing one is named in the error.
  std::vector<std::string> instanceExtensions;
  std::vector<std::string> deviceExtensions;
  // Defaults from the environment: SG_VALIDATION=1 turns both validations on,
  // SG_DEVICE picks a device by name.
  static ContextOptions fromEnvironment();
};

// Logical queues. On a device with one queue (lavapipe) all three are the same
// VkQueue; the render graph's batches and semaphores are identical either way.
enum class Queue { Graphics = 0, AsyncCompute = 1, Transfer = 2 };

struct QueueInfo {
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = 0;
};

// Allocates a primary command buffer from `pool` and begins it for one submission.
VkCommandBuffer beginOneTimeCommands(VkDevice device, VkCommandPool pool);

class Context {
 public:
  explicit Context(const ContextOptions& options = ContextOptions::fromEnvironment());
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physicalDevice_; }
  VkDevice device() const { return device_; }
  const QueueInfo& queue(Queue q) const { return queues_[static_cast<int>(q)]; }
  // The distinct queue families behind the logical queues (for concurrent sharing).
  std::vector<uint32_t> queueFamilies() const;
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string deviceName() const { return properties_.deviceName; }
  // How many invocations run as one SIMD unit (8 on lavapipe with 256-bit
  // vectors, 32 or 64 on GPUs): shaders that share per-workgroup setup size
  // their workgroups by it.
  uint32_t subgroupSize() const { return subgroupSize_; }
  std::string driverDescription() const;
  bool validationEnabled() const { return validation_; }
  // Messages from the validation layer (errors and non-allowed warnings).
  ValidationLog& validationLog() { return validationLog_; }

  // The host's steady clock (CLOCK_MONOTONIC) minus the device's timestamp
  // clock, in ns, now; empty when the device cannot say (VK_EXT_calibrated_timestamps).
  std::optional<int64_t> hostMinusDeviceClockNs() const;

  // Records and submits one command buffer on the graphics queue and waits for it.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);
  void setDebugName(VkObjectType type, uint64_t handle, const char* name) const;

 private:
  void createInstance(const ContextOptions& options);
  void pickPhysicalDevice(const ContextOptions& options);
  void createDevice(const ContextOptions& options);
  void destroy();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  uint32_t subgroupSize_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  QueueInfo queues_[3];
  VkCommandPool immediatePool_ = VK_NULL_HANDLE;
  bool validation_ = false;
  ValidationLog validationLog_;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;
  PFN_vkGetCalibratedTimestampsEXT calibratedTimestamps_ = nullptr;  // set when device and host clocks calibrate
};

}  // namespace sg::gpu
