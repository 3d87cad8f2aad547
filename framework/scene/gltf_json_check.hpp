#pragma once
// Internal to the glTF loader: checks the JSON types of every glTF property
// the loader reads, before tinygltf parses it. tinygltf 2.7 silently drops a
// property of the wrong type (a "primitives" object instead of an array, a
// string index, a texture index of -1), which would load a different model
// than the file describes; this turns each into an error naming the property,
// e.g. "meshes[0].primitives: expected an array, got an object".
#include <span>
#include <string_view>

namespace sg::scene::detail {

// Throws InvalidAsset. `json` is the .gltf text or a .glb's JSON chunk. Also
// rejects files whose extensionsRequired names one not in `supportedExtensions`
// (checked first: tinygltf's own errors for such files, e.g. Draco-compressed
// accessors without a bufferView, would not say why).
void checkGltfJson(std::string_view json, std::span<const std::string_view> supportedExtensions);

}  // namespace sg::scene::detail
