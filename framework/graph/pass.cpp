#include <shadelgraph/graph/pass.hpp>

#include <algorithm>
#include <array>
#include <utility>

namespace sg::graph {
namespace {

// The pipeline stages of every ShaderStage combination (3 bits): one table
// read per declared access instead of three tests.
constexpr std::array<PipelineStage, 8> kShaderPipelineStages = [] {
  std::array<PipelineStage, 8> stages{};
  for (uint32_t s = 0; s < stages.size(); ++s) stages[s] = detail::shaderPipelineStages(static_cast<ShaderStage>(s));
  return stages;
}();

// Another pass declared since `mine`'s accesses: moves them to the end to keep
// them contiguous (out of line: the common path stays small).
[[gnu::noinline]] void moveToEnd(std::vector<ResourceAccess>& all, Range& mine) {
  all.reserve(all.size() + mine.count + 1);
  const uint32_t moved = static_cast<uint32_t>(all.size());
  for (uint32_t i = 0; i < mine.count; ++i) all.push_back(all[mine.first + i]);
  mine.first = moved;
}

// Declaring is on every frame's path: one function with everything inline
// (read() and write() call nothing else), the common case first.
[[gnu::always_inline]] inline void recordAccess(GraphDeclaration& declaration, PassId id, ResourceHandle resource,
                                                Access access, ShaderStage stages, bool write) {
  PassDecl& pass = declaration.passes[id.index];
  const detail::AccessTraits& t = detail::traits(access);
  if (stages == ShaderStage::None && t.shader) stages = defaultShaderStage(pass.kind);
  const PipelineStage pipelineStages =
      t.shader ? kShaderPipelineStages[static_cast<uint8_t>(stages) & 7u] : t.stages;

  std::vector<ResourceAccess>& all = declaration.accesses;
  Range& mine = pass.accesses;
  const auto size = static_cast<uint32_t>(all.size());
  if (mine.first + mine.count != size) [[unlikely]] moveToEnd(all, mine);
  // A real handle's version never exceeds the accesses declared so far (each
  // version comes from a write); forged ones stay out of the count and
  // validate() reports them.
  std::vector<uint32_t>& versionCounts = declaration.versionCounts;
  if (resource.id.index < versionCounts.size() && resource.version <= size) {
    uint32_t& count = versionCounts[resource.id.index];
    count = std::max(count, resource.version + (write ? 2u : 1u));
  }
  all.push_back({resource.id, resource.version, access, write, stages, t.layout, pipelineStages, t.access});
  ++mine.count;
}

}  // namespace

void Pass::read(ResourceHandle resource, Access access, ShaderStage stages) {
  recordAccess(*declaration_, id_, resource, access, stages, false);
}

ResourceHandle Pass::write(ResourceHandle resource, Access access, ShaderStage stages) {
  recordAccess(*declaration_, id_, resource, access, stages, true);
  return {resource.id, resource.version + 1};
}

Pass& Pass::sideEffect() {
  declaration_->passes[id_.index].sideEffect = true;
  return *this;
}

Pass& Pass::execute(ExecuteFn callback) {
  declaration_->callbacks[id_.index] = std::move(callback);
  return *this;
}

}  // namespace sg::graph
