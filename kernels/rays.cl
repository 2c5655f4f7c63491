/* rays.cl — primary rays from the seed camera model (host/render/camera.hpp). */

typedef struct ray_t {
  vec3_t origin;
  vec3_t dir; /* unit */
} ray_t;

/* The ray through pixel (px, py), row 0 at the top; fractional coordinates sample inside a pixel.
 * The seed indexes columns from the right and rows from the bottom (its first pixel p_1m is
 * bottom-right for a right-handed world), hence the flips. */
ray_t camera_ray(__constant const fr_frame_constants* fc, real_t px, real_t py) {
  real_t i = (real_t)(fc->width - 1) - px;
  real_t j = (real_t)(fc->height - 1) - py;
  vec3_t d = v3_from_float4(fc->first_pixel_dir);
  d = v3_mad(d, v3_from_float4(fc->pixel_step_x), i);
  d = v3_mad(d, v3_from_float4(fc->pixel_step_y), j);
  ray_t ray;
  ray.origin = v3_from_float4(fc->eye);
  ray.dir = v3_normalize(d);
  return ray;
}

/* Hit threshold at path length t from the eye: the clarity function k * t * pixel angle, never
 * below a few ulp of |p| so that far from the origin the test stays meaningful in float. */
inline real_t hit_threshold(__constant const fr_frame_constants* fc, real_t t, vec3_t p) {
  real_t clarity = (real_t)(fc->hit_threshold_k * fc->pixel_angle_rad) * t;
  real_t ulp_floor = (real_t)(4 * FR_SCALAR_EPSILON) * v3_length(p);
  return fmax(clarity, ulp_floor);
}
