/* frame_constants.h — the per-frame constants, declared once for the host (C++) and the device
 * (OpenCL C). Only 4-byte float and int fields, and float[4] for vectors, so the layout is the
 * same on both sides with no padding rules to get wrong; host/render/frame_constants.cpp freezes
 * it with static_asserts. Vectors are world space; angles are radians; lengths are world units. */
#ifndef FR_FRAME_CONSTANTS_H
#define FR_FRAME_CONSTANTS_H

#define FR_MAX_LIGHTS 8
/* light_kind's values: the ABI's FR_LIGHT_DIRECTIONAL and FR_LIGHT_POINT (checked by the host). */
#define FR_KERNEL_LIGHT_DIRECTIONAL 1
#define FR_KERNEL_LIGHT_POINT 2
#define FR_CONE_BLOCK 8 /* pixels a side of the cone pre-pass's blocks (cone.cl) */

/* DE-evaluation counters (kernels/eval_counts.cl), filled only by kernels built to count. One cell
 * per (bounce, kind): bounce 0 is the primary ray, 1..FR_COUNT_MAX_BOUNCES the mirror bounces;
 * kind is one of the FR_COUNT_* below, the shadow kind plus the light's index. Each cell holds two
 * uints: evaluations by lanes that wanted them, and lane evaluations made (a packet evaluation
 * makes FR_LANES: the work the SIMD unit did). Work-item w adds its sums to slot w % FR_COUNT_SLOTS, so no 32-bit
 * cell overflows below 2^32 x FR_COUNT_SLOTS evaluations of one kind in a frame; the host adds the
 * slots up in 64 bits. Buffer layout: uint counts[FR_COUNT_SLOTS][FR_COUNT_CELLS][2]. */
#define FR_COUNT_MARCH 0
#define FR_COUNT_NORMALS 1
#define FR_COUNT_SURFACE 2
#define FR_COUNT_AO 3
#define FR_COUNT_CONE 4
#define FR_COUNT_SHADOW 5
#define FR_COUNT_KINDS (FR_COUNT_SHADOW + FR_MAX_LIGHTS)
#define FR_COUNT_MAX_BOUNCES 8
#define FR_COUNT_CELLS ((FR_COUNT_MAX_BOUNCES + 1) * FR_COUNT_KINDS)
#define FR_COUNT_SLOTS 256

