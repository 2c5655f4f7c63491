/* crystal_garden.c — Knighty's kaleidoscopic crystals grown on a plain: icosahedral, octahedral,
 * tetrahedral and cube-cornered ones, twisted by one shared angle. A composed scene from the DE
 * library. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_TWIST_DEG,
  P_ITERATIONS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_GLASS,
  P_IOR,
  P_TINT,
  P_COUNT
};

static const fr_param_desc twist_deg = FR_FLOAT_PARAM(
    "twist_deg", "Twist", "Fractal", "The rotation each crystal turns by per fold, degrees.", 12.0,
    -60, 60, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Levels of each crystal.", 10, 3, 20,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.85, 0.7);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.35, 0.5, 0.75);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

/* Path tracing (the material function in crystal_garden_surface.cl): the crystals are glass. */
static const fr_param_desc glass =
    FR_FLOAT_PARAM("glass", "Glass", "Material",
                   "Path tracing: the share of the crystals' light that enters them (0: opaque).",
                   1.0, 0, 1, FR_PARAM_ANIMATABLE);
static const fr_param_desc ior =
    FR_FLOAT_PARAM("ior", "Index of refraction", "Material",
                   "Path tracing: the crystals' index of refraction (quartz 1.55, diamond 2.42).",
                   1.55, 1, 2.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc tint = FR_FLOAT_PARAM(
    "tint", "Tint", "Material",
    "Path tracing: how strongly the crystals absorb the complement of their colour, per world "
    "unit.",
    1.5, 0, 20, FR_PARAM_ANIMATABLE);

static const fr_param_desc* const params[P_COUNT] = {
    &twist_deg, &iterations, &color_near, &color_far, &color_contrast, &glass, &ior, &tint};

/* Across the garden, from a little above. */
static const fr_camera camera = FR_CAMERA(4.2, 1.6, 5.2, 0.0, -0.3, 0.0, 0.0, 1.0, 0.0, 50.0);
/* A sun of 1.5 degrees' radius (soft shadows when path traced; a direction to the fast integrator).
 */
static const fr_light light_0 = FR_SUN_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3, 0.026);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "crystal_garden",
    .name = "Crystal garden",
    .version = "1.1.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "Knighty's kaleidoscopic crystals, five kinds, grown on a plain of sand.",
    .tags = "showcase kifs crystals",
    .credit =
        "Knighty, 'Kaleidoscopic (escape time) IFS', fractalforums.com, 2010; composed by the "
        "Fractalis developers",
    .de_source = fr_de_source,
    .de_source_name = "crystal_garden.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "crystal_garden_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 7.5, /* the ground disc, radius 7 */
};

FR_SCENE_ENTRY(&scene);
