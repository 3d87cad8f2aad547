#pragma once
// Synthetic frame graphs shaped like real ones, for measuring what declaring
// and compiling a graph costs: each pass reads 1-3 earlier results (mostly
// recent ones, sometimes an old one), writes 1-2 (mostly new transients,
// sometimes a new version of an existing resource), about a fifth run on the
// async-compute queue, and the last pass writes the imported output.
#include <shadelgraph/graph/graph.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sg::graph {

struct SyntheticResource {
  std::string name;
  bool image = true;
  ImageDesc imageDesc;
  BufferDesc bufferDesc;
};

struct SyntheticPass {
  std::string name;
  QueueClass queue = QueueClass::Graphics;
  PassKind kind = PassKind::Raster;
  std::vector<uint32_t> reads;   // indices into SyntheticGraph::resources
  std::vector<uint32_t> writes;
};

// The recipe of a graph, not the graph: declaring it is part of what is measured.
struct SyntheticGraph {
  std::vector<SyntheticResource> resources;  // the last one is the imported output
  std::vector<SyntheticPass> passes;
};

// `passCount` passes; the same seed gives the same graph.
SyntheticGraph makeSyntheticGraph(uint32_t passCount, uint32_t seed);

// Declares the recipe into `graph` (its passes do nothing when executed).
void declare(RenderGraph& graph, const SyntheticGraph& recipe);

// A 1920x1080 output, memory requirements estimated (no device).
CompileOptions syntheticCompileOptions();

}  // namespace sg::graph
