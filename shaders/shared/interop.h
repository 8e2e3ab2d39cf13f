// Lets one header declare a layout for both C++ and GLSL (include it first in shared headers).
//
//   SSR_SHARED_BEGIN                   opens namespace ssr::shared in C++, nothing in GLSL
//   float thickness SSR_DEFAULT(0.1);  "= 0.1" in C++ (a default), nothing in GLSL
//
// Only 4-byte scalars, vec4, ivec4, uvec4 and mat4 are used in shared *structs*, so std140/std430
// and C++ agree on every offset without hand-written padding rules (functions may use any type).
#ifdef __cplusplus
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#define SSR_SHARED_BEGIN namespace ssr::shared { \
  using vec2 = glm::vec2; using vec3 = glm::vec3; using vec4 = glm::vec4; using mat3 = glm::mat3; using ivec4 = glm::ivec4; \
  using uvec4 = glm::uvec4; using mat4 = glm::mat4; using uint = std::uint32_t;
#define SSR_SHARED_END }
#define SSR_DEFAULT(x) = x
#else
#define SSR_SHARED_BEGIN
#define SSR_SHARED_END
#define SSR_DEFAULT(x)
#endif
