/* rays.cl — primary rays from the pinhole camera model (host/render/camera.hpp). */

typedef struct ray_t {
  vec3_t origin;
  vec3_t dir; /* unit */
} ray_t;

/* A host double stored as two floats (hi + lo): the double build gets the double back, the
 * float build the rounded float. */
inline scalar_t hi_lo(float hi, float lo) { return (scalar_t)hi + (scalar_t)lo; }
inline vec3_t v3_hi_lo(__constant const float* hi, __constant const float* lo) {
  return v3s(hi_lo(hi[0], lo[0]), hi_lo(hi[1], lo[1]), hi_lo(hi[2], lo[2]));
}

/* The ray through this image's pixel (px, py), row 0 at the top, moved by (jx, jy) whole-image
 * pixels (a sample's jitter); fractional coordinates sample inside a pixel. This image may be a
 * window of the whole (a poster's band, a lattice): its pixel is the whole image's
 * (pixel_origin + p * pixel_stride), computed exactly, and the ray the whole image's, bit for bit.
 * The model indexes columns from the right and rows from the bottom (its first pixel p_1m is
 * bottom-right for a right-handed world), hence the flips. The ray starts on the start plane
 * (frame_constants.h), *path_start from the eye: its origin is the start point of the image's
 * centre plus a small offset, so a far camera loses no precision (eye + dir * 1e6 in float would
 * round to the nearest 0.06 units). */
ray_t camera_ray(__constant const fr_frame_constants* fc, real_t px, real_t py, real_t jx,
                 real_t jy, real_t* path_start) {
  const real_t x = (real_t)fc->pixel_origin_x + px * (real_t)fc->pixel_stride_x + jx;
  const real_t y = (real_t)fc->pixel_origin_y + py * (real_t)fc->pixel_stride_y + jy;
  real_t i = (real_t)(fc->full_width - 1) - x;
  real_t j = (real_t)(fc->full_height - 1) - y;
  vec3_t d = v3_hi_lo(fc->first_pixel_dir, fc->first_pixel_dir_lo);
  d = v3_mad(d, v3_hi_lo(fc->pixel_step_x, fc->pixel_step_x_lo), i);
  d = v3_mad(d, v3_hi_lo(fc->pixel_step_y, fc->pixel_step_y_lo), j);
  const real_t ic = i - (real_t)((scalar_t)(fc->full_width - 1) * (scalar_t)0.5);
  const real_t jc = j - (real_t)((scalar_t)(fc->full_height - 1) * (scalar_t)0.5);
  ray_t ray;
  ray.origin = v3_hi_lo(fc->ray_start, fc->ray_start_lo);
  ray.origin = v3_mad(ray.origin, v3_hi_lo(fc->start_step_x, fc->start_step_x_lo), ic);
  ray.origin = v3_mad(ray.origin, v3_hi_lo(fc->start_step_y, fc->start_step_y_lo), jc);
  ray.dir = v3_normalize(d);
  *path_start = (real_t)hi_lo(fc->start_scale, fc->start_scale_lo) * v3_length(d);
  return ray;
}

/* A point relative to the bounding sphere's centre: the origin, except in a double-double kernel,
 * whose coordinates are relative to the eye (the centre at -eye). Other kernels compile the point
 * as it is: no work they do not need. */
#if FR_DD
#define FR_FROM_CENTRE(p) v3_sub((p), v3_hi_lo(fc->bounding_centre, fc->bounding_centre_lo))
#else
#define FR_FROM_CENTRE(p) (p)
#endif

/* Hit threshold at path length t from the eye: the clarity function k * t * pixel angle, never
 * below a few ulp of max(|p|, the eye's distance from the centre up to the bounding radius):
 * positions are only that precise (a ray's points are the eye's position plus a path), and
 * without the floor a ray next to a singular point (the Mandelbulb's centre, |p| -> 0, DE -> 0)
 * would crawl by ever smaller steps for its whole budget. Not the bounding radius alone: an
 * imported view's bound reaches as far as Mandelbulber2 could see (tens of units), and its
 * ulps would hide a close-up's detail in float. */
inline real_t hit_threshold(__constant const fr_frame_constants* fc, real_t t, vec3_t p) {
  real_t clarity = fc->hit_threshold_abs > 0 ? (real_t)fc->hit_threshold_abs
                                             : (real_t)(fc->hit_threshold_k * fc->pixel_angle_rad) * t;
  /* (|p| in world coordinates: a double-double kernel's p is relative to the eye, and its
   * positions are pairs, FR_POSITION_EPSILON.) */
  real_t ulp_floor = (real_t)(4 * FR_POSITION_EPSILON) *
                     fmax(v3_length(FR_FROM_CENTRE(p)), (real_t)fc->threshold_floor_scale);
  return fmax(clarity, ulp_floor);
}

/* The whole image's pixel of this image's pixel (frame_constants.h): random numbers drawn for it
 * do not depend on how the image was cut into windows (a poster's bands, MPI ranks). */
inline lane_uint_t image_pixel_x(__constant const fr_frame_constants* fc, real_t px) {
  return real_to_uint(px) * (uint)fc->pixel_stride_x + (uint)fc->pixel_origin_x;
}
inline lane_uint_t image_pixel_y(__constant const fr_frame_constants* fc, real_t py) {
  return real_to_uint(py) * (uint)fc->pixel_stride_y + (uint)fc->pixel_origin_y;
}

/* Uniform in [0, 1): a function of the whole image's pixel, the sample's index, the stream (one
 * per random decision) and the seed only. */
inline real_t pixel_random(__constant const fr_frame_constants* fc, lane_uint_t ix, lane_uint_t iy,
                           uint stream) {
  return random_unit(ix, iy, (uint)fc->sample_index, stream + (uint)fc->seed * 0x9E3779B9U);
}
