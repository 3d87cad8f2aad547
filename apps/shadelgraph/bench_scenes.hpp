#pragma once
// shadelgraph bench A B C --scene-ratios: what the scenes after the first
// cost against it, and what each costs against the same frame as before
// issue 14. Every scene renders forward and decoupled, each as now and as
// before (without occlusion culling),
// through the first scene's first camera path (each scene through its own
// default view when the first has no camera path); frames
// alternate round-robin over all (scene, configuration) pairs, one warm-up
// round then --repetitions timed rounds; medians of the GPU frame time and
// of each pass, and each scene's ratio to the first under the same
// configuration and to the same path as before. Writes scene-ratios.json and prints a table.
#include <filesystem>
#include <string>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>

#include <nlohmann/json.hpp>

#include "scene_source.hpp"

namespace sg::app {

struct SceneRatioArgs {
  std::vector<std::string> scenes;  // at least two: the first is the baseline
  std::vector<std::string> sizes;
  int repetitions = 5;
  bool withoutOccludedSkip = false;  // also decoupled without the occluded-entry skip, alternated
};

// One size of that bench: the run's JSON (width, height, repetitions and per
// scene and configuration the medians and ratios). withBefore false: only
// forward and decoupled as now (ratio_to_before null).
nlohmann::json measureSceneRatios(gpu::Device& device, const std::vector<LoadedScene>& loaded,
                                  const std::vector<std::string>& names, uint32_t width, uint32_t height,
                                  int repetitions, bool withBefore = true, bool withoutOccludedSkip = false);

void runSceneRatioBench(gpu::Context& context, gpu::Device& device, const SceneRatioArgs& args,
                        const std::filesystem::path& out);

}  // namespace sg::app
