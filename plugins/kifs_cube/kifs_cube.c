/* kifs_cube.c — Knighty's kaleidoscopic IFS on the cube (fractalforums.com, "Kaleidoscopic (escape
 * time) IFS", 2010): the octahedral group's fold scaled about a cube corner (1, 1, 1), so eight
 * copies sit at the corners; rotations turn the box of boxes into cogs and crystals. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SCALE,
  P_OFFSET,
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
    "scale", "Scale", "Fractal", "Scale about the offset point each iteration (above 1).", 2.0, 1.2,
    4, FR_PARAM_ANIMATABLE);
static const fr_param_desc offset = FR_VEC3_PARAM(
    "offset", "Offset", "Fractal",
    "The point the scale is taken about; (1, 1, 1) is a cube corner.", 1.0, 1.0, 1.0, -2, 2, 0);
static const fr_param_desc angle_x_deg = FR_FLOAT_PARAM(
    "angle_x_deg", "Rotation x", "Fractal", "Rotation about x after each fold, degrees.", 25.0,
    -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_y_deg = FR_FLOAT_PARAM(
    "angle_y_deg", "Rotation y", "Fractal", "Rotation about y after each fold, degrees.", 10.0,
    -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_z_deg = FR_FLOAT_PARAM(
    "angle_z_deg", "Rotation z", "Fractal", "Rotation about z after each fold, degrees.", 0.0, -180,
    180, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Levels of the IFS; more is finer.", 10, 2,
                 30, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.7, 0.45);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.25, 0.3, 0.4);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&scale,       &offset,      &angle_x_deg,
                                                     &angle_y_deg, &angle_z_deg, &iterations,
                                                     &color_near,  &color_far,   &color_contrast};

/* Three quarters, the whole shape. */
static const fr_camera camera = FR_CAMERA(2.6, 1.9, 3.1, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* The fractal lies inside the ball |p| <= |offset| (fr/kifs.cl). */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  const double* c = v[P_OFFSET].v;
  state->bounding_radius = 1.02 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "kifs_cube",
    .name = "KIFS cube",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Knighty's kaleidoscopic IFS scaled about a cube's corner: eight cubes of cubes, twisted "
        "into a cauliflower.",
    .tags = "kifs cube rotation",
    .credit = "Knighty, 'Kaleidoscopic (escape time) IFS', fractalforums.com, 2010",
    .de_source = fr_de_source,
    .de_source_name = "kifs_cube.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "kifs_cube_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.82,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
