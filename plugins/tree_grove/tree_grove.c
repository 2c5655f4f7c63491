/* tree_grove.c — Pythagoras trees on a grassy knoll, five of them, each turned and sized its own
 * way: a composed scene from the DE library, in haze. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_CHILD_SCALE, P_TILT_DEG, P_LEVELS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc child_scale = FR_FLOAT_PARAM(
    "child_scale", "Branch ratio", "Fractal", "Each branch's size relative to its parent.", 0.5,
    0.3, 0.62, FR_PARAM_ANIMATABLE);
static const fr_param_desc tilt_deg =
    FR_FLOAT_PARAM("tilt_deg", "Tilt", "Fractal", "How far each branch leans out, degrees.", 48.0,
                   10, 80, FR_PARAM_ANIMATABLE);
static const fr_param_desc levels = FR_INT_PARAM(
    "levels", "Levels", "Fractal", "Generations of branches.", 8, 2, 12, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.38, 0.26, 0.16);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.5, 0.7, 0.3);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&child_scale, &tilt_deg,  &levels,
                                                     &color_near,  &color_far, &color_contrast};

/* Across the knoll at eye height. */
static const fr_camera camera = FR_CAMERA(4.4, 1.4, 5.4, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 50.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "tree_grove",
    .name = "Tree grove",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "Five Pythagoras trees on a grassy knoll, each turned and sized its own way.",
    .tags = "showcase tree ifs",
    .credit = "Albert E. Bosman, the Pythagoras tree, 1942; composed by the Fractalis developers",
    .de_source = fr_de_source,
    .de_source_name = "tree_grove.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "tree_grove_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_FOG,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 7.5, /* the ground disc, radius 7 */
};

FR_SCENE_ENTRY(&scene);
