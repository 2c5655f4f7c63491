/* frame_constants.h — the per-frame constants, declared once for the host (C++) and the device
 * (OpenCL C). Only 4-byte float and int fields, and float[4] for vectors, so the layout is the
 * same on both sides with no padding rules to get wrong; host/render/frame_constants.cpp freezes
 * it with static_asserts. Vectors are world space; angles are radians. */
#ifndef FR_FRAME_CONSTANTS_H
#define FR_FRAME_CONSTANTS_H

typedef struct fr_frame_constants {
  /* Camera, in the seed model's terms (host/render/camera.hpp): the ray through pixel column x,
   * row y (row 0 at the top) has direction first_pixel_dir + pixel_step_x * (width - 1 - x)
   * + pixel_step_y * (height - 1 - y), normalised. */
  float eye[4];
  float first_pixel_dir[4]; /* p_1m */
  float pixel_step_x[4];    /* q_x */
  float pixel_step_y[4];    /* q_y */

  float to_light[4];     /* unit vector from the surface towards the (directional) light */
  float light_color[4];  /* linear RGB times intensity */
  float ambient_color[4];
  float albedo[4];
  float sky_zenith[4];
  float sky_horizon[4];
  float sky_up[4]; /* unit "up" of the sky gradient: the camera's up vector */

  int width;
  int height;
  int max_steps;        /* march iterations per ray */
  int shadow_max_steps; /* march iterations per shadow ray */

  float pixel_angle_rad;   /* angle between neighbouring pixel centres at the image centre */
  float hit_threshold_k;   /* epsilon = k * t * pixel_angle_rad (the clarity function) */
  float max_distance;      /* rays end here */
  float bounding_radius;   /* the scene's surface lies inside this sphere around the origin */
  float step_scale;        /* multiplies each DE step (< 1 for DEs that over-estimate) */
  float ao_strength;       /* exponent of the step-count occlusion term */
  float shadow_softness;   /* penumbra factor k of the soft-shadow term; larger is harder */
  float specular_strength; /* Blinn-Phong weight */
  float specular_power;    /* Blinn-Phong exponent */
  float reserved[3];       /* zero; keeps the struct a multiple of 16 bytes */
} fr_frame_constants;

#endif /* FR_FRAME_CONSTANTS_H */
