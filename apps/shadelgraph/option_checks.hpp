#pragma once
// Values of command-line options, checked strictly before anything is loaded:
// an error names the option, the value and what it accepts.
#include <cstdint>
#include <string>

namespace sg::app {

// The largest output side the CLI accepts (lavapipe's and most GPUs' image limit).
inline constexpr uint32_t kMaxOutputSide = 16384;

// "1280x720" -> width, height: decimal digits only, each side 1..kMaxOutputSide;
// anything else (signs, spaces, trailing text, overflow) throws naming `option`.
void parseSize(const std::string& option, const std::string& text, uint32_t& width, uint32_t& height);
// Throws "<option> <value>: must be at least <min>" (and at most <max>).
void requireInRange(const std::string& option, long long value, long long min, long long max);
// Throws unless value is finite and within [min, max].
void requireFiniteInRange(const std::string& option, double value, double min, double max);

}  // namespace sg::app
