/* mandelbox_rotated.c — Tom Lowe's Mandelbox with a rotation after each fold (as Mandelbulber's
 * rotated boxes): the rooms and towers of the box twist into spirals and stairs. The rotation is an
 * isometry, so the Mandelbox's estimate holds unchanged. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SCALE,
  P_MIN_RADIUS,
  P_FIXED_RADIUS,
  P_FOLD_LIMIT,
  P_ANGLE_X_DEG,
  P_ANGLE_Y_DEG,
  P_ANGLE_Z_DEG,
  P_ITERATIONS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc scale = FR_FLOAT_PARAM(
    "scale", "Scale", "Fractal", "z <- scale * R fold(z) + p.", 2.0, -3, 3, FR_PARAM_ANIMATABLE);
static const fr_param_desc min_radius =
    FR_FLOAT_PARAM("min_radius", "Min radius", "Fractal",
                   "Inside it the sphere fold scales by (fixed / min)^2.", 0.5, 0.05, 1, 0);
static const fr_param_desc fixed_radius =
    FR_FLOAT_PARAM("fixed_radius", "Fixed radius", "Fractal",
                   "Between min and fixed radius the sphere fold inverts.", 1.0, 0.5, 2, 0);
static const fr_param_desc fold_limit =
    FR_FLOAT_PARAM("fold_limit", "Fold limit", "Fractal", "The box fold reflects beyond +-limit.",
                   1.0, 0.25, 2, 0);
static const fr_param_desc angle_x_deg = FR_FLOAT_PARAM(
    "angle_x_deg", "Rotation x", "Fractal", "Rotation about x after each fold, degrees.", 6.0, -180,
    180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_y_deg = FR_FLOAT_PARAM(
    "angle_y_deg", "Rotation y", "Fractal", "Rotation about y after each fold, degrees.", 11.0,
    -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_z_deg = FR_FLOAT_PARAM(
    "angle_z_deg", "Rotation z", "Fractal", "Rotation about z after each fold, degrees.", 0.0, -180,
    180, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_ITERATIONS_PARAM("iterations", "Iterations", "Fractal",
                        "Folds per evaluation; more is finer. A view d across needs about "
                        "log2(1/d) + a few (render.auto_iterations raises it for a deep view).",
                        14, 4, 100, FR_PARAM_SPECIALIZE, 2.0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.8, 0.6);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.3, 0.4, 0.55);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.5, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &scale,       &min_radius, &fixed_radius, &fold_limit, &angle_x_deg,   &angle_y_deg,
    &angle_z_deg, &iterations, &color_near,   &color_far,  &color_contrast};

/* The whole twisted box from a corner. */
static const fr_camera camera = FR_CAMERA(20.0, 14.0, 22.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 50.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "mandelbox_rotated",
    .name = "Twisted Mandelbox",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The Mandelbox with a rotation after every fold: rooms and towers twisted into stairs.",
    .tags = "box folds rotation",
    .credit =
        "Tom Lowe, 'Amazing Box, Amazing Fractal', fractalforums.com, 2010; rotations as in "
        "Mandelbulber (Krzysztof Marczak)",
    .de_source = fr_de_source,
    .de_source_name = "mandelbox_rotated.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "mandelbox_rotated_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 12.5, /* checked: the DE is positive from 12.5 to twice that at the defaults
                                (fractalis check) */
};

FR_SCENE_ENTRY(&scene);
