/* menger_4d.c — The Menger sponge's four-dimensional sibling, sliced to 3D (fr/menger.cl): each
 * slice of the 4D sponge is a different lattice; the slice w = 0 is Cantor's dust. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_SLICE_W, P_SCALE, P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc slice_w = FR_FLOAT_PARAM(
    "slice_w", "Slice w", "Fractal", "The fourth coordinate of the slice, in [-1, 1].", 0.42, -1, 1,
    FR_PARAM_ANIMATABLE);
static const fr_param_desc scale =
    FR_FLOAT_PARAM("scale", "Scale", "Fractal", "Scale per level; 3 is the sponge.", 3.0, 2, 4,
                   FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations = FR_INT_PARAM(
    "iterations", "Levels", "Fractal", "The sponge's levels.", 4, 1, 8, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.75, 0.55);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.3, 0.4, 0.6);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&slice_w,    &scale,     &iterations,
                                                     &color_near, &color_far, &color_contrast};

/* The slice from a corner. */
static const fr_camera camera = FR_CAMERA(2.6, 1.9, 3.1, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "menger_4d",
    .name = "Menger sponge 4D",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "A 3D slice of the four-dimensional Menger sponge: each slice a different lattice of "
        "tunnels.",
    .tags = "ifs sponge 4d",
    .credit =
        "Karl Menger, 1926 (the sponge, in any dimension); the fold form after Knighty, "
        "fractalforums.com, 2010",
    .de_source = fr_de_source,
    .de_source_name = "menger_4d.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "menger_4d_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.82, /* the slice lies in the unit cube, radius sqrt(3) */
};

FR_SCENE_ENTRY(&scene);
