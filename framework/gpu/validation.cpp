#include <shadelgraph/gpu/validation.hpp>

#include <cstdio>

namespace sg::gpu {

void ValidationLog::record(ValidationMessage message) {
  std::fprintf(stderr, "[validation %s] %s\n", message.error ? "error" : "warning", message.text.c_str());
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
}

std::vector<ValidationMessage> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

size_t ValidationLog::count() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

void ValidationLog::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
}

VKAPI_ATTR VkBool32 VKAPI_CALL ValidationLog::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                       VkDebugUtilsMessageTypeFlagsEXT,
                                                       const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                       void* userData) {
  const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  const bool warning = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
  if (!error && !warning) return VK_FALSE;
  std::string id = data->pMessageIdName ? data->pMessageIdName : "";
  if (!error && isAllowedWarning(id)) return VK_FALSE;
  static_cast<ValidationLog*>(userData)->record({error, std::move(id), data->pMessage ? data->pMessage : ""});
  return VK_FALSE;
}

}  // namespace sg::gpu
