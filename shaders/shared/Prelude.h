// Lets the headers in shaders/shared/ compile as both GLSL and C++: in C++ the GLSL
// vector types are GLM's and every struct gets a namespace. Only vec4, uvec4 and mat4
// members are used, so std140 and C++ layouts agree without padding rules to remember.
#ifdef __cplusplus
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
namespace specula::shared {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
} // namespace specula::shared
#define SPECULA_SHARED_BEGIN namespace specula::shared {
#define SPECULA_SHARED_END }
#else
#define SPECULA_SHARED_BEGIN
#define SPECULA_SHARED_END
#endif
