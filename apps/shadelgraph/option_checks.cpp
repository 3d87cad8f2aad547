#include "option_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace sg::app {
namespace {

// Digits only, no sign or space, no overflow.
bool parseSide(const char* begin, const char* end, uint32_t& side) {
  if (begin == end || *begin < '0' || *begin > '9') return false;
  const auto [ptr, ec] = std::from_chars(begin, end, side);
  return ec == std::errc() && ptr == end;
}

std::string number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

void parseSize(const std::string& option, const std::string& text, uint32_t& width, uint32_t& height) {
  const auto x = text.find_first_of("xX");
  uint32_t w = 0, h = 0;
  const char* s = text.data();
  if (x == std::string::npos || !parseSide(s, s + x, w) || !parseSide(s + x + 1, s + text.size(), h) || w == 0 ||
      h == 0 || w > kMaxOutputSide || h > kMaxOutputSide)
    throw std::invalid_argument(option + " '" + text + "': expected WIDTHxHEIGHT, e.g. 1280x720, each side 1 to " +
                                std::to_string(kMaxOutputSide));
  width = w;
  height = h;
}

void requireInRange(const std::string& option, long long value, long long min, long long max) {
  if (value < min)
    throw std::invalid_argument(option + " " + std::to_string(value) + ": must be at least " + std::to_string(min));
  if (value > max)
    throw std::invalid_argument(option + " " + std::to_string(value) + ": must be at most " + std::to_string(max));
}

void requireFiniteInRange(const std::string& option, double value, double min, double max) {
  if (!std::isfinite(value) || value < min || value > max)
    throw std::invalid_argument(option + " " + number(value) + ": expected a finite number from " + number(min) +
                                " to " + number(max));
}

}  // namespace sg::app
