/* fractalis/helpers.h — macros that spell out common declarations, for scene authors.
 *
 * Each expands to a braced initializer with designated fields, so a scene's tables read like
 * what they mean and stay correct if a struct grows at the end:
 *
 *   static const fr_param_desc power =
 *       FR_FLOAT_PARAM("power", "Power", "Fractal", "Exponent n.", 8, 2, 16, FR_PARAM_ANIMATABLE);
 *
 * Valid C11 and C++20. Nothing here is part of the binary ABI. */
#ifndef FRACTALIS_HELPERS_H
#define FRACTALIS_HELPERS_H

#include "fractalis/param.h"

#define FR_PARAM_DESC_(type_, key_, name_, group_, desc_, flags_, d0, d1, d2, l0, l1, l2, h0, h1, \
                       h2)                                                                        \
  {                                                                                               \
    .struct_size = sizeof(fr_param_desc), .type = (type_), .flags = (flags_), .reserved = 0,      \
    .key = (key_), .name = (name_), .group = (group_), .description = (desc_),                    \
    .default_value = {{(d0), (d1), (d2)}}, .min_value = {{(l0), (l1), (l2)}}, .max_value = {      \
      {(h0), (h1), (h2)}                                                                          \
    }                                                                                             \
  }

#define FR_FLOAT_PARAM(key, name, group, desc, def, min, max, flags) \
  FR_PARAM_DESC_(FR_PARAM_FLOAT, key, name, group, desc, flags, def, 0, 0, min, 0, 0, max, 0, 0)
#define FR_INT_PARAM(key, name, group, desc, def, min, max, flags) \
  FR_PARAM_DESC_(FR_PARAM_INT, key, name, group, desc, flags, def, 0, 0, min, 0, 0, max, 0, 0)
/* An iteration count whose each step resolves detail `ratio` times finer (ABI 1.4,
 * fr_param_desc.detail_ratio): the host raises it as a view deepens (render.auto_iterations). */
#define FR_ITERATIONS_PARAM(key_, name_, group_, desc_, def, min, max, flags_, ratio)            \
  {                                                                                              \
    .struct_size = sizeof(fr_param_desc), .type = FR_PARAM_INT, .flags = (flags_), .reserved = 0, \
    .key = (key_), .name = (name_), .group = (group_), .description = (desc_),                   \
    .default_value = {{(def), 0, 0}}, .min_value = {{(min), 0, 0}},                              \
    .max_value = {{(max), 0, 0}}, .detail_ratio = (ratio)                                        \
  }
#define FR_BOOL_PARAM(key, name, group, desc, def, flags) \
  FR_PARAM_DESC_(FR_PARAM_BOOL, key, name, group, desc, flags, def, 0, 0, 0, 0, 0, 1, 0, 0)
/* Each component of a vec3 lies in [min, max]. */
#define FR_VEC3_PARAM(key, name, group, desc, x, y, z, min, max, flags)                          \
  FR_PARAM_DESC_(FR_PARAM_VEC3, key, name, group, desc, flags, x, y, z, min, min, min, max, max, \
                 max)
#define FR_COLOR_PARAM(key, name, group, desc, r, g, b) \
  FR_PARAM_DESC_(FR_PARAM_COLOR, key, name, group, desc, 0, r, g, b, 0, 0, 0, 1, 1, 1)

/* A choice among named values (ABI 1.2): `names_` a static array of strings, `def` the index of
 * the default. Declare the scene with FR_SCENE_ENTRY_V1_2, since a 1.1 host does not know it. */
#define FR_CHOICE_PARAM(key_, name_, group_, desc_, def, names_, flags_)                           \
  {                                                                                                \
    .struct_size = sizeof(fr_param_desc), .type = FR_PARAM_CHOICE, .flags = (flags_),               \
    .reserved = 0, .key = (key_), .name = (name_), .group = (group_), .description = (desc_),       \
    .default_value = {{(def), 0, 0}}, .min_value = {{0, 0, 0}},                                     \
    .max_value = {{(double)(sizeof(names_) / sizeof((names_)[0])) - 1, 0, 0}}, .choices = (names_), \
    .choice_count = (uint32_t)(sizeof(names_) / sizeof((names_)[0])), .reserved2 = 0               \
  }

/* The number of elements of a static array, for fr_scene_desc.param_count and .light_count, so a
 * count can never disagree with its table. */
#define FR_ARRAY_COUNT(array) ((uint32_t)(sizeof(array) / sizeof((array)[0])))

#define FR_CAMERA(eye_x, eye_y, eye_z, target_x, target_y, target_z, up_x, up_y, up_z, fov) \
  {                                                                                         \
    .struct_size = sizeof(fr_camera), .reserved = 0, .eye = {(eye_x), (eye_y), (eye_z)},    \
    .target = {(target_x), (target_y), (target_z)}, .up = {(up_x), (up_y), (up_z)},         \
    .fov_deg = (fov)                                                                        \
  }

#define FR_DIRECTIONAL_LIGHT(dx, dy, dz, r, g, b, intensity_)                                    \
  {                                                                                              \
    .struct_size = sizeof(fr_light), .kind = FR_LIGHT_DIRECTIONAL, .vector = {(dx), (dy), (dz)}, \
    .color = {(r), (g), (b)}, .intensity = (intensity_), .attenuation = 0, .falloff = 2          \
  }

/* k / (1 + a d^e) with k = intensity, a = attenuation, e = falloff. */
#define FR_POINT_LIGHT(px, py, pz, r, g, b, intensity_, attenuation_, falloff_)            \
  {                                                                                        \
    .struct_size = sizeof(fr_light), .kind = FR_LIGHT_POINT, .vector = {(px), (py), (pz)}, \
    .color = {(r), (g), (b)}, .intensity = (intensity_), .attenuation = (attenuation_),    \
    .falloff = (falloff_)                                                                  \
  }

/* ABI 1.3 area lights (fr_light.radius): a glowing sphere of world-space radius `radius_`, and a
 * sun whose disc has the angular radius `angle_rad`. On an older host both are points. */
#define FR_SPHERE_LIGHT(px, py, pz, r, g, b, intensity_, attenuation_, falloff_, radius_)   \
  {                                                                                        \
    .struct_size = sizeof(fr_light), .kind = FR_LIGHT_POINT, .vector = {(px), (py), (pz)}, \
    .color = {(r), (g), (b)}, .intensity = (intensity_), .attenuation = (attenuation_),    \
    .falloff = (falloff_), .radius = (radius_)                                             \
  }
#define FR_SUN_LIGHT(dx, dy, dz, r, g, b, intensity_, angle_rad)                                 \
  {                                                                                              \
    .struct_size = sizeof(fr_light), .kind = FR_LIGHT_DIRECTIONAL, .vector = {(dx), (dy), (dz)}, \
    .color = {(r), (g), (b)}, .intensity = (intensity_), .attenuation = 0, .falloff = 2,         \
    .radius = (angle_rad)                                                                        \
  }

#endif /* FRACTALIS_HELPERS_H */
