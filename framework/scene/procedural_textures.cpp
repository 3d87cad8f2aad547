#include <shadelgraph/scene/procedural_textures.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <glm/glm.hpp>
#include <stb_perlin.h>

namespace sg::scene {
namespace {

uint8_t toByte(float v) { return static_cast<uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

Texture fill(const char* name, uint32_t size, bool srgb, const std::function<glm::vec4(float, float)>& texel) {
  Texture t;
  t.name = name;
  t.width = t.height = size;
  t.srgb = srgb;
  t.pixels.resize(size_t(size) * size * 4);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      glm::vec4 c = texel((float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
      uint8_t* p = &t.pixels[(size_t(y) * size + x) * 4];
      for (int i = 0; i < 4; ++i) p[i] = toByte(c[i]);
    }
  return t;
}

// Tangent-space normal map from a height function by central differences.
Texture normalFromHeight(const char* name, uint32_t size, float strength, const std::function<float(float, float)>& height) {
  const float d = 1.0f / float(size);
  return fill(name, size, false, [&](float u, float v) {
    const float dx = (height(u + d, v) - height(u - d, v)) / (2 * d);
    const float dy = (height(u, v + d) - height(u, v - d)) / (2 * d);
    // glTF normal maps: +Y points along -V (texture up); heights rise with +V downward.
    glm::vec3 n = glm::normalize(glm::vec3(-dx * strength, dy * strength, 1.0f));
    return glm::vec4(n * 0.5f + 0.5f, 1.0f);
  });
}

float noise(float u, float v, float scale, int seed = 0) {
  return stb_perlin_fbm_noise3(u * scale, v * scale, float(seed) * 7.31f, 2.0f, 0.5f, 5);
}

// Distance to the nearest mortar line of a grid, in cell units (0 at the line).
float groove(float cellCoord) {
  float f = cellCoord - std::floor(cellCoord);
  return std::min(f, 1.0f - f);
}

float tileHeight(float u, float v, int tiles) {
  float g = std::min(groove(u * float(tiles)), groove(v * float(tiles)));
  return glm::smoothstep(0.0f, 0.05f, g) * 0.01f + noise(u, v, 16.0f) * 0.001f;
}

float brickHeight(float u, float v, int rows) {
  const float row = v * float(rows);
  const float offset = (int(std::floor(row)) % 2) * 0.5f;
  const float col = u * float(rows) * 0.5f + offset;
  float g = std::min(groove(row), groove(col) * 0.5f);
  return glm::smoothstep(0.0f, 0.08f, g) * 0.01f;
}

}  // namespace

Texture makeTilesColor(uint32_t size, int tiles) {
  return fill("tiles-color", size, true, [&](float u, float v) {
    const float n = noise(u, v, 24.0f) * 0.5f + 0.5f;
    const float cell = std::sin(std::floor(u * float(tiles)) * 12.9898f + std::floor(v * float(tiles)) * 78.233f);
    const float shade = 0.55f + 0.15f * (cell - std::floor(cell)) + 0.2f * n;
    const bool mortar = tileHeight(u, v, tiles) < 0.004f;
    return mortar ? glm::vec4(0.25f, 0.24f, 0.22f, 1.0f) : glm::vec4(shade * 0.85f, shade * 0.8f, shade * 0.7f, 1.0f);
  });
}

Texture makeTilesNormal(uint32_t size, int tiles) {
  return normalFromHeight("tiles-normal", size, 4.0f, [&](float u, float v) { return tileHeight(u, v, tiles); });
}

Texture makeBricksColor(uint32_t size, int rows) {
  return fill("bricks-color", size, true, [&](float u, float v) {
    const float n = noise(u, v, 32.0f, 1) * 0.5f + 0.5f;
    const bool mortar = brickHeight(u, v, rows) < 0.004f;
    return mortar ? glm::vec4(0.6f, 0.58f, 0.52f, 1.0f) : glm::vec4(0.45f + 0.2f * n, 0.16f + 0.08f * n, 0.1f, 1.0f);
  });
}

Texture makeBricksNormal(uint32_t size, int rows) {
  return normalFromHeight("bricks-normal", size, 3.0f, [&](float u, float v) { return brickHeight(u, v, rows); });
}

Texture makeMarbleColor(uint32_t size) {
  return fill("marble-color", size, true, [&](float u, float v) {
    const float veins = std::abs(std::sin((u * 6.0f + noise(u, v, 6.0f, 2) * 3.0f) * std::numbers::pi_v<float>));
    const float c = 0.75f + 0.2f * std::pow(veins, 0.3f);
    return glm::vec4(c, c * 0.97f, c * 0.93f, 1.0f);
  });
}

Texture makeRipplesNormal(uint32_t size, int cycles) {
  return normalFromHeight("ripples-normal", size, 1.0f, [&](float u, float v) {
    const float r = std::hypot(u - 0.5f, v - 0.5f);
    return std::sin(r * float(cycles) * 2 * std::numbers::pi_v<float>) * 0.15f / float(cycles) +
           std::sin(u * float(cycles) * 4.0f) * std::sin(v * float(cycles) * 2.0f) * 0.08f / float(cycles);
  });
}

Texture makeCheckerColor(uint32_t size, int cells) {
  return fill("checker-color", size, true, [&](float u, float v) {
    const bool odd = (int(std::floor(u * float(cells))) + int(std::floor(v * float(cells)))) % 2;
    return odd ? glm::vec4(0.8f, 0.1f, 0.08f, 1.0f) : glm::vec4(0.9f, 0.85f, 0.75f, 1.0f);
  });
}

}  // namespace sg::scene
