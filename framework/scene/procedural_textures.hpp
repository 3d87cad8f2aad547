#pragma once
// Procedural textures for built-in scenes (stb_perlin noise), RGBA8.
#include <cstdint>

#include <shadelgraph/scene/texture.hpp>

namespace sg::scene {

// Square stone tiles with mortar grooves: base colour (sRGB) and normal map (linear).
Texture makeTilesColor(uint32_t size, int tiles);
Texture makeTilesNormal(uint32_t size, int tiles);
// Running-bond bricks.
Texture makeBricksColor(uint32_t size, int rows);
Texture makeBricksNormal(uint32_t size, int rows);
// Marble-like veins.
Texture makeMarbleColor(uint32_t size);
// Fine concentric ripples: a high-frequency normal map (`cycles` ripples across).
Texture makeRipplesNormal(uint32_t size, int cycles);
// Two-colour checker, for the painted torus.
Texture makeCheckerColor(uint32_t size, int cells);

}  // namespace sg::scene
