// vec3.hpp — the one conversion between the ABI's plain double[3] (fr_camera's eye, target, up;
// fr_light's position) and glm's dvec3, which the host computes with.
#pragma once

#include <glm/vec3.hpp>

#include <array>

namespace fr {

inline glm::dvec3 to_dvec3(const double v[3]) {
  return {v[0], v[1], v[2]};
}

inline void store_dvec3(double out[3], const glm::dvec3& v) {
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}

// Rounded to float, for what a float kernel or probe takes.
inline std::array<float, 3> to_float3(const double v[3]) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

}  // namespace fr
