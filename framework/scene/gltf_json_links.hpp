#pragma once
// Internal to the glTF loader: what the JSON says about itself, checked on the
// JSON before tinygltf stores it (tinygltf keeps indices in `int`, so 2^32
// becomes 0, and offsets in `size_t`, where sums wrap). Run after the shape
// check, which guarantees the types. Errors name the JSON pointer the Khronos
// glTF-Validator names:
// - UNRESOLVED_REFERENCE: every index is below the size of what it indexes;
// - ACCESSOR_TOO_LONG, BUFFER_VIEW_TOO_LONG, sparse ranges: every byte range
//   lies inside what contains it, with overflow-checked arithmetic, and
//   accessors without a bufferView have a bounded count, so no count in the
//   file allocates more than the bytes behind it;
// - ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE, ACCESSOR_SMALL_BYTESTRIDE;
// - NODE_MATRIX_TRS, NODE_MATRIX_NON_TRS;
// - coordinates (translation, texture-transform offset/scale) beyond
//   kMaxCoordinate.
#include <nlohmann/json.hpp>

namespace sg::scene::detail {

// Throws InvalidAsset.
void checkGltfLinks(const nlohmann::json& document);

// Most elements an accessor without a bufferView may have: nothing in the
// file backs them (they are zeros, or sparse values), so a count of 2^62
// would otherwise allocate what it says.
inline constexpr uint64_t kMaxUnbackedAccessorElements = uint64_t{1} << 24;

}  // namespace sg::scene::detail
