#include "render/eye_relative.hpp"

namespace fr {

std::array<DoubleDouble, 3> eye_pairs(const fr_camera& camera, const CameraLow& low) {
  std::array<DoubleDouble, 3> eye;
  for (int i = 0; i < 3; ++i) eye[i] = pair_plus({camera.eye[i], 0}, low.eye[i]);
  return eye;
}

EyeRelativeView eye_relative_view(const SceneState& world, double resolution_rad) {
  EyeRelativeView v;
  v.state = world;
  const std::array<double, 3> view = view_vector(world.camera, world.camera_lo);
  const std::array<DoubleDouble, 3> pairs = eye_pairs(world.camera, world.camera_lo);
  glm::dvec3 eye(0.0);
  for (int i = 0; i < 3; ++i) {
    v.origin.eye[i] = pairs[i];
    eye[i] = pairs[i].hi;
    v.state.camera.eye[i] = 0;
    v.state.camera.target[i] = view[i];
  }
  v.state.camera_lo = CameraLow{};
  for (fr_light& l : v.state.lights)
    if (l.kind == FR_LIGHT_POINT)
      for (int i = 0; i < 3; ++i) l.vector[i] -= eye[i];
  v.origin.resolution_rad = static_cast<float>(resolution_rad);
  v.bounding_centre = -eye;
  return v;
}

}  // namespace fr
