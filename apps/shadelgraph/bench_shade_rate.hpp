#pragma once
// shadelgraph bench --shade-rates 1,2,4: what reusing shading across raster
// frames buys. For each scene and size, forward and decoupled at each shade
// rate render the same moving-camera path, alternated frame by frame (each
// configuration keeps its own state across the path: its reuse needs the
// frame before). Reports median and mean raster-frame GPU time over the path
// (shade frames included), their ratio to forward, per-pass medians of shade
// and fill frames and the raster passes' share (the floor), ꟻLIP and PSNR of
// every frame against a forward reference of the same frame (referenceScale²
// spp) and flicker along the path, what staleness costs (PSNR against rate 1,
// fill frames), and with framesInFlight 2 each rate above 1 also with the
// shade frame in flight, and the wall time of consecutive frames.
#include <filesystem>
#include <string>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>

namespace sg::app {

struct ShadeRateBenchArgs {
  std::vector<int> rates;
  std::vector<std::string> scenes;  // empty: the built-in scene
  std::vector<std::string> sizes;
  int pathFrames = 24;
  std::string movingObject;  // non-empty: this object (by name) also moves, on a small circle
  std::vector<double> budgets;  // budget mode configurations (--shade-budget MS each)
  std::string material;         // non-empty: every object's material
  bool unkeptLayers = false;    // each rate also with view-independent layers computed like the others
  int referenceScale = 4;       // reference: this many samples per pixel side
  int framesInFlight = 1;       // 2: each rate above 1 also with two frames in flight
};

// Writes shade-rate.json into `out` and prints a table.
void runShadeRateBench(gpu::Context& context, gpu::Device& device, const ShadeRateBenchArgs& args,
                       const std::filesystem::path& out);

}  // namespace sg::app
