#include <shadelgraph/graph/pass.hpp>

#include <shadelgraph/graph/branchless.hpp>

#include <algorithm>
#include <array>
#include <utility>

namespace sg::graph {
namespace {

// The pipeline stages of every access with every ShaderStage combination (3
// bits): one table read per declared access, no test of whether it is a
// shader access (accesses of both kinds mix at random).
constexpr std::size_t kAccessCount = detail::kAccessTraits.size();
constexpr std::array<std::array<PipelineStage, 8>, kAccessCount> kPipelineStages = [] {
  std::array<std::array<PipelineStage, 8>, kAccessCount> table{};
  for (std::size_t a = 0; a < kAccessCount; ++a) {
    const detail::AccessTraits& t = detail::kAccessTraits[a];
    for (uint32_t s = 0; s < 8; ++s) {
      table[a][s] = t.shader ? detail::shaderPipelineStages(static_cast<ShaderStage>(s)) : t.stages;
    }
  }
  return table;
}();

// Another pass declared since `mine`'s accesses: moves them to the end to keep
// them contiguous (rare).
[[gnu::noinline]] void moveToEnd(std::vector<ResourceAccess>& all, Range& mine) {
  all.reserve(all.size() + mine.count + 1);
  const uint32_t moved = static_cast<uint32_t>(all.size());
  for (uint32_t i = 0; i < mine.count; ++i) all.push_back(all[mine.first + i]);
  mine.first = moved;
}

// The rare cases of appending an access, out of line: the array is full, or
// another pass was declared since `mine`'s accesses.
[[gnu::noinline]] void appendSlow(std::vector<ResourceAccess>& all, Range& mine, const ResourceAccess& access) {
  if (mine.first + mine.count != all.size()) moveToEnd(all, mine);
  all.push_back(access);
  ++mine.count;
}

// Appends one access to the pass's range. The test for room compares the
// same pointers push_back() does, so the compiler drops push_back()'s growth
// path: read() and write() then keep few values live and save no registers.
inline void append(std::vector<ResourceAccess>& all, Range& mine, const ResourceAccess& access) {
  const bool full = all.data() + all.capacity() == all.data() + all.size();
  if (mine.first + mine.count != all.size() || full) [[unlikely]] return appendSlow(all, mine, access);
  all.push_back(access);
  ++mine.count;
}

// The default shader stage of each pass kind (defaultShaderStage as a table:
// one load instead of two data-dependent tests).
constexpr std::array<ShaderStage, 4> kDefaultShaderStages = {
    defaultShaderStage(PassKind::Raster), defaultShaderStage(PassKind::Compute),
    defaultShaderStage(PassKind::Transfer), ShaderStage::None};
static_assert(static_cast<uint8_t>(PassKind::Raster) == 0 && static_cast<uint8_t>(PassKind::Compute) == 1 &&
              static_cast<uint8_t>(PassKind::Transfer) == 2);

// Declaring is on every frame's path: one function with everything inline
// (read() and write() call nothing else on the common path), and selects
// instead of branches where the outcome depends on the access.
[[gnu::always_inline]] inline void recordAccess(GraphDeclaration& declaration, PassId id, ResourceHandle resource,
                                                Access access, ShaderStage stages, bool write) {
  PassDecl& pass = declaration.passes[id.index];
  const detail::AccessTraits& t = detail::traits(access);
  // The pass kind's default applies to shader accesses declared without
  // stages; both tables are read and the results masked, so that no branch
  // depends on the access (a mix of shader and fixed-function ones).
  const auto given = static_cast<uint8_t>(stages);
  const auto defaulted = maskIf<uint8_t>((given == 0) & t.shader);
  stages = static_cast<ShaderStage>(
      given | (static_cast<uint8_t>(kDefaultShaderStages[static_cast<uint8_t>(pass.kind) & 3u]) & defaulted));
  const PipelineStage pipelineStages = kPipelineStages[static_cast<uint8_t>(access)][static_cast<uint8_t>(stages) & 7u];
  const ResourceAccess recorded{resource.id, resource.version, access, write, stages, t.layout, pipelineStages,
                                t.access};

  std::vector<ResourceAccess>& all = declaration.accesses;
  Range& mine = pass.accesses;
  const auto size = static_cast<uint32_t>(all.size());
  // A real handle's version never exceeds the accesses declared so far (each
  // version comes from a write); forged ones stay out of the count and
  // validate() reports them.
  std::vector<uint32_t>& versionCounts = declaration.versionCounts;
  if (resource.id.index < versionCounts.size() && resource.version <= size) {
    uint32_t& count = versionCounts[resource.id.index];
    count = std::max(count, resource.version + (write ? 2u : 1u));
  }
  append(all, mine, recorded);
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
  declaration_->callbacks[id_.index].swap(callback);  // cheaper than a move-assignment
  return *this;
}

}  // namespace sg::graph
