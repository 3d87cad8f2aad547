#pragma once
// shadelgraph bench model.gltf --play N: forward and decoupled while the
// scene's glTF animations play (skins and morph targets deform every frame).
// Both render N frames 1/30 s apart, alternated frame by frame, each keeping
// its own state (its own scene and renderer), after one warm-up frame each.
// Reports per path the median GPU frame span and the decoupled/forward ratio,
// and for decoupled the median shadels per covered pixel and the composite
// misses over the frames. Writes playback.json and prints a table.
#include <filesystem>
#include <string>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>

namespace sg::app {

struct PlaybackBenchArgs {
  std::vector<std::string> scenes;  // empty: the built-in scene
  std::vector<std::string> sizes;
  int frames = 0;  // timed frames of playback
};

void runPlaybackBench(gpu::Context& context, gpu::Device& device, const PlaybackBenchArgs& args,
                      const std::filesystem::path& out);

}  // namespace sg::app
