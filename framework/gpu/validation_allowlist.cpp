// The validation warnings shadelgraph accepts. Every entry says why; anything
// not listed here fails a device test.
#include <shadelgraph/gpu/validation.hpp>

#include <algorithm>
#include <array>

namespace sg::gpu {
namespace {
constexpr std::array<AllowedWarning, 1> kAllowed{{
    // The loader reports lavapipe as a software ICD; that is the reference device here.
    {"Loader Message", "informational loader notes about the software (lavapipe) ICD"},
}};
}  // namespace

bool isAllowedWarning(std::string_view id) {
  return std::any_of(kAllowed.begin(), kAllowed.end(), [&](const AllowedWarning& a) { return a.id == id; });
}

}  // namespace sg::gpu
