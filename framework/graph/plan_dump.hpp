#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>

#include <string>

namespace sg::graph {

// Human-readable summary: order, batches with waits and signals, each pass's
// accesses and barriers, final barriers, resources and memory.
std::string toText(const CompiledPlan& plan);

// Graphviz: passes are boxes coloured by queue (culled ones dashed), resource
// versions are ellipses, edges are reads and writes.
std::string toDot(const CompiledPlan& plan);

// Every declared pass (name, queue, culled, accesses, barriers, waits), every
// resource (kind, description, memory for transients), order, batches, final
// barriers, heaps and memory totals. Layout described in docs.
std::string toJson(const CompiledPlan& plan);

}  // namespace sg::graph
