#pragma once
// Occlusion queries (precise where the device has them) around the passes of
// a measurement frame: the samples passing the depth test in the pre-pass
// (both halves) and in forward-opaque after it. Read back without waiting, a
// frame or more later (z_prepass_choice.hpp).
#include <atomic>
#include <cstdint>
#include <optional>

#include <vulkan/vulkan.h>

namespace sg::gpu {
class Context;
}

namespace sg::passes {

enum class OverdrawSlot : uint32_t { Prepass, PrepassLate, ForwardOpaque, Count };

struct OverdrawCounts {
  uint64_t prepass = 0;        // samples passing in the pre-pass, both halves
  uint64_t forwardOpaque = 0;  // samples passing in forward-opaque against its depth
};

class OverdrawProbe {
 public:
  explicit OverdrawProbe(gpu::Context& context);
  ~OverdrawProbe();
  OverdrawProbe(const OverdrawProbe&) = delete;
  OverdrawProbe& operator=(const OverdrawProbe&) = delete;

  // Resets the queries (host) for a new measurement frame.
  void arm();
  // Inside the slot's rendering, each slot once a frame, after a graphics pipeline,
  // all its descriptor sets and the geometry are bound: lavapipe (Mesa 22.3)
  // crashed at a query begun before them (frames that skin or morph on the GPU,
  // forward draws before their material set was bound).
  void begin(VkCommandBuffer cmd, OverdrawSlot slot);
  void end(VkCommandBuffer cmd, OverdrawSlot slot);
  // Whether any slot was recorded since arm() (a frame only planned records none).
  bool recorded() const { return begun_.load() != 0; }
  // The counts once every recorded query has its result; empty while the frame runs.
  std::optional<OverdrawCounts> read() const;

 private:
  VkDevice device_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  VkQueryControlFlags control_ = 0;
  std::atomic<uint32_t> begun_{0};  // bit per slot
};

// What a pass records its counting with: none, or a probe's slot.
struct OverdrawCounter {
  OverdrawProbe* probe = nullptr;
  OverdrawSlot slot = OverdrawSlot::Prepass;
  void begin(VkCommandBuffer cmd) const {
    if (probe) probe->begin(cmd, slot);
  }
  void end(VkCommandBuffer cmd) const {
    if (probe) probe->end(cmd, slot);
  }
};

}  // namespace sg::passes
