/* mandelbox.c — Tom Lowe's Mandelbox ("Amazing Box", fractalforums.com, 2010): box fold, sphere
 * fold, scale and add. Scale 2 gives the classic box with its rooms and towers, scale -1.5 the
 * spiky ball; both with min radius 0.5, fixed radius 1 and fold limit 1. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SCALE,
  P_MIN_RADIUS,
  P_FIXED_RADIUS,
  P_FOLD_LIMIT,
  P_ITERATIONS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc scale =
    FR_FLOAT_PARAM("scale", "Scale", "Fractal",
                   "z <- scale * fold(z) + p; 2 is the classic box, -1.5 the spiky ball.", 2, -3, 3,
                   FR_PARAM_ANIMATABLE);
static const fr_param_desc min_radius =
    FR_FLOAT_PARAM("min_radius", "Min radius", "Fractal",
                   "Inside it the sphere fold scales by (fixed / min)^2.", 0.5, 0.05, 1, 0);
static const fr_param_desc fixed_radius =
    FR_FLOAT_PARAM("fixed_radius", "Fixed radius", "Fractal",
                   "Between min and fixed radius the sphere fold inverts.", 1, 0.5, 2, 0);
static const fr_param_desc fold_limit = FR_FLOAT_PARAM(
    "fold_limit", "Fold limit", "Fractal", "The box fold reflects beyond +-limit.", 1, 0.25, 2, 0);
static const fr_param_desc iterations =
    FR_ITERATIONS_PARAM("iterations", "Iterations", "Fractal",
                        "Folds per evaluation; more is finer. A view d across needs about "
                        "log2(1/d) + a few: 55 at 1e-15, 70 at 1e-20, 100 at 1e-28 "
                        "(render.auto_iterations raises it for a deep view).",
                        14, 4, 100, FR_PARAM_SPECIALIZE, 2.0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the origin.", 0.86, 0.62, 0.36);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.26, 0.36, 0.52);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.5, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&scale,      &min_radius,    &fixed_radius,
                                                     &fold_limit, &iterations,    &color_near,
                                                     &color_far,  &color_contrast};

/* The scale-2 box (half-side 6) from a corner, whole. */
static const fr_camera camera = FR_CAMERA(15.0, 11.0, 17.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 50.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.5, -0.9, -0.3, 1.0, 0.95, 0.86, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, -0.1, 0.7, 0.45, 0.55, 0.8, 0.3);
static const fr_light* const lights[] = {&key, &fill};

/* Lowe's bound: a point with some |x_i| beyond 2 (|s| + 1) / (|s| - 1) escapes, so the set lies
 * in that cube; its corner is sqrt(3) times as far. Scales with |s| <= 1.05 have no such bound:
 * the cube of 2 (|s| + 1) / 0.05 then stands in (the set is mostly empty or all of space there,
 * and the DE still bounds it). */
static double bounding_radius(double s) {
  double a = fabs(s);
  double half_side = 2.0 * (a + 1.0) / fmax(a - 1.0, 0.05);
  return 1.02 * sqrt(3.0) * half_side + 0.05;
}

static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  state->bounding_radius = bounding_radius(state->params[P_SCALE].v[0]);
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "mandelbox",
    .name = "Mandelbox",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "Tom Lowe's Mandelbox: box and sphere folds build a city of rooms and towers.",
    .tags = "box folds",
    .credit = "Tom Lowe, 'Amazing Box, Amazing Fractal', fractalforums.com, 2010",
    .de_source = fr_de_source,
    .de_source_name = "mandelbox.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "mandelbox_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 10.7, /* bounding_radius(2) */
    .update = update,
};

FR_SCENE_ENTRY(&scene);
