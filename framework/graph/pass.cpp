#include <shadelgraph/graph/pass.hpp>

#include <algorithm>
#include <utility>

namespace sg::graph {

void Pass::read(ResourceHandle resource, Access access, ShaderStage stages) {
  record(resource, access, stages, false);
}

ResourceHandle Pass::write(ResourceHandle resource, Access access, ShaderStage stages) {
  record(resource, access, stages, true);
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

void Pass::record(ResourceHandle resource, Access access, ShaderStage stages, bool write) {
  const PassKind kind = declaration_->passes[id_.index].kind;
  if (stages == ShaderStage::None && isShaderAccess(access)) stages = defaultShaderStage(kind);
  const AccessSync sync = describeAccess(access, stages);

  std::vector<ResourceAccess>& all = declaration_->accesses;
  Range& mine = declaration_->passes[id_.index].accesses;
  if (mine.first + mine.count != all.size()) {
    // Another pass declared since: move this pass's accesses to the end to keep them contiguous.
    all.reserve(all.size() + mine.count + 1);
    const uint32_t moved = static_cast<uint32_t>(all.size());
    for (uint32_t i = 0; i < mine.count; ++i) all.push_back(all[mine.first + i]);
    mine.first = moved;
  }
  // A real handle's version never exceeds the accesses declared so far (each
  // version comes from a write); forged ones stay out of the count and
  // validate() reports them.
  if (resource.id.index < declaration_->versionCounts.size() && resource.version <= all.size()) {
    uint32_t& count = declaration_->versionCounts[resource.id.index];
    count = std::max(count, resource.version + (write ? 2u : 1u));
  }
  all.push_back({resource.id, resource.version, access, write, stages, sync.layout, sync.stages, sync.access});
  ++mine.count;
}

}  // namespace sg::graph
