#include <algorithm>
#include <cstring>
#include <optional>

#include <shadelgraph/scene/checked_math.hpp>
#include <shadelgraph/scene/gltf_accessor.hpp>
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/gltf_json_links.hpp>

namespace sg::scene::detail {
namespace {

size_t componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;  // inverse bind matrices (MAT2/MAT3 have column padding rules; unused)
    default: return 0;
  }
}

// The bytes [offset, offset + length) of a bufferView, checked.
const uint8_t* viewBytes(const tinygltf::Model& model, int viewIndex, const std::string& what) {
  if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size())
    throw InvalidAsset(what + ": bufferView " + std::to_string(viewIndex) + " does not exist (the file has " +
                       std::to_string(model.bufferViews.size()) + ")");
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(viewIndex)];
  return model.buffers[static_cast<size_t>(view.buffer)].data.data() + view.byteOffset;  // range checked by checkBufferViews
}

// `count` elements of `elementSize` bytes, `stride` (>= elementSize) apart,
// starting `offset` bytes into bufferView `viewIndex`, tightly packed. The
// range is checked before anything is allocated, with overflow-checked
// arithmetic, so a count in the file never allocates more than the bytes
// that back it.
std::vector<uint8_t> readElements(const tinygltf::Model& model, int viewIndex, size_t offset, size_t count,
                                  size_t elementSize, size_t stride, const std::string& what) {
  const uint8_t* base = viewBytes(model, viewIndex, what);
  const size_t viewLength = model.bufferViews[static_cast<size_t>(viewIndex)].byteLength;
  const std::optional<uint64_t> end = elementsEnd(offset, count, elementSize, stride);
  if (!end || *end > viewLength)
    throw InvalidAsset(what + ": reads bytes [" + std::to_string(offset) + ", " +
                       (end ? std::to_string(*end) : std::string("beyond 2^64")) + ") of bufferView " +
                       std::to_string(viewIndex) + ", which has " + std::to_string(viewLength) + " bytes");
  std::vector<uint8_t> out(count * elementSize);  // <= *end: stride >= elementSize
  if (stride == elementSize) {
    std::memcpy(out.data(), base + offset, out.size());
  } else {
    for (size_t i = 0; i < count; ++i) std::memcpy(out.data() + i * elementSize, base + offset + i * stride, elementSize);
  }
  return out;
}

template <class T>
T load(const uint8_t* bytes) {
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

}  // namespace

const char* componentTypeName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
    default: return "an unknown component type";
  }
}

const char* typeName(int components) {
  switch (components) {
    case 1: return "SCALAR";
    case 2: return "VEC2";
    case 3: return "VEC3";
    case 4: return "VEC4";
    case 16: return "MAT4";
    default: return "MAT";
  }
}

void checkBufferViews(const tinygltf::Model& model) {
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    const tinygltf::BufferView& view = model.bufferViews[i];
    const std::string name = describe("bufferView", i, view.name);
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
      throw InvalidAsset(name + ": buffer " + std::to_string(view.buffer) + " does not exist (the file has " +
                         std::to_string(model.buffers.size()) + ")");
    const tinygltf::Buffer& buffer = model.buffers[static_cast<size_t>(view.buffer)];
    const size_t size = buffer.data.size();
    if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
      throw InvalidAsset(name + ": bytes [" + std::to_string(view.byteOffset) + ", " +
                         std::to_string(view.byteOffset + view.byteLength) + ") lie outside " +
                         describe("buffer", static_cast<size_t>(view.buffer), buffer.name) +
                         (buffer.uri.empty() || buffer.uri.starts_with("data:") ? "" : " ('" + buffer.uri + "')") +
                         ", which has " + std::to_string(size) + " bytes");
  }
}

