#include "procedural_sky.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>
#include <stb_image_write.h>

namespace sg::bench {

void writeProceduralSky(const std::filesystem::path& file, uint32_t width, uint32_t height, float sun) {
  const float pi = 3.14159265358979f;
  const glm::vec3 sunDir = glm::normalize(glm::vec3(0.7f, std::tan(40.0f * pi / 180.0f), -0.7f));
  std::vector<float> rgb(size_t(width) * height * 3);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      // environment.glsl's mapping: u = atan2(x, -z) / 2pi + 1/2, v = acos(y) / pi.
      const float theta = (float(y) + 0.5f) / float(height) * pi, phi = ((float(x) + 0.5f) / float(width) - 0.5f) * 2.0f * pi;
      const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
      glm::vec3 c = d.y >= 0.0f ? glm::mix(glm::vec3(1.2f), glm::vec3(0.25f, 0.45f, 1.0f), std::sqrt(d.y))
                                : glm::vec3(0.3f, 0.22f, 0.15f);
      if (glm::dot(d, sunDir) > std::cos(5.0f * pi / 180.0f)) c = glm::vec3(sun);
      for (int k = 0; k < 3; ++k) rgb[(size_t(y) * width + x) * 3 + size_t(k)] = c[k];
    }
  if (!stbi_write_hdr(file.c_str(), int(width), int(height), 3, rgb.data()))
    throw std::runtime_error("cannot write " + file.string());
}

}  // namespace sg::bench
