#include "app/camera_controller.hpp"
#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fr {
CameraMotion update_camera(fr_camera& camera, CameraMode mode, const InputState& input, bool look,
                           double dt_s, double surface_distance, const CameraControls& c) {
  CameraMotion motion;
  glm::dvec3 eye = to_dvec3(camera.eye), target = to_dvec3(camera.target);
  // At a pole (up parallel to the view) the image's own stable up (scene/camera_up.hpp).
  const glm::dvec3 up = glm::normalize(effective_up(camera));
  glm::dvec3 forward = target - eye;
  double target_distance = glm::length(forward);
  forward /= target_distance;

  // Turning: yaw about up, pitch about right, kept away from the poles so up stays valid.
  if (look && (input.look_dx != 0 || input.look_dy != 0)) {
    const double rad_per_px = c.mouse_sensitivity_deg_per_px * std::numbers::pi / 180.0;
    const double yaw = -input.look_dx * rad_per_px;
    const double pitch = (c.invert_y ? input.look_dy : -input.look_dy) * rad_per_px;
    glm::dvec3 turned = glm::angleAxis(yaw, up) * forward;
    const glm::dvec3 right = glm::normalize(glm::cross(turned, up));
    const glm::dvec3 pitched = glm::angleAxis(pitch, right) * turned;
    if (std::abs(glm::dot(pitched, up)) < 0.995) turned = pitched;
    forward = glm::normalize(turned);
    motion.moved = true;
  }

  const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
  glm::dvec3 move(0.0);
  if (input.is_held(Action::MoveForward)) move += forward;
  if (input.is_held(Action::MoveBack)) move -= forward;
  if (input.is_held(Action::MoveRight)) move += right;
  if (input.is_held(Action::MoveLeft)) move -= right;
  if (input.is_held(Action::MoveUp)) move += up;
  if (input.is_held(Action::MoveDown)) move -= up;

  double speed = c.speed_per_distance * std::max(surface_distance, 0.0);
  if (input.is_held(Action::SpeedUp)) speed *= c.speed_up_factor;
  speed = std::clamp(speed, c.min_speed, c.max_speed);
  // Never move more than 0.9 of the distance to the surface in one frame.
  const double max_step = 0.9 * std::max(surface_distance, 0.0);

  if (mode == CameraMode::Fly) {
    if (glm::length(move) > 0) {
      const double step = std::min(speed * dt_s, max_step > 0 ? max_step : speed * dt_s);
      eye += glm::normalize(move) * step;
      motion.moved = true;
    }
    target = eye + forward * target_distance;
  } else {
    // Orbit: the eye sits at target - forward * distance; forward/back and the wheel zoom.
    double zoom = 0;
    if (input.is_held(Action::MoveForward)) zoom += speed * dt_s;
    if (input.is_held(Action::MoveBack)) zoom -= speed * dt_s;
    zoom += input.wheel * 0.1 * target_distance;
    if (zoom != 0) motion.moved = true;
    if (max_step > 0) zoom = std::min(zoom, max_step);
    target_distance = std::max(target_distance - zoom, 1e-6);
    eye = target - forward * target_distance;
  }
  store_dvec3(camera.eye, eye);
  store_dvec3(camera.target, target);
  return motion;
}

}  // namespace fr
