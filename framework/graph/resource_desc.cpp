#include <shadelgraph/graph/resource_desc.hpp>

#include <algorithm>
#include <cmath>

namespace sg::graph {
namespace {

// Every case: zero extents, scales that are not positive (or NaN), products
// below 1 (at least 1 texel) or from 2^32 on.
uint32_t scaleExtentAnyCase(uint32_t extent, float scale) {
  if (extent == 0 || !(scale > 0.0f)) return 0;
  const double product = static_cast<double>(extent) * static_cast<double>(scale);
  // Positive and below 2^32: truncation is the floor, without a libm call.
  if (product < 4294967296.0) return std::max(static_cast<uint32_t>(product), 1u);
  const double scaled = std::floor(product);
  return static_cast<uint32_t>(std::max(1.0, scaled));
}

// The same, with the common case (a product from 1 to below 2^32: every real
// extent) short enough to be inlined; truncation is then the floor.
uint32_t scaleExtent(uint32_t extent, float scale) {
  const double product = static_cast<double>(extent) * static_cast<double>(scale);
  if (product >= 1.0 && product < 4294967296.0) return static_cast<uint32_t>(product);
  return scaleExtentAnyCase(extent, scale);
}

}  // namespace

ResolvedImageDesc resolveImageDesc(const ImageDesc& desc, uint32_t outputWidth, uint32_t outputHeight) {
  ResolvedImageDesc out;
  out.format = desc.format;
  if (desc.size.mode == Size::Mode::Absolute) {
    out.width = desc.size.width;
    out.height = desc.size.height;
  } else {
    out.width = scaleExtent(outputWidth, desc.size.scaleX);
    out.height = scaleExtent(outputHeight, desc.size.scaleY);
  }
  out.depth = desc.depth;
  out.layers = desc.layers;
  out.mipLevels = desc.mipLevels;
  out.samples = desc.samples;
  return out;
}

std::string_view toString(ResourceKind kind) {
  switch (kind) {
    case ResourceKind::TransientImage: return "TransientImage";
    case ResourceKind::TransientBuffer: return "TransientBuffer";
    case ResourceKind::Imported: return "Imported";
    case ResourceKind::Persistent: return "Persistent";
    case ResourceKind::History: return "History";
  }
  return "?";
}

std::string_view toString(ResourceType type) { return type == ResourceType::Image ? "Image" : "Buffer"; }

}  // namespace sg::graph
