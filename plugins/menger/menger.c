/* menger.c — the Menger sponge: iterations, scale, fold offset and a rotation per fold. With the
 * defaults (scale 3, offset 1,1,1, no rotation) the surface is exactly the level-n sponge in
 * [-1, 1]^3; the DE is a lower bound for every parameter value, since folds are 1-Lipschitz. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_ITERATIONS, P_SCALE, P_OFFSET, P_ROTATION, P_COLOR_NEAR, P_COLOR_FAR, P_COUNT };

static const fr_param_desc iterations =
    FR_ITERATIONS_PARAM("iterations", "Level", "Fractal",
                        "Recursion level n: the sponge of 20^n cubes, holes down to 3^-n across "
                        "(a view 1e-20 across needs about 42; render.auto_iterations raises it "
                        "for a deep view).",
                        4, 1, 70, FR_PARAM_SPECIALIZE, 3.0);
static const fr_param_desc scale = FR_FLOAT_PARAM(
    "scale", "Scale", "Fractal", "Scale per fold; 3 is the classic sponge.", 3, 1.5, 4, 0);
static const fr_param_desc offset =
    FR_VEC3_PARAM("offset", "Fold offset", "Fractal",
                  "Corner the scale is taken about; 1,1,1 is classic.", 1, 1, 1, 0, 2, 0);
static const fr_param_desc rotation =
    FR_FLOAT_PARAM("rotation_deg", "Rotation per fold", "Fractal",
                   "Rotation about x after each fold, degrees; 0 keeps the exact sponge.", 0, -180,
                   180, FR_PARAM_ANIMATABLE);
static const fr_param_desc color_near = FR_COLOR_PARAM(
    "color_near", "Colour (outer)", "Colour", "Albedo of the large faces.", 0.82, 0.80, 0.74);
static const fr_param_desc color_far = FR_COLOR_PARAM(
    "color_far", "Colour (inner)", "Colour", "Albedo deep in the holes.", 0.62, 0.30, 0.16);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &scale,      &offset,
                                                     &rotation,   &color_near, &color_far};

static const fr_camera camera = FR_CAMERA(3.3, 2.5, 4.3, 0.0, -0.12, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.5, -0.8, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.25);
static const fr_light* const lights[] = {&key, &fill};

/* Each fold maps the attractor A into itself via z -> (z + c (s - 1)) / s, so |A| <= |c| and the
 * base cube adds sqrt 3: a generous sphere around both. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const double* c = state->params[P_OFFSET].v;
  double largest = fmax(1.0, fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2]))));
  state->bounding_radius = 1.05 * sqrt(3.0) * largest + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "menger",
    .name = "Menger sponge",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "The Menger sponge by folding: a cube with ever smaller square tunnels.",
    .tags = "ifs sponge cube",
    .credit =
        "Karl Menger, 'Dimensionstheorie', 1928; the fold form after Knighty, fractalforums.com, "
        "2010",
    .de_source = fr_de_source,
    .de_source_name = "menger.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "menger_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.87,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
