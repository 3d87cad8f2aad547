#version 460
// --view sheet: the shade storage (layer image) as it is laid out in memory.
#include <framework/shadel/shaders/decoupled_interface.h>

layout(set = 0, binding = kBindLayerImage) uniform sampler2D layerImage;
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
  ivec2 size = textureSize(layerImage, 0);
  outColor = vec4(texelFetch(layerImage, ivec2(inUv * vec2(size)), 0).rgb, 1.0);
}
