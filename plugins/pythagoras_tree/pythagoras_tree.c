/* pythagoras_tree.c — A 3D Pythagoras tree (after Albert Bosman's tree, 1942): each branch carries
 * four smaller branches tilted outwards, down to twigs. The DE is exact up to the last level's
 * bounding balls. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_CHILD_SCALE,
  P_TILT_DEG,
  P_WIDTH,
  P_LEVELS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc child_scale = FR_FLOAT_PARAM(
    "child_scale", "Branch ratio", "Fractal", "Each branch's size relative to its parent.", 0.5,
    0.3, 0.7, FR_PARAM_ANIMATABLE);
static const fr_param_desc tilt_deg = FR_FLOAT_PARAM(
    "tilt_deg", "Tilt", "Fractal", "How far each branch leans out from its parent, degrees.", 50.0,
    5, 80, FR_PARAM_ANIMATABLE);
static const fr_param_desc width =
    FR_FLOAT_PARAM("width", "Width", "Fractal", "Branch radius relative to its length.", 0.07, 0.01,
                   0.3, FR_PARAM_ANIMATABLE);
static const fr_param_desc levels = FR_INT_PARAM(
    "levels", "Levels", "Fractal", "Generations of branches.", 9, 1, 14, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.4, 0.28, 0.18);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.45, 0.75, 0.3);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &child_scale, &tilt_deg, &width, &levels, &color_near, &color_far, &color_contrast};

/* The whole tree from a little above. */
static const fr_camera camera = FR_CAMERA(2.3, 1.9, 2.7, 0.0, 1.05, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* Branch lengths shrink by k per level, so the tree lies within 1 / (1 - k) (plus its width)
 * of its base. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  const double k = v[P_CHILD_SCALE].v[0];
  state->bounding_radius = 1.02 * (1.0 / (1.0 - k) + v[P_WIDTH].v[0]) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "pythagoras_tree",
    .name = "Pythagoras tree",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "A Pythagoras tree in 3D: each branch carries four smaller ones, down to twigs.",
    .tags = "ifs tree",
    .credit = "Albert E. Bosman, the Pythagoras tree, 1942",
    .de_source = fr_de_source,
    .de_source_name = "pythagoras_tree.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "pythagoras_tree_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 3.5,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
