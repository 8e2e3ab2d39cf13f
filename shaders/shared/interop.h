// Lets one header declare a layout for both C++ and GLSL (include it first in shared headers).
//
//   SSR_SHARED_BEGIN                   opens namespace ssr::shared (with GLM's names) in C++,
//                                      nothing in GLSL
//   float thickness SSR_DEFAULT(0.1);  "= 0.1" in C++ (a default), nothing in GLSL
//   SSR_FN vec3 f(vec3 x) { ... }      a function both languages compile ("inline" in C++)
//
// Only 4-byte scalars, vec4, ivec4, uvec4 and mat4 are used in shared *structs*, so std140/std430
// and C++ agree on every offset without hand-written padding rules (functions may use any type).
#ifdef __cplusplus
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#define SSR_SHARED_BEGIN namespace ssr::shared { using namespace glm; using uint = std::uint32_t;
#define SSR_SHARED_END }
#define SSR_DEFAULT(x) = x
#define SSR_FN inline
#else
#define SSR_SHARED_BEGIN
#define SSR_SHARED_END
#define SSR_DEFAULT(x)
#define SSR_FN
#endif
