/* kifs_octahedron.c — Knighty's kaleidoscopic IFS on the octahedron (fractalforums.com,
 * "Kaleidoscopic (escape time) IFS", 2010): fold into the octahedral group's chamber, rotate,
 * scale about a vertex. Scale 2 about (1, 0, 0) with no rotation is Sierpinski's octahedron;
 * rotations turn it into crystalline clusters. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SCALE,
  P_OFFSET,
  P_ANGLE_X,
  P_ANGLE_Y,
  P_ANGLE_Z,
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
    "The point the scale is taken about; a vertex gives the classic shape.", 1, 0, 0, -2, 2, 0);
static const fr_param_desc angle_x =
    FR_FLOAT_PARAM("angle_x_deg", "Rotation x", "Fractal",
                   "Rotation about x after each fold, degrees.", 0, -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_y =
    FR_FLOAT_PARAM("angle_y_deg", "Rotation y", "Fractal",
                   "Rotation about y after each fold, degrees.", 0, -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_z =
    FR_FLOAT_PARAM("angle_z_deg", "Rotation z", "Fractal",
                   "Rotation about z after each fold, degrees.", 0, -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Levels of the IFS; more is finer.", 10, 2,
                 30, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (inner)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.92, 0.78, 0.52);
static const fr_param_desc color_far = FR_COLOR_PARAM(
    "color_far", "Colour (outer)", "Colour", "Albedo where the orbit stayed out.", 0.3, 0.45, 0.62);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&scale,      &offset,    &angle_x,
                                                     &angle_y,    &angle_z,   &iterations,
                                                     &color_near, &color_far, &color_contrast};

static const fr_camera camera = FR_CAMERA(2.2, 1.5, 2.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&key, &fill};

/* The fractal lies inside the ball |p| <= |offset| (fr/kifs.cl): each inverse map takes that
 * ball into itself. The margin covers the hit threshold's shell. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const double* c = state->params[P_OFFSET].v;
  state->bounding_radius = 1.02 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "kifs_octahedron",
    .name = "KIFS octahedron",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Knighty's kaleidoscopic IFS on the octahedron: Sierpinski's octahedron, twisted at will.",
    .tags = "kifs octahedron",
    .credit = "Knighty, 'Kaleidoscopic (escape time) IFS', fractalforums.com, 2010",
    .de_source = fr_de_source,
    .de_source_name = "kifs_octahedron.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "kifs_octahedron_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.07,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
