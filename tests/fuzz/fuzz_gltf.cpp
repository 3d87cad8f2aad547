// libFuzzer target: the glTF/GLB loader (sg::scene::loadGltf), then what
// 'shadelgraph inspect' does with the result. The loader tells .glb from
// .gltf by the "glTF" magic, so one target covers both (the corpus has both).
// Its contract is SceneError for any bad file: another exception escapes
// and libFuzzer reports it, like a crash.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/uv_chart.hpp>

#include "fuzz_scratch.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = sg::fuzz::writeInput(glb ? "input.glb" : "input.gltf", data, size);
  try {
    const sg::scene::Scene scene = sg::scene::loadGltf(path);
    // Touch what the renderer and inspect read, so bad sizes show up here.
    volatile size_t sink = sg::scene::instancedTriangleCount(scene);
    for (const auto& mesh : scene.meshes) sink = sink + sg::scene::chooseShadingChart(mesh).overlappingPairs;
  } catch (const sg::scene::SceneError&) {
  }
  return 0;
}
