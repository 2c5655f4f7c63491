/* cantor_dust.c — Cantor's dust in 3D (Georg Cantor, 1883): each cube replaced by its eight corner
 * cubes, 1/scale of its size, recursively. The DE is the exact distance to the cubes of the last
 * level. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_SCALE, P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc scale =
    FR_FLOAT_PARAM("scale", "Scale", "Fractal",
                   "Each corner cube is 1/scale of its parent; 3 is the classic dust.", 3.0, 1.5, 6,
                   FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations = FR_INT_PARAM(
    "iterations", "Levels", "Fractal", "Levels of subdivision.", 4, 1, 12, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.75, 0.4);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.3, 0.45, 0.7);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&scale, &iterations, &color_near, &color_far,
                                                     &color_contrast};

/* The whole cloud from a corner. */
static const fr_camera camera = FR_CAMERA(2.0, 1.5, 2.4, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "cantor_dust",
    .name = "Cantor dust",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Cantor's dust: every cube becomes its eight corners, a cloud of ever smaller cubes.",
    .tags = "ifs cube dust",
    .credit =
        "Georg Cantor, 'Ueber unendliche, lineare Punktmannichfaltigkeiten', Mathematische "
        "Annalen, 1883 (the middle-thirds set)",
    .de_source = fr_de_source,
    .de_source_name = "cantor_dust.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "cantor_dust_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.82, /* the unit cube has radius sqrt(3); the dust lies in it */
};

FR_SCENE_ENTRY(&scene);