typedef struct fr_frame_constants {
  /* Camera, in the camera model's terms (host/render/camera.hpp), for the whole image (of
   * full_width x full_height pixels, of which this one may be a window): the ray through its pixel
   * column x, row y (row 0 at the top) has direction first_pixel_dir + pixel_step_x *
   * (full_width - 1 - x) + pixel_step_y * (full_height - 1 - y), normalised. Each of these four vectors is the rounded
   * float of the double value; the *_lo fields further down hold what rounding lost, so the
   * double kernel rebuilds the double camera as hi + lo ("double end to end"). Rays start at
   * ray_start below, not at the eye. */
  float first_pixel_dir[4]; /* p_1m */
  float pixel_step_x[4];    /* q_x */
  float pixel_step_y[4];    /* q_y */
  float camera_right[4];    /* unit vectors of the image plane and view, for the lens */
  float camera_up[4];
  float camera_forward[4];

  float light_vector[FR_MAX_LIGHTS][4]; /* xyz: direction of travel (directional) or position
                                           (point); w: zero */
  float light_color[FR_MAX_LIGHTS][4];  /* rgb: colour x intensity; w: zero */
  int light_kind[FR_MAX_LIGHTS];        /* FR_KERNEL_LIGHT_DIRECTIONAL or _POINT */
  float light_attenuation[FR_MAX_LIGHTS]; /* point lights: a of k / (1 + a d^e); else 0 */
  float light_falloff[FR_MAX_LIGHTS];     /* point lights: e of k / (1 + a d^e); else 0 */

  float ambient_color[4];
  float albedo[4]; /* the material without a scene surface source; w: zero */
  float sky_zenith[4];
  float sky_horizon[4];
  float sky_up[4];     /* unit "up" of the sky gradient: the camera's up vector */
  float glow_color[4]; /* rgb; w: zero */
  float fog_color[4];  /* rgb; w: zero */

  int width;
  int height;
  int max_steps;        /* march iterations per ray */
  int shadow_max_steps; /* march iterations per shadow ray */
  int light_count;
  int max_bounces;      /* mirror bounces after the primary hit */
  int ao_samples;       /* samples of the sampled ambient occlusion */
  int sample_index;     /* 0 for the first sample of an accumulation */

  float pixel_angle_rad;   /* angle between neighbouring pixel centres at the image centre */
  float hit_threshold_k;   /* epsilon = k * t * pixel_angle_rad (the clarity function) */
  float bounding_radius;   /* the scene's surface lies inside this sphere around the origin */
  float step_scale;        /* multiplies each DE step (< 1 for DEs that over-estimate) */
  float ao_strength;       /* step-count: exponent; sampled: occlusion gain */
  float ao_distance;       /* sampled AO: farthest sample along the normal */
  float shadow_softness;   /* penumbra factor k of the soft-shadow term; larger is harder */
  float specular_strength; /* Blinn-Phong weight */
  float specular_power;    /* Blinn-Phong exponent */
  float roughness;         /* Oren-Nayar sigma, radians */
  float fresnel_f0;        /* Schlick reflectance at normal incidence */
  float fog_density;       /* exponential fog: 1 - exp(-density * t) */
  float glow_falloff;      /* glow = strength * exp(-closest approach / falloff) */
  float aperture_radius;   /* thin lens; 0 is a pinhole */
  float focus_distance;    /* along the view direction */
  float jitter_x;          /* sub-pixel offset of this sample, pixels */
  float jitter_y;
  float accumulate_weight; /* weight of this sample in the running mean: 1 / (sample_index + 1) */
  float relaxation;        /* over-relaxation factor omega of the march, in [1, 2) */
  float reflectivity;      /* of the material without a scene surface source */
  float glow_strength;     /* glow = strength * exp(-closest approach / falloff) */
  float fog_scale;         /* power-law fog: amount = fog_scale * t^0.75 (t in world units) */

  /* What float rounding lost of the camera vectors above (double kernels add it back). */
  float first_pixel_dir_lo[4];
  float pixel_step_x_lo[4];
  float pixel_step_y_lo[4];
  /* Where primary rays start (rays.cl): not at the eye but on the plane start_scale * (the
   * direction's component along the view) ahead of it, just in front of the bounding sphere, so
   * that a far camera's rays start next to the object and keep float's precision there. The ray
   * of image offset (i - (width-1)/2, j - (height-1)/2) from the centre starts at
   * ray_start + start_step_x * i' + start_step_y * j', having travelled start_scale * |d|. All
   * zero-offset (start at the eye) when the eye is inside the bounds or the lens is on. */
  float ray_start[4];
  float ray_start_lo[4];
  float start_step_x[4];
  float start_step_x_lo[4];
  float start_step_y[4];
  float start_step_y_lo[4];
  float start_scale;
  float start_scale_lo;
  float ao_reference_steps; /* step-count AO: this many steps is full occlusion */
  int refine_steps;         /* plain DE steps after a hit, towards the surface (march.cl) */
  /* The cone pre-pass (cone.cl): blocks of FR_CONE_BLOCK pixels on the whole image's grid, so
   * that a window of it (a poster's band) has the same blocks; the phase is the window's offset
   * into its first block. */
  int cone_phase_x;
  int cone_phase_y;
  int cone_blocks_x; /* blocks covering this image (or window) */
  int cone_blocks_y;
  /* Mirror bounces (reflect.cl) march at most this many steps (never more than max_steps), and
   * their shadow rays at most this many (0: reflections show no shadows). */
  int bounce_max_steps;
  int bounce_shadow_max_steps;
  /* The whole image's pixel of this image's pixel (x, y) is (pixel_origin_x + x * pixel_stride_x,
   * ...): a window (a poster's band, a lattice) draws the whole image's random numbers. */
  int pixel_origin_x;
  int pixel_origin_y;
  int pixel_stride_x;
  int pixel_stride_y;
  int full_width; /* the whole image's size: the camera vectors above are the whole image's */
  int full_height;
  int seed;             /* of the random numbers (path tracing, the lens) */
  int path_max_bounces; /* path tracing: surface interactions after the first hit (path.cl) */
  /* Path tracing's glass (path.cl): the share of the unmirrored light that enters, the index of
   * refraction, and the absorption coefficient per world unit (times 1 - the surface colour);
   * and the surface's emission. */
  float transmission;
  float ior;
  float absorption;
  float emission; /* path tracing: light a surface gives off, times its colour */
  /* Path tracing's lights have a size (fr_light.radius): a point light's sphere radius, a
   * directional light's angular radius in radians; 0 is a point. */
  float light_radius[FR_MAX_LIGHTS];
  /* Path tracing's default material beyond the colour (path.cl, material_t): the metallic share,
   * the gloss's roughness (GGX alpha = roughness^2), the share of the diffuse light that scatters
   * under the surface and its mean free path there (world units). */
  float metalness;
  float specular_roughness;
  float subsurface;
  float mean_free_path;
  int aperture_blades; /* the lens's aperture: a regular polygon of this many sides; < 3: round */
  /* The sky's panorama (environment.cl), when there is one: its frame (x, y = its zenith, z;
   * unit, world space), its size in pixels and the factor its radiance is scaled by. */
  float env_axes[3][4];
  int env_width;
  int env_height;
  float env_intensity;
  float hit_threshold_abs; /* > 0: epsilon is this, in world units, instead of the clarity term */
  /* The centre of the bounding sphere (hi, and what float rounding lost): the origin, except in a
   * double-double kernel, whose coordinates are relative to the eye (dd_relative.cl): -eye. */
  float bounding_centre[4];
  float bounding_centre_lo[4];
  /* The hit threshold's floor is a few ulps of max(|p|, this) (rays.cl): the eye's distance from
   * the bounding centre, between 1/1024 of the bounding radius and the radius
   * (threshold_floor_scale, host/render/frame_constants.hpp). */
  float threshold_floor_scale;
} fr_frame_constants;

#endif /* FR_FRAME_CONSTANTS_H */
