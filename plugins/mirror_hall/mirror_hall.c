/* mirror_hall.c — A sphereflake between two mirror walls on a mirror floor, repeated into a hall of
 * flakes: a composed scene from the DE library, with reflections. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_CHILD_SCALE, P_LEVELS, P_MIRROR, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc child_scale = FR_FLOAT_PARAM(
    "child_scale", "Child size", "Fractal", "Each child's radius relative to its parent.", 0.36,
    0.15, 0.4, FR_PARAM_ANIMATABLE);
static const fr_param_desc levels = FR_INT_PARAM(
    "levels", "Levels", "Fractal", "Generations of children.", 5, 1, 9, FR_PARAM_SPECIALIZE);
static const fr_param_desc mirror = FR_FLOAT_PARAM(
    "mirror", "Mirrors", "Colour", "How much the walls and floor mirror.", 0.8, 0, 1, 0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.93, 0.9);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.85, 0.5, 0.25);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&child_scale, &levels,    &mirror,
                                                     &color_near,  &color_far, &color_contrast};

/* Down the hall, the flake and its images. */
static const fr_camera camera = FR_CAMERA(1.6, 0.7, 5.2, 0.0, 0.1, 0.0, 0.0, 1.0, 0.0, 55.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "mirror_hall",
    .name = "Mirror hall",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "A sphereflake between mirrors, repeated into a hall of flakes.",
    .tags = "showcase spheres reflections",
    .credit = "Eric Haines' Sphereflake, 1987; composed by the Fractalis developers",
    .de_source = fr_de_source,
    .de_source_name = "mirror_hall.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "mirror_hall_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_REFLECTIONS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 7.5, /* the floor disc, radius 7, and the walls inside it */
};

FR_SCENE_ENTRY(&scene);
