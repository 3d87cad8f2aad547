#pragma once
// Triangle strips and fans to triangle lists.
#include <cstdint>
#include <span>
#include <vector>

namespace sg::scene {

enum class Topology { TriangleList, TriangleStrip, TriangleFan };

// Corner indices of `topology` as a triangle list, each triangle wound as the
// glTF spec defines it (strip: odd triangles swap their last two corners;
// fan: {v[i+1], v[i+2], v[0]}). Strip triangles that repeat an index are the
// stitching between sub-strips and are dropped. A list is returned unchanged
// except that a trailing partial triangle is dropped.
std::vector<uint32_t> toTriangleList(std::span<const uint32_t> corners, Topology topology);

}  // namespace sg::scene
