/* jerusalem_cube.c — the Jerusalem cube (Eric Baird, 2011): a cube replaced by 8 corner cubes
 * scaled by sqrt(2) - 1 and 12 edge cubes scaled by its square, leaving a cross-shaped tunnel
 * through every face, at every level. The DE is a lower bound (kernels/de/jerusalem.cl). */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COUNT };

static const fr_param_desc iterations = FR_INT_PARAM(
    "iterations", "Level", "Fractal", "Recursion level.", 5, 1, 10, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (corners)", "Colour",
                   "Albedo of points that descended through corner cubes.", 0.85, 0.78, 0.62);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (edges)", "Colour",
                   "Albedo of points that descended through edge cubes.", 0.55, 0.20, 0.16);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &color_near, &color_far};

static const fr_camera camera = FR_CAMERA(2.5, 1.9, 3.2, 0.0, -0.1, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.5, -0.8, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.25);
static const fr_light* const lights[] = {&key, &fill};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "jerusalem_cube",
    .name = "Jerusalem cube",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Eric Baird's Jerusalem cube: corner and edge cubes of two sizes, crosses cut through.",
    .tags = "ifs cube cross",
    .credit = "Eric Baird, 'The Jerusalem Cube', 2011",
    .de_source = fr_de_source,
    .de_source_name = "jerusalem_cube.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "jerusalem_cube_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.8, /* the cube's corner, sqrt(3), with a margin */
    .update = NULL,
};

FR_SCENE_ENTRY(&scene);
