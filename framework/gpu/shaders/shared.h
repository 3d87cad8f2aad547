// Lets one header declare a shader interface for both C++ and GLSL, in the
// manner of Daxa's shared headers: constants, records and push-constant
// blocks are written once in the GLSL subset both languages accept, with
// GLSL's type names. C++ sees them in namespace sg::shader with the
// GLSL names mapped to fixed-size types and GLM. Records use scalar block
// layout on the GPU (the device requires scalarBlockLayout), which is C++'s
// natural layout of these types, so neither side pads by hand.
#ifndef SG_SHARED_H
#define SG_SHARED_H

#ifdef __cplusplus
#include <cstdint>

#include <glm/glm.hpp>

#define SG_CONST inline constexpr
#define SG_SHARED_BEGIN     \
  namespace sg::shader {      \
  using uint = std::uint32_t; \
  using uvec2 = glm::uvec2;   \
  using uvec4 = glm::uvec4;   \
  using ivec2 = glm::ivec2;   \
  using vec2 = glm::vec2;     \
  using vec3 = glm::vec3;     \
  using vec4 = glm::vec4;     \
  using mat4 = glm::mat4;
#define SG_SHARED_END }
#else
#define SG_CONST const
#define SG_SHARED_BEGIN
#define SG_SHARED_END
#endif

#endif
