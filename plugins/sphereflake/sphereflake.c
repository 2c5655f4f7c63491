/* sphereflake.c — A sphereflake after Eric Haines ("A Proposal for Standard Graphics Environments",
 * IEEE CG&A, 1987), with six children on the axes: a sphere carries six smaller spheres, each of
 * which carries six more. The DE is exact up to the last level's bounding balls. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_CHILD_SCALE,
  P_LEVELS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_TRANSLUCENCY,
  P_MEAN_FREE_PATH,
  P_COUNT
};

static const fr_param_desc child_scale = FR_FLOAT_PARAM(
    "child_scale", "Child size", "Fractal", "Each child's radius relative to its parent.", 0.36,
    0.15, 0.4, FR_PARAM_ANIMATABLE);
static const fr_param_desc levels = FR_INT_PARAM(
    "levels", "Levels", "Fractal", "Generations of children.", 6, 1, 12, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.9, 0.85);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.85, 0.45, 0.2);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

/* Path tracing (the material function in sphereflake_surface.cl): marble-like spheres that
 * scatter light under a thin clear coat. */
static const fr_param_desc translucency = FR_FLOAT_PARAM(
    "translucency", "Translucency", "Material",
    "Path tracing: the share of the spheres' diffuse light that scatters under the surface.", 1.0,
    0, 1, FR_PARAM_ANIMATABLE);
static const fr_param_desc mean_free_path = FR_FLOAT_PARAM(
    "mean_free_path", "Mean free path", "Material",
    "Path tracing: world units between scatterings under the surface; larger is more "
    "translucent (and slower).",
    0.05, 0.002, 1, FR_PARAM_ANIMATABLE | FR_PARAM_LOG_SCALE);

static const fr_param_desc* const params[P_COUNT] = {&child_scale,   &levels,         &color_near,
                                                     &color_far,     &color_contrast, &translucency,
                                                     &mean_free_path};

/* The whole flake from above a corner. */
static const fr_camera camera = FR_CAMERA(3.6, 2.6, 4.4, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
/* A sun of 2 degrees' radius (soft shadows when path traced; a direction to the fast integrator).
 */
static const fr_light light_0 = FR_SUN_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3, 0.035);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* The whole flake lies within 1 + 2 k / (1 - k) of its centre (k the child size). */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  const double k = v[P_CHILD_SCALE].v[0];
  state->bounding_radius = 1.02 * (1.0 + 2.0 * k / (1.0 - k)) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "sphereflake",
    .name = "Sphereflake",
    .version = "1.1.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "A sphereflake after Eric Haines: spheres on spheres on spheres, six to a parent.",
    .tags = "ifs spheres",
    .credit =
        "Eric Haines, 'A Proposal for Standard Graphics Environments', IEEE Computer Graphics and "
        "Applications 7(11), 1987",
    .de_source = fr_de_source,
    .de_source_name = "sphereflake.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "sphereflake_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_REFLECTIONS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.3,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
