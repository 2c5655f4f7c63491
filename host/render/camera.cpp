#include "render/camera.hpp"
#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace fr {
CameraRays make_camera_rays(const fr_camera& c, int k, int m, bool mirror_vertical,
                            bool pixel_corners) {
  const glm::dvec3 t = to_dvec3(c.target) - to_dvec3(c.eye);
  const glm::dvec3 b = glm::cross(effective_up(c), t);
  const glm::dvec3 v = glm::cross(t, b);
  const glm::dvec3 t_n = glm::normalize(t), b_n = glm::normalize(b), v_n = glm::normalize(v);
  const double g_x = std::tan(c.fov_deg * std::numbers::pi / 360.0);
  const double g_y = g_x * m / k;
  CameraRays r;
  r.eye = to_dvec3(c.eye);
  r.right = -b_n;
  r.up = v_n;
  r.forward = t_n;
  r.width_px = k;
  r.height_px = m;
  // The first pixel's offsets along b_n and v_n (the model's p_1m: the bottom-right pixel).
  double first_x, first_y;
  if (pixel_corners) {
    // Column i from the right is image column k - 1 - i, at (2 (k - 1 - i) / k - 1) g_x across:
    // (1 - 2 / k) g_x - i (2 g_x / k), and b_n points left. Likewise rows from the bottom.
    r.pixel_step_x = (2.0 * g_x / k) * b_n;
    r.pixel_step_y = (2.0 * g_y / m) * v_n;
    first_x = (1.0 - 2.0 / k) * g_x;
    first_y = (1.0 - 2.0 / m) * g_y;
    r.pixel_angle_rad = std::atan(2.0 * g_x / k);
  } else {
    // A one-pixel-wide image has a single column at the centre (the model divides by k - 1).
    r.pixel_step_x = k > 1 ? (2.0 * g_x / (k - 1)) * b_n : glm::dvec3(0.0);
    r.pixel_step_y = m > 1 ? (2.0 * g_y / (m - 1)) * v_n : glm::dvec3(0.0);
    first_x = k > 1 ? g_x : 0.0;
    first_y = m > 1 ? g_y : 0.0;
    r.pixel_angle_rad = k > 1 ? std::atan(2.0 * g_x / (k - 1)) : 2.0 * std::atan(g_x);
  }
  // Mirrored, every row's vertical offset changes sign: the first row's and the step's.
  if (mirror_vertical) {
    first_y = -first_y;
    r.pixel_step_y = -r.pixel_step_y;
  }
  r.first_pixel_dir = t_n - first_x * b_n - first_y * v_n;
  return r;
}

glm::dvec3 camera_ray_dir(const CameraRays& r, double x, double y) {
  const double i = (r.width_px - 1) - x, j = (r.height_px - 1) - y;
  return glm::normalize(r.first_pixel_dir + r.pixel_step_x * i + r.pixel_step_y * j);
}

}  // namespace fr
