#include "render/camera.hpp"
#include "scene/camera_up.hpp"
#include "scene/vec3.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace fr {
CameraRays make_camera_rays(const fr_camera& c, int k, int m) {
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
  // A one-pixel-wide image has a single column at the centre (the model divides by k - 1).
  r.pixel_step_x = k > 1 ? (2.0 * g_x / (k - 1)) * b_n : glm::dvec3(0.0);
  r.pixel_step_y = m > 1 ? (2.0 * g_y / (m - 1)) * v_n : glm::dvec3(0.0);
  r.first_pixel_dir = t_n - (k > 1 ? g_x : 0.0) * b_n - (m > 1 ? g_y : 0.0) * v_n;
  r.pixel_angle_rad = k > 1 ? std::atan(2.0 * g_x / (k - 1)) : 2.0 * std::atan(g_x);
  return r;
}

CameraRays window_rays(const CameraRays& full, int x0, int y0, int w, int h) {
  // The model counts pixels from the image's far corner (i = W - 1 - x): the window's first
  // pixel direction is the full image's, stepped by the columns and rows beyond the window.
  CameraRays r = full;
  r.first_pixel_dir = full.first_pixel_dir +
                      full.pixel_step_x * static_cast<double>(full.width_px - x0 - w) +
                      full.pixel_step_y * static_cast<double>(full.height_px - y0 - h);
  r.width_px = w;
  r.height_px = h;
  return r;
}

glm::dvec3 camera_ray_dir(const CameraRays& r, double x, double y) {
  const double i = (r.width_px - 1) - x, j = (r.height_px - 1) - y;
  return glm::normalize(r.first_pixel_dir + r.pixel_step_x * i + r.pixel_step_y * j);
}

std::optional<glm::dvec2> camera_project(const CameraRays& r, const glm::dvec3& point) {
  const glm::dvec3 d = point - r.eye;
  const double forward = glm::dot(d, r.forward);
  if (!(forward > 0)) return std::nullopt;
  // Scaled to forward distance 1, the ray is first_pixel_dir + pixel_step_x i + pixel_step_y j:
  // both steps are across the view (perpendicular to it and to each other), and the first
  // pixel's direction is 1 along it, so i and j are the offset's components along the steps.
  const glm::dvec3 offset = d / forward - r.first_pixel_dir;
  const double step_x2 = glm::dot(r.pixel_step_x, r.pixel_step_x);
  const double step_y2 = glm::dot(r.pixel_step_y, r.pixel_step_y);
  const double i = step_x2 > 0 ? glm::dot(offset, r.pixel_step_x) / step_x2 : 0;
  const double j = step_y2 > 0 ? glm::dot(offset, r.pixel_step_y) / step_y2 : 0;
  return glm::dvec2((r.width_px - 1) - i, (r.height_px - 1) - j);
}

}  // namespace fr
