#include "app/camera_controller.hpp"
#include "io/dd_text.hpp"
#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fr {
namespace {

// A wheel notch zooms a quarter of the way in.
constexpr double kZoomPerNotch = 0.75;
constexpr double kNotchesPerSecondHeld = 4;

}  // namespace

double zoom_notches(const InputState& input, double dt_s) {
  double n = input.wheel;
  if (input.is_held(Action::ZoomIn)) n += kNotchesPerSecondHeld * dt_s;
  if (input.is_held(Action::ZoomOut)) n -= kNotchesPerSecondHeld * dt_s;
  return n;
}

CameraMotion update_camera(fr_camera& camera, CameraLow& low, CameraMode mode,
                           const InputState& input, bool look, double dt_s, double surface_distance,
                           const CameraControls& c, const ZoomPoint* zoom_point) {
  CameraMotion motion;
  // Relative to the eye: the eye at the origin, the target at target - eye from the pairs.
  const std::array<double, 3> view = view_vector(camera, low);
  glm::dvec3 eye(0.0), target(view[0], view[1], view[2]);
  // At a pole (up parallel to the view) the image's own stable up (scene/camera_up.hpp).
  fr_camera relative = camera;
  store_dvec3(relative.eye, eye);
  store_dvec3(relative.target, target);
  const glm::dvec3 up = glm::normalize(effective_up(relative));
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

  // The slowest speed is the controls', or a hundredth of the target's distance a second where
  // that is less: a deep view's whole scene is smaller than 1e-5.
  const double min_speed = std::min(c.min_speed, 0.01 * target_distance);
  double speed = c.speed_per_distance * std::max(surface_distance, 0.0);
  if (input.is_held(Action::SpeedUp)) speed *= c.speed_up_factor;
  speed = std::clamp(speed, min_speed, c.max_speed);
  // Never move more than 0.9 of the distance to the surface in one frame.
  const double max_step = 0.9 * std::max(surface_distance, 0.0);
  const double notches = zoom_notches(input, dt_s);
  // The nearest a zoom goes: where a pair no longer tells neighbouring points apart.
  const std::array<double, 3> eye_pair_scale = {std::abs(camera.eye[0]), std::abs(camera.eye[1]),
                                                std::abs(camera.eye[2])};
  const double floor_distance =
      0x1p-100 * std::max({eye_pair_scale[0], eye_pair_scale[1], eye_pair_scale[2], 1e-300});

  glm::dvec3 moved_by(0.0);  // of the eye
  if (mode == CameraMode::Fly) {
    if (glm::length(move) > 0) {
      const double step = std::min(speed * dt_s, max_step > 0 ? max_step : speed * dt_s);
      moved_by += glm::normalize(move) * step;
      motion.moved = true;
    }
    if (notches != 0 && zoom_point && zoom_point->distance > 0) {
      const glm::dvec3 dir(zoom_point->dir[0], zoom_point->dir[1], zoom_point->dir[2]);
      double along = (1 - std::pow(kZoomPerNotch, notches)) * zoom_point->distance;
      along = std::min(along, zoom_point->distance - floor_distance);
      if (max_step > 0) along = std::min(along, max_step);
      moved_by += dir * along;
      motion.moved = motion.moved || along != 0;
    }
    eye += moved_by;
    target = eye + forward * target_distance;
  } else {
    // Orbit: the eye sits at target - forward * distance; forward/back and the wheel zoom.
    double zoom = 0;
    if (input.is_held(Action::MoveForward)) zoom += speed * dt_s;
    if (input.is_held(Action::MoveBack)) zoom -= speed * dt_s;
    zoom += (1 - std::pow(kZoomPerNotch, notches)) * target_distance;
    if (zoom != 0) motion.moved = true;
    if (max_step > 0) zoom = std::min(zoom, max_step);
    target_distance =
        std::max(target_distance - zoom, std::max(0.01 * target_distance, floor_distance));
    eye = target - forward * target_distance;
  }
  // Back to world coordinates, in pairs: the target is the old eye plus its new offset (in
  // orbit mode the offset it had), the eye likewise.
  const double eye_hi[3] = {camera.eye[0], camera.eye[1], camera.eye[2]};
  const double eye_lo[3] = {low.eye[0], low.eye[1], low.eye[2]};
  for (int i = 0; i < 3; ++i) {
    const DoubleDouble moved_eye = pair_plus({eye_hi[i], eye_lo[i]}, eye[i]);
    camera.eye[i] = moved_eye.hi;
    low.eye[i] = moved_eye.lo;
    if (mode == CameraMode::Fly || target[i] != view[i]) {
      const DoubleDouble moved_target = pair_plus({eye_hi[i], eye_lo[i]}, target[i]);
      camera.target[i] = moved_target.hi;
      low.target[i] = moved_target.lo;
    }
  }
  return motion;
}

}  // namespace fr
