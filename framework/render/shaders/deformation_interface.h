// The skinning pass's (passes/skinning) data, bindings and push constants, declared once for C++
// (sg::shader) and GLSL. Buffers use the scalar block layout.
#ifndef SG_DEFORMATION_INTERFACE_H
#define SG_DEFORMATION_INTERFACE_H

#include "../../gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kBindSkinRest = 0u;        // render::GpuVertex[]: the rest pose of every deformed range
SG_CONST uint kBindSkinInfluences = 1u;  // SgSkinInfluence[]: joints and weights of skinned vertices
SG_CONST uint kBindSkinDeltas = 2u;      // SgMorphDelta[]: per target, per vertex
SG_CONST uint kBindSkinJoints = 3u;      // mat4[]: this frame's joint matrices (mesh space), host-written
SG_CONST uint kBindSkinWeights = 4u;     // float[]: this frame's morph weights, host-written
SG_CONST uint kBindSkinVertices = 5u;    // render::GpuVertex[]: the scene vertex buffer, written

SG_CONST uint kSkinNone = 0xffffffffu;  // influenceFirst of a range that is only morphed

struct SgSkinInfluence {
  uvec4 joints0;
  vec4 weights0;
  uvec4 joints1;  // weights1 all 0 when the file has no JOINTS_1
  vec4 weights1;
};

struct SgMorphDelta {
  vec3 position;
  vec3 normal;
  vec3 tangent;
};

// One primitive of one deformed object: rest vertices [restFirst, +vertexCount)
// become scene vertices [vertexFirst, +vertexCount).
struct SgSkinningPush {
  uint restFirst;
  uint vertexFirst;
  uint vertexCount;
  uint influenceFirst;  // kSkinNone: not skinned
  uint jointFirst;      // the object's first joint matrix
  uint deltaFirst;      // target t of vertex v: deltas[deltaFirst + t * vertexCount + v]
  uint targetCount;
  uint weightFirst;     // the object's first morph weight
};

SG_SHARED_END

#endif
