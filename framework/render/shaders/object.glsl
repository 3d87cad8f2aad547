// Per-draw data (push constants) and the vertex layout of GpuScene.
#ifndef SG_OBJECT_GLSL
#define SG_OBJECT_GLSL

#extension GL_EXT_scalar_block_layout : require
#include "frame_interface.h"

layout(push_constant, scalar) uniform Object { SgObjectConstants object; };

#ifdef SG_VERTEX_SHADER
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
#endif

#endif
