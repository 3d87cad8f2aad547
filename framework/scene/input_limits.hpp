#pragma once
// Internal to the loaders: limits that keep hostile input from exhausting the
// stack or flooding a terminal, shared by the glTF and the scene-file loader.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sg::scene::detail {

// Deepest object/array nesting accepted in a JSON text. The JSON parsers
// (nlohmann, and tinygltf's walk over its result) recurse once per level, so
// an unbounded depth (16,000 levels fit in 32 KB) overflows the stack. Real
// glTF files nest about 8 deep.
inline constexpr size_t kMaxJsonDepth = 256;

// Coordinates (translations, positions, radii, texture-transform offsets and
// scales) up to this magnitude keep squared lengths finite in 32-bit float.
inline constexpr double kMaxCoordinate = 1e18;

// Numbers become 32-bit floats: beyond this magnitude (the largest finite
// float, as a double) a finite double turns infinite.
inline constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());

// Where the nesting of `json` first exceeds `maxDepth`, as a message, or
// nullopt. A linear scan that honours strings and escapes, done before any
// recursive parser sees the text.
std::optional<std::string> jsonDepthError(std::string_view json, size_t maxDepth = kMaxJsonDepth);

// `text` cut to `maxChars` with "..." and how much was cut: error messages
// quote names, URIs and values from the file, which may be megabytes long.
std::string capText(std::string_view text, size_t maxChars = 200);

// At most `maxCount` warnings; the rest summarized as "and K more warnings".
void capWarnings(std::vector<std::string>& warnings, size_t maxCount = 20);

}  // namespace sg::scene::detail
