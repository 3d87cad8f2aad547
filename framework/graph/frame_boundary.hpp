#pragma once
// Where one frame meets the frames before and after it (frames in flight).
//
// The host waits only for the batches the frame's results need: passes that
// write an imported resource (the output image, readbacks), produce a
// markOutput() version or have sideEffect(), and every pass those depend on.
// On each queue the batches after the last such batch are the frame's *tail*:
// they only feed persistent resources, which later frames consume (e.g. a
// shade frame on async compute read by the next raster frames), so the host
// records and submits the next frame while they run.
//
// Persistent, history and imported resources carry the frames' order: per
// resource and logical queue the plan lists the first and last batch using it.
// A later frame's first batch using the resource on queue Q waits on the
// timeline of every other queue that used the same memory in an earlier frame
// (the executor keeps those values per physical resource); on Q itself
// submission order and the resource's first barrier suffice.
#include <shadelgraph/graph/assign_queues.hpp>
#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/graph/version_table.hpp>

#include <span>
#include <vector>

namespace sg::graph {

// What the frame's results need: per pass (by PassId) whether it is a root
// (output producer, imported-resource access, side effect) or one depends on it.
// `order` is any topological order of the kept passes (Kahn's, or it after
// orderTailLast(): the answer is the same).
void neededByResults(const RenderGraph& graph, const VersionTable& versions, const DependencyGraph& deps,
                     std::span<const PassId> order, std::vector<bool>& needed);
// Moves the passes nothing of the frame needs after all the others (keeping
// each group's order), so that on any queue the tail is submitted last and,
// on a single physical queue (lavapipe), runs after what the host waits for.
void orderTailLast(const std::vector<bool>& needed, std::vector<PassId>& order);

// Marks the tail batches (Batch::tail), sets plan.hostWaitBatch and fills
// plan.externalUses. `plan` must hold the order, resources and batches;
// `versions` says which passes use external resources at all.
void planFrameBoundary(const RenderGraph& graph, const VersionTable& versions, const std::vector<bool>& needed,
                       std::span<const uint32_t> passBatch, CompiledPlan& plan);

}  // namespace sg::graph
