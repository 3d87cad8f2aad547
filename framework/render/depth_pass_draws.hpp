#pragma once
// Draws a package hands the depth pre-pass instead of rasterizing them once
// more in a pass of its own. The pre-pass draws them with the package's
// pipelines into one more colour target (R32UI, the output's size),
// before its own depth-only draws, and gives its own draws a fragment shader
// that writes 0 there and compares LESS: a package's fragment tied in depth
// with one of them keeps the pixel. So each pixel's value is the one of the
// fragment that kept the depth. (Decoupled shading writes there which
// shadels each pixel's footprint needs: shadel-mark's requests; its draws
// settle ties among themselves as its composite does.)
#include <cstdint>
#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/render_graph.hpp>

namespace sg::render {

struct DepthPassDraws {
  std::vector<uint32_t> draws;  // GpuScene draw indices the package draws (sorted); the pre-pass leaves them out
  // Records the package's draws (pipelines, descriptors), each from command
  // d of `indirect` (the frame's draw commands; those the phase draws).
  std::function<void(PassContext&, VkBuffer indirect)> draw;
  // The target's last version, which the pre-pass writes (invalid before).
  graph::ResourceHandle target;
};

}  // namespace sg::render
