#include "device_fixture.hpp"

namespace sg::test {

TEST_F(DeviceTest, CreatesValidatedDevice) {
  EXPECT_TRUE(context->validationEnabled());
  EXPECT_NE(context->device(), VK_NULL_HANDLE);
  EXPECT_GE(context->properties().apiVersion, VK_API_VERSION_1_3);
  EXPECT_FALSE(context->deviceName().empty());
}

TEST_F(DeviceTest, ValidationErrorsAreRecorded) {
  // Deliberately invalid: a buffer of size 0. The messenger must record it,
  // which is what turns validation errors into test failures.
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCreateBuffer(context->device(), &info, nullptr, &buffer);
  if (buffer) vkDestroyBuffer(context->device(), buffer, nullptr);
  auto messages = context->validationLog().messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_TRUE(messages.front().error);
  EXPECT_NE(messages.front().text.find("size"), std::string::npos);
  context->validationLog().clear();  // expected; keep TearDown's check for the rest
}

TEST_F(DeviceTest, AllocatorTracksTotalsPerCategory) {
  VkMemoryRequirements req{1000, 256, ~0u};
  auto a = memory->allocate(req, gpu::MemoryLocation::Device, "meshes");
  auto b = memory->allocate(req, gpu::MemoryLocation::Device, "meshes");
  auto c = memory->allocate(req, gpu::MemoryLocation::Upload, "staging");
  auto totals = memory->totals();
  EXPECT_GE(totals.bytesByCategory["meshes"], 2000u);
  EXPECT_GE(totals.bytesByCategory["staging"], 1000u);
  EXPECT_NE(c.mapped, nullptr);
  // Two live ranges in one block never overlap.
  if (a.memory == b.memory) {
    EXPECT_TRUE(a.offset + a.size <= b.offset || b.offset + b.size <= a.offset);
  }
  memory->free(a);
  memory->free(b);
  memory->free(c);
  EXPECT_EQ(memory->totals().bytesByCategory.count("meshes"), 0u);
}

}  // namespace sg::test
