#pragma once
// Validation-layer messages as data: every error, and every warning not on the
// allow-list (validation_allowlist.cpp), is recorded so a test or the CLI can
// fail on it instead of just printing a log line.
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::gpu {

struct ValidationMessage {
  bool error = false;  // else a warning
  std::string id;      // VUID or message id name
  std::string text;
};

// One place that lists the warnings we accept, each with the reason.
struct AllowedWarning {
  std::string_view id;
  std::string_view reason;
};
bool isAllowedWarning(std::string_view id);

class ValidationLog {
 public:
  void record(ValidationMessage message);
  std::vector<ValidationMessage> messages() const;
  size_t count() const;
  void clear();
  // Installed as the VkDebugUtilsMessengerEXT callback; userData is a ValidationLog*.
  static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* userData);

 private:
  mutable std::mutex mutex_;
  std::vector<ValidationMessage> messages_;
};

}  // namespace sg::gpu
