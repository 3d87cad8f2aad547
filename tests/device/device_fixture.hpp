#pragma once
// Every device test runs on a context with the Khronos validation layer and
// synchronization validation on; any validation message fails the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/memory.hpp>
#include <shadelgraph/gpu/pipeline_cache.hpp>
#include <shadelgraph/gpu/shader_compiler.hpp>

namespace sg::test {

inline gpu::ContextOptions validatedOptions() {
  gpu::ContextOptions o;
  o.validation = true;
  o.synchronizationValidation = true;
  return o;
}

class DeviceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    cacheDir = std::filesystem::temp_directory_path() /
               ("sg-test-cache-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(cacheDir);
    context = std::make_unique<gpu::Context>(validatedOptions());
    memory = std::make_unique<gpu::MemoryAllocator>(*context);
    compiler = std::make_unique<gpu::ShaderCompiler>(library, cacheDir);
    pipelineCache = std::make_unique<gpu::PipelineCache>(*context, std::filesystem::path());
  }
  void TearDown() override {
    if (context) vkDeviceWaitIdle(context->device());
    for (const auto& m : context->validationLog().messages())
      ADD_FAILURE() << "validation " << (m.error ? "error" : "warning") << " [" << m.id << "]: " << m.text;
    pipelineCache.reset();
    compiler.reset();
    memory.reset();
    context.reset();
    std::filesystem::remove_all(cacheDir);
  }

  std::filesystem::path cacheDir;
  gpu::ShaderLibrary library;
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<gpu::MemoryAllocator> memory;
  std::unique_ptr<gpu::ShaderCompiler> compiler;
  std::unique_ptr<gpu::PipelineCache> pipelineCache;
};

}  // namespace sg::test