PackedAccessor readAccessor(const tinygltf::Model& model, int accessorIndex, const std::string& what) {
  if (accessorIndex < 0 || static_cast<size_t>(accessorIndex) >= model.accessors.size())
    throw InvalidAsset(what + ": accessor " + std::to_string(accessorIndex) + " does not exist (the file has " +
                       std::to_string(model.accessors.size()) + ")");
  const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(accessorIndex)];
  const std::string where = what + " (accessor " + std::to_string(accessorIndex) + ")";

  PackedAccessor result;
  result.componentType = accessor.componentType;
  result.components = componentCount(accessor.type);
  result.normalized = accessor.normalized;
  result.count = accessor.count;
  const size_t size = componentSize(accessor.componentType);
  if (size == 0) throw InvalidAsset(where + ": unsupported component type " + componentTypeName(accessor.componentType));
  if (result.components == 0) throw InvalidAsset(where + ": matrix accessors are not supported here");
  const size_t elementSize = size * static_cast<size_t>(result.components);
  if (result.count == 0) return result;

  if (accessor.bufferView >= 0) {
    viewBytes(model, accessor.bufferView, where);  // range check
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(accessor.bufferView)];
    const size_t stride = view.byteStride ? view.byteStride : elementSize;
    if (stride < elementSize)
      throw InvalidAsset(where + ": byteStride " + std::to_string(stride) + " is smaller than its " +
                         std::to_string(elementSize) + "-byte elements");
    result.bytes = readElements(model, accessor.bufferView, accessor.byteOffset, result.count, elementSize, stride, where);
  } else if (!accessor.sparse.isSparse) {
    throw InvalidAsset(where + ": has neither a bufferView nor sparse values");
  } else {
    // Nothing in the file backs these zeros: bounded (the JSON check names the limit).
    if (result.count > kMaxUnbackedAccessorElements)
      throw InvalidAsset(where + ": " + std::to_string(result.count) + " elements without a bufferView (at most " +
                         std::to_string(kMaxUnbackedAccessorElements) + ")");
    result.bytes.assign(result.count * elementSize, 0);
  }

  if (accessor.sparse.isSparse) {
    if (accessor.sparse.count < 0 || accessor.sparse.indices.byteOffset < 0 || accessor.sparse.values.byteOffset < 0)
      throw InvalidAsset(where + ": sparse count and byte offsets must be >= 0");
    const auto sparseCount = static_cast<size_t>(accessor.sparse.count);
    const int indexType = accessor.sparse.indices.componentType;
    const size_t indexSize = componentSize(indexType);
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      throw InvalidAsset(where + ": sparse indices have component type " + componentTypeName(indexType) +
                         ", expected UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    if (sparseCount > result.count)
      throw InvalidAsset(where + ": sparse count " + std::to_string(sparseCount) + " exceeds the accessor's count " +
                         std::to_string(result.count));
    if (sparseCount == 0) return result;
    const std::vector<uint8_t> indexBytes =
        readElements(model, accessor.sparse.indices.bufferView, static_cast<size_t>(accessor.sparse.indices.byteOffset),
                     sparseCount, indexSize, indexSize, where + " sparse indices");
    const std::vector<uint8_t> valueBytes =
        readElements(model, accessor.sparse.values.bufferView, static_cast<size_t>(accessor.sparse.values.byteOffset),
                     sparseCount, elementSize, elementSize, where + " sparse values");
    for (size_t i = 0; i < sparseCount; ++i) {
      const uint8_t* at = indexBytes.data() + i * indexSize;
      const size_t target = indexSize == 1   ? load<uint8_t>(at)
                            : indexSize == 2 ? load<uint16_t>(at)
                                             : load<uint32_t>(at);
      if (target >= result.count)
        throw InvalidAsset(where + ": sparse index " + std::to_string(target) + " is out of range (count " +
                           std::to_string(result.count) + ")");
      std::memcpy(result.bytes.data() + target * elementSize, valueBytes.data() + i * elementSize, elementSize);
    }
  }
  return result;
}

std::vector<float> toFloats(const PackedAccessor& accessor) {
  const size_t n = accessor.count * static_cast<size_t>(accessor.components);
  std::vector<float> out(n);
  const uint8_t* in = accessor.bytes.data();
  const bool normalized = accessor.normalized;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(out.data(), in, n * sizeof(float)); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      for (size_t i = 0; i < n; ++i) out[i] = normalized ? in[i] / 255.0f : in[i];
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (size_t i = 0; i < n; ++i) {
        const auto v = load<uint16_t>(in + 2 * i);
        out[i] = normalized ? v / 65535.0f : v;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      for (size_t i = 0; i < n; ++i) {
        const auto v = load<int8_t>(in + i);
        out[i] = normalized ? std::max(v / 127.0f, -1.0f) : v;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      for (size_t i = 0; i < n; ++i) {
        const auto v = load<int16_t>(in + 2 * i);
        out[i] = normalized ? std::max(v / 32767.0f, -1.0f) : v;
      }
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      for (size_t i = 0; i < n; ++i) out[i] = static_cast<float>(load<uint32_t>(in + 4 * i));
      break;
    default: break;
  }
  return out;
}

std::vector<uint32_t> toUints(const PackedAccessor& accessor) {
  const size_t n = accessor.count * static_cast<size_t>(accessor.components);
  std::vector<uint32_t> out(n);
  const uint8_t* in = accessor.bytes.data();
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: std::copy(in, in + n, out.begin()); break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      for (size_t i = 0; i < n; ++i) out[i] = load<uint16_t>(in + 2 * i);
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: std::memcpy(out.data(), in, n * sizeof(uint32_t)); break;
    default: break;
  }
  return out;
}

}  // namespace sg::scene::detail
