#pragma once
// What the environment passes keep per renderer (FrameContext::ownState):
// the image's texels, the prefiltered maps, and whether they hold the result yet.
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/render/frame_context.hpp>

namespace sg::passes {

inline constexpr const char* kEnvironmentMapsState = "environment";

struct EnvironmentMaps {
  const void* scene = nullptr;  // the scene::Environment the maps were made from
  gpu::Buffer source;           // the image, RGBA32F texels row by row (the background reads it too)
  gpu::Image specular, irradiance, brdf;
  bool prefiltered = false;
};

// The frame's scene's maps, created (not yet prefiltered) when the scene's environment is new.
EnvironmentMaps& environmentMaps(render::FrameContext& frame);

}  // namespace sg::passes
