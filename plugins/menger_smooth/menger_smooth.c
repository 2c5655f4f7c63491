/* menger_smooth.c — The Menger sponge with smooth folds (after Darkbeam's smooth Menger,
 * fractalforums.com, 2012): every abs and every swap of the fold blended over `smoothness`, so the
 * sponge's edges round into a soft, bone-like lattice. The DE stays a lower bound (fr/menger.cl).
 */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SMOOTHNESS,
  P_SCALE,
  P_OFFSET,
  P_ITERATIONS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc smoothness = FR_FLOAT_PARAM(
    "smoothness", "Smoothness", "Fractal", "How far each fold is blended (squared width).", 0.01,
    0.0, 0.2, FR_PARAM_ANIMATABLE);
static const fr_param_desc scale =
    FR_FLOAT_PARAM("scale", "Scale", "Fractal", "Scale per level; 3 is the classic sponge.", 3.0, 2,
                   4, FR_PARAM_ANIMATABLE);
static const fr_param_desc offset =
    FR_VEC3_PARAM("offset", "Offset", "Fractal", "The corner each level scales about.", 1.0, 1.0,
                  1.0, 0, 2, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations = FR_INT_PARAM(
    "iterations", "Levels", "Fractal", "The sponge's levels.", 5, 1, 10, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.93, 0.88, 0.78);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.55, 0.42, 0.35);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &smoothness, &scale, &offset, &iterations, &color_near, &color_far, &color_contrast};

/* The rounded sponge from a corner. */
static const fr_camera camera = FR_CAMERA(2.9, 2.2, 3.4, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "menger_smooth",
    .name = "Smooth Menger sponge",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The Menger sponge with smooth folds: its tunnels rounded into a soft, bone-like lattice.",
    .tags = "ifs sponge smooth",
    .credit =
        "Karl Menger, 1926 (the sponge); smooth folds after Darkbeam, fractalforums.com, 2012",
    .de_source = fr_de_source,
    .de_source_name = "menger_smooth.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "menger_smooth_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.9, /* the smoothing only shrinks the unit cube (radius sqrt(3)) a little */
};

FR_SCENE_ENTRY(&scene);
