// Preloaded by `./sg test --sanitize`: opens the validation layer and lavapipe
// once with RTLD_NODELETE, so they stay mapped after the Vulkan loader's
// dlclose at vkDestroyInstance. LeakSanitizer checks at exit; what those
// uninstrumented libraries keep until then must still belong to a module for
// tools/lsan.supp to match it. RTLD_LOCAL: no symbol is interposed.
#include <dlfcn.h>

__attribute__((constructor)) static void keepVulkanModules(void) {
  dlopen("libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
}
