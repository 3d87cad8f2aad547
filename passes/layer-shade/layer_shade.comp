#version 460
// Shades one 8x8 chunk of shadels per workgroup, from the object's work list
// (one indirect dispatch per object per layer). For each shadel: its UV at its
// level -> the triangle from the ID map -> barycentrics clamped to
// [-eps, 1+eps] (a shadel just outside its triangle extrapolates it, as the
// ID map's conservative texels intend) -> vertex attributes and their
// derivatives per shadel step, interpolated as a fragment shader would -> the
// material -> the layer image.
#extension GL_EXT_scalar_block_layout : require
#include <framework/render/shaders/frame.glsl>
#include <plugins/decoupled/shaders/decoupled.glsl>
#include <plugins/decoupled/shaders/work.glsl>
#include <materials/gltf-pbr/material.glsl>
#include <materials/gltf-pbr/gltf_pbr.glsl>

layout(local_size_x = 8, local_size_y = 8) in;

struct SgVertex {  // render::GpuVertex
  vec3 position;
  vec3 normal;
  vec4 tangent;
  vec2 uv0;
  vec2 uv1;
  vec4 color;
};
layout(set = 0, binding = 10, std430) readonly buffer IdMaps { uint idMaps[]; };
layout(set = 0, binding = 11, scalar) readonly buffer Vertices { SgVertex vertices[]; };
layout(set = 0, binding = 12, std430) readonly buffer Indices { uint indices[]; };
layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D layerImage;
layout(push_constant) uniform Push { uint objectIndex; uint layer; } push;

const uint SG_NO_TRIANGLE = 0xFFFFFFFFu;
const float kBarycentricEpsilon = 0.05;

vec3 barycentrics(vec2 p, vec2 a, vec2 b, vec2 c) {
  vec2 v0 = b - a, v1 = c - a, v2 = p - a;
  float d = v0.x * v1.y - v1.x * v0.y;
  float v = (v2.x * v1.y - v1.x * v2.y) / d;
  float w = (v0.x * v2.y - v2.x * v0.y) / d;
  return vec3(1.0 - v - w, v, w);
}

vec2 shadingUv(SgVertex v, SgDecoupledObject o) { return (o.shadingUvSet == 1u ? v.uv1 : v.uv0) - o.tileOffset; }

void main() {
  SgDecoupledObject o = objects[push.objectIndex];
  uint item = sgWorkItemSlot(work[sgObjectOffsetSlot(push.objectIndex)] + gl_WorkGroupID.x);
  uint entryIndex = work[item], chunkIndex = work[item + 1u], level = work[item + 2u], physical = work[item + 3u];
  uint texelIndex = gl_LocalInvocationID.y * SG_CHUNK_SIZE + gl_LocalInvocationID.x;
  ivec2 target = ivec2(sgStorageTexel(physical, texelIndex, params.storageWidthChunks));

  uvec2 shadel = sgVirtualShadel(SgShadelAddress(entryIndex, chunkIndex, texelIndex), params.entriesPerSideLog2);
  SgLevelRect rect = sgLevelRect(push.objectIndex, level);
  uvec2 local = shadel - rect.origin;
  // Chunks of levels smaller than a chunk, and texels past the level's edge.
  if (local.x >= rect.size || local.y >= rect.size) {
    imageStore(layerImage, target, vec4(0.0));
    return;
  }
  uint size0 = shadelInstances[push.objectIndex].level0Size;
  uint levelOffset = 0u;
  for (uint l = 0u; l < level; ++l) levelOffset += (size0 >> l) * (size0 >> l);
  uint triangle = idMaps[o.idMapOffset + levelOffset + local.y * rect.size + local.x];
  if (triangle == SG_NO_TRIANGLE) {
    imageStore(layerImage, target, vec4(0.0));
    return;
  }
  uint i0 = indices[o.firstIndex + 3u * triangle] + uint(o.vertexOffset);
  uint i1 = indices[o.firstIndex + 3u * triangle + 1u] + uint(o.vertexOffset);
  uint i2 = indices[o.firstIndex + 3u * triangle + 2u] + uint(o.vertexOffset);
  SgVertex v0 = vertices[i0], v1 = vertices[i1], v2 = vertices[i2];
  vec2 s0 = shadingUv(v0, o), s1 = shadingUv(v1, o), s2 = shadingUv(v2, o);

  float step = 1.0 / float(rect.size);
  vec2 uv = (vec2(local) + 0.5) * step;
  vec3 b = clamp(barycentrics(uv, s0, s1, s2), -kBarycentricEpsilon, 1.0 + kBarycentricEpsilon);
  b /= b.x + b.y + b.z;
  // Barycentrics are affine in UV: their change per shadel step is exact and
  // the same everywhere in the triangle.
  vec3 bDx = barycentrics(uv + vec2(step, 0.0), s0, s1, s2) - barycentrics(uv, s0, s1, s2);
  vec3 bDy = barycentrics(uv + vec2(0.0, step), s0, s1, s2) - barycentrics(uv, s0, s1, s2);

  mat3 normalMatrix = transpose(inverse(mat3(o.world)));
  Surface s;
  s.position = (o.world * vec4(v0.position * b.x + v1.position * b.y + v2.position * b.z, 1.0)).xyz;
  s.normal = normalize(normalMatrix * (v0.normal * b.x + v1.normal * b.y + v2.normal * b.z));
  vec4 t = v0.tangent * b.x + v1.tangent * b.y + v2.tangent * b.z;
  s.tangent = vec4(mat3(o.world) * t.xyz, v0.tangent.w);
  s.uv0 = v0.uv0 * b.x + v1.uv0 * b.y + v2.uv0 * b.z;
  s.uv1 = v0.uv1 * b.x + v1.uv1 * b.y + v2.uv1 * b.z;
  s.color = v0.color * b.x + v1.color * b.y + v2.color * b.z;
  s.uv0Dx = v0.uv0 * bDx.x + v1.uv0 * bDx.y + v2.uv0 * bDx.z;
  s.uv0Dy = v0.uv0 * bDy.x + v1.uv0 * bDy.y + v2.uv0 * bDy.z;
  s.uv1Dx = v0.uv1 * bDx.x + v1.uv1 * bDx.y + v2.uv1 * bDx.z;
  s.uv1Dy = v0.uv1 * bDy.x + v1.uv1 * bDy.y + v2.uv1 * bDy.z;
  // Double-sided surfaces seen from behind: shade the side facing the camera.
  if (material.flags.y != 0u && dot(s.normal, frame.cameraPosition.xyz - s.position) < 0.0) s.normal = -s.normal;
  imageStore(layerImage, target, shadeGltfPbr(s));
}
