#include "overdraw_probe.hpp"

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::passes {
namespace {
constexpr uint32_t kSlots = uint32_t(OverdrawSlot::Count);
}

namespace {
// gpu::Context enables occlusionQueryPrecise wherever the device has it.
VkQueryControlFlags preciseWhereAvailable(gpu::Context& context) {
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
  return features.occlusionQueryPrecise ? VK_QUERY_CONTROL_PRECISE_BIT : 0;
}
}  // namespace

OverdrawProbe::OverdrawProbe(gpu::Context& context)
    : device_(context.device()), control_(preciseWhereAvailable(context)) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_OCCLUSION;
  info.queryCount = kSlots;
  SG_VK(vkCreateQueryPool(device_, &info, nullptr, &pool_));
}

OverdrawProbe::~OverdrawProbe() { vkDestroyQueryPool(device_, pool_, nullptr); }

void OverdrawProbe::arm() {
  vkResetQueryPool(device_, pool_, 0, kSlots);
  begun_ = 0;
}

void OverdrawProbe::begin(VkCommandBuffer cmd, OverdrawSlot slot) {
  begun_ |= 1u << uint32_t(slot);
  vkCmdBeginQuery(cmd, pool_, uint32_t(slot), control_);
}

void OverdrawProbe::end(VkCommandBuffer cmd, OverdrawSlot slot) { vkCmdEndQuery(cmd, pool_, uint32_t(slot)); }

std::optional<OverdrawCounts> OverdrawProbe::read() const {
  uint64_t samples[kSlots] = {};
  const uint32_t begun = begun_.load();
  for (uint32_t s = 0; s < kSlots; ++s) {
    if (!(begun & (1u << s))) continue;
    uint64_t result[2] = {};  // value, availability
    const VkResult r = vkGetQueryPoolResults(device_, pool_, s, 1, sizeof(result), result, sizeof(result),
                                             VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (r == VK_NOT_READY || !result[1]) return std::nullopt;
    SG_VK(r);
    samples[s] = result[0];
  }
  return OverdrawCounts{samples[uint32_t(OverdrawSlot::Prepass)] + samples[uint32_t(OverdrawSlot::PrepassLate)],
                        samples[uint32_t(OverdrawSlot::ForwardOpaque)]};
}

}  // namespace sg::passes
