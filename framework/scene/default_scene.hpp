#pragma once
// The built-in scene that `./sg run` renders, generated in code: a small
// courtyard with occlusion (ground, walls, pillars), curved objects, procedural
// textures, a glossy sphere with a high-frequency normal pattern (the shimmer
// case decoupled shading is meant to fix; it moves: its `motion`) and three
// lights. Every object has a unique UV chart.
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene {

// `textureSize` is the side of each procedural texture (a power of two).
Scene makeDefaultScene(uint32_t textureSize = 512);

}  // namespace sg::scene
