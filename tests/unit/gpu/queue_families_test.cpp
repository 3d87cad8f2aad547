// Which queue family each logical queue runs on, for device descriptions this
// machine does not have (lavapipe has one family): with a separate compute
// family, async compute runs there and resources of both queues are shared
// between the two families.
#include <gtest/gtest.h>

#include <shadelgraph/gpu/queue_families.hpp>

namespace sg::gpu {
namespace {

VkQueueFamilyProperties family(VkQueueFlags flags, uint32_t count = 1) {
  VkQueueFamilyProperties p{};
  p.queueFlags = flags;
  p.queueCount = count;
  p.timestampValidBits = 64;
  return p;
}

constexpr VkQueueFlags kAll = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT;

TEST(QueueFamilies, OneFamilyLikeLavapipeRunsEveryLogicalQueueOnIt) {
  const std::vector families{family(kAll)};
  const auto choice = chooseQueueFamilies(families);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->graphics, 0u);
  EXPECT_EQ(choice->compute, 0u);
  EXPECT_EQ(choice->transfer, 0u);
  EXPECT_EQ(choice->distinct(), std::vector<uint32_t>{0u});
}

TEST(QueueFamilies, SeparateComputeFamilyTakesAsyncCompute) {
  const std::vector families{family(kAll, 16), family(VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT, 8)};
  const auto choice = chooseQueueFamilies(families);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->graphics, 0u);
  EXPECT_EQ(choice->compute, 1u);
  EXPECT_EQ(choice->transfer, 0u) << "no transfer-only family: transfer stays on graphics";
  EXPECT_EQ(choice->of(1), 1u);
  EXPECT_EQ(choice->distinct(), (std::vector<uint32_t>{0u, 1u})) << "CONCURRENT resources are shared by both";
}

TEST(QueueFamilies, DiscreteGpuWithComputeAndTransferFamilies) {
  const std::vector families{family(kAll, 16), family(VK_QUEUE_TRANSFER_BIT, 2),
                             family(VK_QUEUE_COMPUTE_BIT | VK_QUEUE_TRANSFER_BIT, 8)};
  const auto choice = chooseQueueFamilies(families);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->graphics, 0u);
  EXPECT_EQ(choice->compute, 2u);
  EXPECT_EQ(choice->transfer, 1u);
  EXPECT_EQ(choice->distinct(), (std::vector<uint32_t>{0u, 2u, 1u}));
}

TEST(QueueFamilies, GraphicsFamilyListedAfterComputeOnly) {
  const std::vector families{family(VK_QUEUE_COMPUTE_BIT), family(kAll)};
  const auto choice = chooseQueueFamilies(families);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->graphics, 1u);
  EXPECT_EQ(choice->compute, 0u);
}

TEST(QueueFamilies, FamiliesWithoutQueuesOrGraphicsAreNotChosen) {
  const std::vector empty{family(kAll, 0), family(VK_QUEUE_COMPUTE_BIT)};
  EXPECT_FALSE(chooseQueueFamilies(empty)) << "no family offers graphics + compute queues";
  const std::vector skipped{family(VK_QUEUE_COMPUTE_BIT, 0), family(kAll)};
  const auto choice = chooseQueueFamilies(skipped);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->compute, 1u) << "a compute family with no queue is skipped";
}

}  // namespace
}  // namespace sg::gpu
