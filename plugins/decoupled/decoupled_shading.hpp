#pragma once
// The decoupled-shading recipe (Baker & Jarzynski 2022) on the render graph:
// z-prepass, shadel-clear, shadel-mark, shadel-allocate, work-aggregate and
// layer-shade (async compute), forward objects, composite, the forward tail
// (blend, exposure, tonemap) and the readback of the shade counters that
// drives the global shade-space adjuster. Owns what lives across frames: the
// virtual shadel space, the remap table, the triangle-ID maps and the tables
// the passes read.
#include <memory>
#include <optional>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>
#include <shadelgraph/render/frame_recipe.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>
#include <shadelgraph/shadel/shadel_storage.hpp>

#include "decoupled_tables.hpp"
#include "layer_history.hpp"
#include "layer_plan.hpp"
#include "shade_space_adjuster.hpp"
#include "shading_choice.hpp"

namespace sg::plugins {

// What the frame shows: the shaded image, or a debug view of decoupled shading.
enum class DebugView { Final, Level, Occupancy, Sheet };

// An object in mode auto is shaded forward while its bounding sphere's
// projected radius is below this many pixels: too small to pay for its chunks.
inline constexpr float kTinyObjectPixels = 8.0f;

// Shade storage is this much larger in frames where a visible material reads
// a neighbourhood (support-expand marks a ring of chunks around what is seen).
inline constexpr double kSupportStorageScale = 2.0;

struct DecoupledSettings {
  uint32_t sheetSizeLog2 = 16;  // 64K x 64K virtual shadels; up to 19 (512K)
  double storageFactor = shadel::kDefaultStorageFactor;  // shade storage = factor x output pixels
  uint32_t storageChunks = 0;  // when non-zero, the shade storage in chunks regardless of the output (tests)
  int filter = 2;                      // composite: 0 point, 1 bilinear, 2 trilinear
  std::optional<float> fixedBias;      // else the adjuster decides
  DebugView view = DebugView::Final;
  ShadeSpaceAdjusterOptions adjuster;
};

// A persistent layer's shadels of the last frame: served from the frame before, or computed.
struct LayerReuse {
  std::string layer;
  uint64_t reused = 0, computed = 0;
};

struct DecoupledStats {
  ShadeCounters counters{};  // of the last executed frame
  float bias = 0.0f;         // the bias that frame was rendered with
  uint32_t objects = 0;  // shaded decoupled in that frame
  uint32_t capacityChunks = 0;
  uint64_t storageBytes = 0;  // shade storage, per layer
  uint64_t remapBytes = 0;
  uint64_t idMapBytes = 0;
  uint64_t historyBytes = 0;  // persistent layers' images and last frame's remap
  uint32_t layerDispatches = 0;  // indirect layer-shade dispatches of the frame
  std::vector<std::string> layers;  // layers the frame ran decoupled, in pass order
  std::vector<LayerReuse> layerReuse;  // per persistent layer
};

class DecoupledShading {
 public:
  DecoupledShading(std::vector<ShadingChoice> choices, DecoupledSettings settings = {});
  ~DecoupledShading();

  render::FrameRecipe recipe();
  graph::ResourceHandle declare(graph::RenderGraph& graph, const render::FrameInputs& inputs);
  // Reads the counters of the last executed frame (call after it completed).
  DecoupledStats stats() const;
  const std::vector<ShadingChoice>& choices() const { return choices_; }

 private:
  void initialize(const render::FrameInputs& inputs);
  // This frame's decoupled objects (frameDraws_, frameObjects_, frameMaterials_) and forward draws.
  void selectFrameObjects(const render::FrameInputs& inputs);
  // One layer-shade pass per depth of the frame's layer plan.
  void addLayerPasses(graph::RenderGraph& graph, render::DecoupledFrame& frame, const plugin::Registry& materials,
                      const LayerHistory::Declared& history);

  std::vector<ShadingChoice> choices_;
  DecoupledSettings settings_;
  ShadeSpaceAdjuster adjuster_;
  float bias_ = 0.0f;
  float lastFrameBias_ = 0.0f;
  uint64_t frames_ = 0;
  bool initialized_ = false;
  // Static: every decoupled object's draw (by object index) and whether its
  // mode is auto; the draws always forward; every draw's world bounding sphere.
  std::vector<uint32_t> decoupledDraws_, forwardDraws_;
  std::vector<glm::vec4> drawSpheres_;
  std::vector<bool> objectAutomatic_;
  std::vector<std::string> objectMaterials_;  // by object: its material (runs decoupled)
  // This frame: the objects shaded decoupled (draws, ids, materials), and the forward draws.
  std::vector<uint32_t> frameDraws_, frameObjects_, frameForwardDraws_;
  std::vector<std::string> frameMaterials_;
  LayerPlan layerPlan_;
  LayerHistory history_;
  std::unique_ptr<shadel::ShadelSpace> space_;
  uint32_t ownedEntryCount_ = 0;
  shadel::StorageLayout storage_;
  uint64_t idMapBytes_ = 0;
  glm::uvec2 sheetRegionOrigin_{0}, sheetRegionSize_{1};  // allocated part of the sheet, in chunks
  uint64_t remapBytes_ = 0;
  gpu::Buffer params_, objects_, shadelInstances_, levelRects_, ownedEntries_, idMaps_, readback_;
};

}  // namespace sg::plugins
