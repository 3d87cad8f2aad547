#pragma once
// Internal to the glTF loader: reads accessors into plain arrays.
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace sg::scene::detail {

// An accessor's elements, tightly packed: byteStride honoured, sparse
// substitution applied (tinygltf 2.7 leaves both to the caller), every read
// bounds-checked against its bufferView and buffer.
struct PackedAccessor {
  int componentType = 0;  // TINYGLTF_COMPONENT_TYPE_*
  int components = 0;     // 1 (SCALAR) to 4 (VEC4), 16 (MAT4)
  bool normalized = false;
  size_t count = 0;
  std::vector<uint8_t> bytes;  // count * components * component size
};

// `what` names the use in messages ("mesh 0 'Box' primitive 0 POSITION").
// Throws InvalidAsset. MAT2 and MAT3 accessors are rejected (nothing reads them);
// MAT4 (inverse bind matrices) has 16 components.
PackedAccessor readAccessor(const tinygltf::Model& model, int accessorIndex, const std::string& what);

// Components as floats: normalized integers mapped to [0, 1] / [-1, 1] as the
// glTF spec says, other integers converted as they are.
std::vector<float> toFloats(const PackedAccessor& accessor);
// Unsigned integer components (indices).
std::vector<uint32_t> toUints(const PackedAccessor& accessor);

const char* componentTypeName(int componentType);
const char* typeName(int components);

// Checks that every byte range of every bufferView lies inside its buffer.
void checkBufferViews(const tinygltf::Model& model);

}  // namespace sg::scene::detail
