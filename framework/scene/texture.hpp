#pragma once
// Decoded textures and glTF samplers.
#include <cstdint>
#include <string>
#include <vector>

namespace sg::scene {

enum class WrapMode { Repeat, ClampToEdge, MirroredRepeat };
enum class Filter { Nearest, Linear };
enum class MipmapMode { None, Nearest, Linear };  // None: sample the base level only

struct Sampler {
  WrapMode wrapS = WrapMode::Repeat;
  WrapMode wrapT = WrapMode::Repeat;
  // glTF leaves unset filters to the implementation: we pick the best quality.
  Filter magFilter = Filter::Linear;
  Filter minFilter = Filter::Linear;
  MipmapMode mipmapMode = MipmapMode::Linear;

  bool operator==(const Sampler&) const = default;
};

// One glTF texture (image + sampler) decoded to RGBA8, rows top to bottom.
// The colour space comes from how materials use it: base colour and emissive
// are sRGB, everything else linear. A glTF texture used both ways becomes two
// Textures.
struct Texture {
  std::string name;  // texture name, else image name, else image URI
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;  // width * height * 4; empty when loaded with decodeImages = false
  bool srgb = false;
  int sampler = 0;  // always a valid index into Scene::samplers
};

}  // namespace sg::scene
