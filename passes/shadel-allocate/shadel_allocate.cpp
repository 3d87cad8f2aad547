#include "shadel_allocate.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

void addShadelAllocate(graph::RenderGraph& graph, render::DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-allocate", graph::QueueClass::AsyncCompute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);
  frame.work = pass.write(frame.work, graph::Access::StorageReadWrite);
  pass.execute([frame](PassContext& ctx) {
    using namespace render;
    const std::array bindings{kBindParams, kBindRemap, kBindOwnedEntries, kBindCounters, kBindWork};
    const auto& pipeline = ctx.device().pipeline("shadel-allocate", [&] {
      return gpu::ComputePipelineDesc{
          .shader = {.path = "passes/shadel-allocate/shadel_allocate.comp"},
          .layout = decoupledLayout(bindings)};
    });
    bindDecoupled(ctx, pipeline, frame, bindings);
    if (frame.ownedEntryCount) vkCmdDispatch(ctx.cmd(), (frame.ownedEntryCount + 63) / 64, 1, 1);
  });
}

}  // namespace sg::passes
