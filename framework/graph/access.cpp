#include <shadelgraph/graph/access.hpp>

#include <shadelgraph/graph/flag_names.hpp>

namespace sg::graph {

// The table is indexed by the enumerator; a reordered enum must fail to build.
static_assert(detail::traits(Access::Present).name == "Present");
static_assert(detail::traits(Access::StorageReadWrite).name == "StorageReadWrite");
static_assert(detail::traits(Access::TransferDst).name == "TransferDst");

std::optional<Layout> mergeLayouts(Layout a, Layout b) {
  if (a == b) return a;
  const auto is = [&](Layout x, Layout y) { return (a == x && b == y) || (a == y && b == x); };
  // A depth attachment can be depth-tested read-only as well.
  if (is(Layout::DepthAttachment, Layout::DepthReadOnly)) return Layout::DepthAttachment;
  // DEPTH_STENCIL_READ_ONLY_OPTIMAL allows sampling while depth testing.
  if (is(Layout::DepthReadOnly, Layout::ShaderReadOnly)) return Layout::DepthReadOnly;
  return std::nullopt;
}

std::string toString(ShaderStage stages) {
  using S = ShaderStage;
  static constexpr std::array<std::pair<S, std::string_view>, 3> kNames{{
      {S::Vertex, "Vertex"},
      {S::Fragment, "Fragment"},
      {S::Compute, "Compute"},
  }};
  return detail::joinFlagNames(stages, kNames);
}

}  // namespace sg::graph
