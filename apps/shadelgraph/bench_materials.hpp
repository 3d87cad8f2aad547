#pragma once
// shadelgraph bench --materials a,b,c: what each material (layer stack) costs,
// forward and decoupled, with the error of each against a supersampled
// forward render of the same material. Also what the material sweep shares
// with the configuration sweep of bench_command.cpp.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/readback.hpp>
#include <shadelgraph/image/png.hpp>

namespace sg::app {

struct MaterialBenchArgs {
  std::vector<std::string> materials;  // registered names, e.g. gltf-pbr, bumps, skin, marble
  std::vector<std::string> scenes;     // empty: the built-in scene
  std::vector<std::string> sizes;
  int repetitions = 5;
  int referenceScale = 4;  // reference: this many samples per pixel side
};

// Runs the material sweep; writes materials.json, materials.csv and images
// into `out` and prints a table.
void runMaterialBench(gpu::Context& context, gpu::Device& device, const MaterialBenchArgs& args,
                      const std::filesystem::path& out);

// Shared with bench_command.cpp (defined there).
image::Rgba8Image toImage(const gpu::HostImage& h);
// Box filter of `scale` x `scale` blocks in linear light (the reference's supersampling).
image::Rgba8Image downsample(const gpu::HostImage& big, uint32_t scale);
double median(std::vector<double> v);
// {name: median of its samples}, e.g. per pass.
nlohmann::json medians(const std::map<std::string, std::vector<double>>& samples);
// One run per scene (the built-in one when `scenes` is empty) and size, scene by scene.
nlohmann::json runPerSceneAndSize(
    const std::vector<std::string>& scenes, const std::vector<std::string>& sizes,
    const std::function<nlohmann::json(const std::string& scene, uint32_t width, uint32_t height)>& run);
// CPU and cores.
nlohmann::json hostJson();
// hostJson() plus the Vulkan device and driver.
nlohmann::json machineJson(const gpu::Context& context);

}  // namespace sg::app
