#pragma once

// Small lookups shared by the graph tests.

#include <shadelgraph/graph/graph.hpp>

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace sg::graph::test {

inline CompileOptions extent(uint32_t width = 64, uint32_t height = 64) {
  CompileOptions options;
  options.outputWidth = width;
  options.outputHeight = height;
  return options;
}

template <class T>
std::vector<T> toVector(std::span<const T> items) {
  return {items.begin(), items.end()};
}

inline PassId idOf(const CompiledPlan& plan, std::string_view name) {
  for (uint32_t p = 0; p < plan.passes.size(); ++p) {
    if (plan.passes[p].name == name) return PassId{p};
  }
  ADD_FAILURE() << "no pass named " << name;
  return PassId{0};
}

inline const PlannedPass& passNamed(const CompiledPlan& plan, std::string_view name) {
  return plan.passes[idOf(plan, name).index];
}

inline std::vector<std::string> orderNames(const CompiledPlan& plan) {
  std::vector<std::string> names;
  for (const PassId p : plan.order) names.push_back(plan.passes[p.index].name);
  return names;
}

inline std::vector<Barrier> barriersOn(std::span<const Barrier> barriers, ResourceHandle resource) {
  std::vector<Barrier> found;
  for (const Barrier& b : barriers) {
    if (b.resource == resource.id) found.push_back(b);
  }
  return found;
}

inline std::vector<Barrier> barriersBefore(const CompiledPlan& plan, std::string_view pass, ResourceHandle resource) {
  return barriersOn(plan.barriersBefore(idOf(plan, pass)), resource);
}

inline std::vector<Barrier> barriersAfter(const CompiledPlan& plan, std::string_view pass) {
  return toVector(plan.barriersAfter(idOf(plan, pass)));
}

inline const Batch& batchOf(const CompiledPlan& plan, std::string_view pass) {
  return plan.batches.at(passNamed(plan, pass).batch);
}

// The semaphore waits of the batch `pass` is in.
inline std::vector<SemaphoreWait> waitsBefore(const CompiledPlan& plan, std::string_view pass) {
  return toVector(plan.waitsOf(batchOf(plan, pass)));
}

inline std::vector<ResourceId> aliasesOf(const CompiledPlan& plan, ResourceHandle resource) {
  return toVector(plan.aliasesOf(resource.id));
}

// A small colour image with an absolute size.
inline ImageDesc colorImage() { return ImageDesc{.format = Format::RGBA8Unorm, .size = Size::absolute(64, 64)}; }

}  // namespace sg::graph::test
