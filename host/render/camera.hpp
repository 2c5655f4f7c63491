// camera.hpp — the pinhole camera model below: primary rays for a k x m image.
//
// With eye E, target T, up w and horizontal field of view theta:
//   t = T - E,  b = w x t,  v = t x b           (then normalised: t_n, b_n, v_n)
//   g_x = tan(theta / 2),  g_y = g_x * m / k     (half-extents of the image plane at distance 1)
//   q_x = 2 g_x / (k - 1) * b_n,  q_y = 2 g_y / (m - 1) * v_n   (steps between pixel centres)
//   p_1m = t_n - g_x b_n - g_y v_n               (the model's first pixel)
//   ray(i, j) = normalise(p_1m + q_x (i - 1) + q_y (j - 1)),  i in 1..k, j in 1..m
// In a right-handed world b = w x t points to the viewer's left, so p_1m is the bottom-right
// pixel; image column x (0 = left) is i - 1 = k - 1 - x and row y (0 = top) is j - 1 = m - 1 - y.
#pragma once

#include "scene/scene_data.hpp"  // check_camera

#include <fractalis/scene.h>

#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace fr {

struct CameraRays {
  glm::dvec3 eye{0.0};
  glm::dvec3 first_pixel_dir{0.0};  // p_1m
  glm::dvec3 pixel_step_x{0.0};     // q_x
  glm::dvec3 pixel_step_y{0.0};     // q_y
  glm::dvec3 right{0.0};            // unit: image +x (the model's -b_n)
  glm::dvec3 up{0.0};               // unit: image up (v_n)
  glm::dvec3 forward{0.0};          // unit: view direction (t_n)
  int width_px = 0;
  int height_px = 0;
  double pixel_angle_rad = 0;  // angle between neighbouring pixel centres at the image centre
};

// The model's vectors for a width_px x height_px image (each >= 1). The camera must pass
// check_camera (scene/scene_data.hpp).
// mirror_vertical: the picture mirrored top to bottom (row y shows the ray of row height - 1 - y,
// or with pixel_corners the vertical offsets negated), as Mandelbulber2's
// legacy_coordinate_system draws; no camera move gives a mirror image.
// pixel_corners: Mandelbulber2's grid: the field of view spans the image edge to edge and pixel
// (x, y) looks through its top-left corner, at (2x / width - 1) g_x across and (1 - 2y / height)
// g_y up (g = tan of half the field of view); without it the first and last pixels' centres lie
// on the field of view's edges, at (2x / (width - 1) - 1) g_x.
CameraRays make_camera_rays(const fr_camera& camera, int width_px, int height_px,
                            bool mirror_vertical = false, bool pixel_corners = false);

// Unit direction of the ray through image pixel (x, y), row 0 at the top; the same arithmetic
// as kernels/rays.cl, in double.
glm::dvec3 camera_ray_dir(const CameraRays& rays, double x, double y);

}  // namespace fr
