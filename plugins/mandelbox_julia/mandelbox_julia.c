/* mandelbox_julia.c — Tom Lowe's Mandelbox as a Julia set (fractalforums.com, 2010): z <- scale *
 * fold(z) + c with a constant c instead of the point itself. Each c gives a different sculpture of
 * folded rooms; most c give dust or a solid block, these defaults a lattice of chambers. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SCALE,
  P_C,
  P_MIN_RADIUS,
  P_FIXED_RADIUS,
  P_FOLD_LIMIT,
  P_ITERATIONS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc scale = FR_FLOAT_PARAM(
    "scale", "Scale", "Fractal", "z <- scale * fold(z) + c.", -2.0, -3, 3, FR_PARAM_ANIMATABLE);
static const fr_param_desc c =
    FR_VEC3_PARAM("c", "c", "Fractal", "The constant added each iteration.", 1.8, 1.8, 1.8, -4, 4,
                  FR_PARAM_ANIMATABLE);
static const fr_param_desc min_radius =
    FR_FLOAT_PARAM("min_radius", "Min radius", "Fractal",
                   "Inside it the sphere fold scales by (fixed / min)^2.", 0.3, 0.05, 1, 0);
static const fr_param_desc fixed_radius =
    FR_FLOAT_PARAM("fixed_radius", "Fixed radius", "Fractal",
                   "Between min and fixed radius the sphere fold inverts.", 1.0, 0.5, 2, 0);
static const fr_param_desc fold_limit =
    FR_FLOAT_PARAM("fold_limit", "Fold limit", "Fractal", "The box fold reflects beyond +-limit.",
                   1.0, 0.25, 2, 0);
static const fr_param_desc iterations =
    FR_ITERATIONS_PARAM("iterations", "Iterations", "Fractal",
                        "Folds per evaluation; more is finer. A view d across needs about "
                        "log2(1/d) + a few (render.auto_iterations raises it for a deep view).",
                        14, 4, 100, FR_PARAM_SPECIALIZE, 2.0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.8, 0.75, 0.6);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.5, 0.25, 0.2);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.5, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&scale,        &c,          &min_radius,
                                                     &fixed_radius, &fold_limit, &iterations,
                                                     &color_near,   &color_far,  &color_contrast};

/* The whole sculpture from a corner. */
static const fr_camera camera = FR_CAMERA(11.0, 8.0, 12.8, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "mandelbox_julia",
    .name = "Mandelbox Julia",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The Mandelbox with a constant c: for each c a different sculpture of folded rooms.",
    .tags = "box julia folds",
    .credit = "Tom Lowe, 'Amazing Box, Amazing Fractal', fractalforums.com, 2010",
    .de_source = fr_de_source,
    .de_source_name = "mandelbox_julia.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "mandelbox_julia_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 12.0, /* checked at the default c (fractalis check, de-bounded) */
};

FR_SCENE_ENTRY(&scene);
