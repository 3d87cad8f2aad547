#version 460
// One vertex of one deformed range: the rest vertex plus its morph targets'
// weighted deltas, then skinned by the weighted sum of its joints' matrices
// (normals by the inverse transpose), written to the scene vertex buffer.
// Mirrors scene::deformVertex (framework/scene/deformation.cpp).
#extension GL_EXT_scalar_block_layout : require
#include <framework/render/shaders/deformation_interface.h>

layout(local_size_x = 64) in;

struct SgVertex {  // render::GpuVertex
  vec3 position;
  vec3 normal;
  vec4 tangent;
  vec2 uv0;
  vec2 uv1;
  vec4 color;
};

layout(set = 0, binding = kBindSkinRest, scalar) readonly buffer Rest { SgVertex rest[]; };
layout(set = 0, binding = kBindSkinInfluences, scalar) readonly buffer Influences { SgSkinInfluence influences[]; };
layout(set = 0, binding = kBindSkinDeltas, scalar) readonly buffer Deltas { SgMorphDelta deltas[]; };
layout(set = 0, binding = kBindSkinJoints, scalar) readonly buffer Joints { mat4 joints[]; };
layout(set = 0, binding = kBindSkinWeights, scalar) readonly buffer Weights { float weights[]; };
layout(set = 0, binding = kBindSkinVertices, scalar) writeonly buffer Vertices { SgVertex vertices[]; };
layout(push_constant, scalar) uniform Push { SgSkinningPush range; };

void addInfluences(uvec4 j, vec4 w, inout mat4 sum, inout float total) {
  for (int i = 0; i < 4; ++i) {
    if (w[i] == 0.0) continue;
    sum += w[i] * joints[range.jointFirst + j[i]];
    total += w[i];
  }
}

vec3 unit(vec3 x, vec3 fallback) {
  float len = length(x);
  return len > 1e-12 ? x / len : fallback;
}

void main() {
  uint v = gl_GlobalInvocationID.x;
  if (v >= range.vertexCount) return;
  SgVertex vertex = rest[range.restFirst + v];
  vec3 position = vertex.position, normal = vertex.normal, tangent = vertex.tangent.xyz;
  for (uint t = 0u; t < range.targetCount; ++t) {
    float w = weights[range.weightFirst + t];
    SgMorphDelta d = deltas[range.deltaFirst + t * range.vertexCount + v];
    position += w * d.position;
    normal += w * d.normal;
    tangent += w * d.tangent;
  }
  if (range.influenceFirst != kSkinNone) {
    SgSkinInfluence influence = influences[range.influenceFirst + v];
    mat4 skin = mat4(0.0);
    float total = 0.0;
    addInfluences(influence.joints0, influence.weights0, skin, total);
    addInfluences(influence.joints1, influence.weights1, skin, total);
    if (total != 0.0) {
      position = (skin * vec4(position, 1.0)).xyz;
      normal = transpose(inverse(mat3(skin))) * normal;
      tangent = mat3(skin) * tangent;
    }
  }
  vertex.position = position;
  vertex.normal = unit(normal, vec3(0.0, 1.0, 0.0));
  vertex.tangent = vec4(unit(tangent, vec3(1.0, 0.0, 0.0)), vertex.tangent.w);
  vertices[range.vertexFirst + v] = vertex;
}
