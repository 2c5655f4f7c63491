/* julia.c — the quaternion Julia set z <- z^2 + c: c as a 4-vector, the 3D slice w, iterations,
 * bailout, and an update callback that can move c around a circle over time. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_C,
  P_C_W,
  P_SLICE_W,
  P_ITERATIONS,
  P_BAILOUT,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_ANIMATE,
  P_PATH_CENTER,
  P_PATH_RADIUS,
  P_PATH_SPEED,
  P_COUNT
};

static const fr_param_desc c =
    FR_VEC3_PARAM("c", "c (x, y, z)", "Fractal", "First three components of the Julia constant.",
                  -0.125, -0.256, 0.847, -1.5, 1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc c_w =
    FR_FLOAT_PARAM("c_w", "c (w)", "Fractal", "Fourth component of the Julia constant.", 0.0895,
                   -1.5, 1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc slice_w =
    FR_FLOAT_PARAM("slice_w", "Slice w", "Fractal", "The 3D slice of the 4D set that is shown.",
                   0.0, -1.5, 1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations = FR_INT_PARAM(
    "iterations", "Iterations", "Fractal", "Maximum iterations.", 11, 1, 64, FR_PARAM_SPECIALIZE);
/* r < B before a step keeps the next |z| below B^2 + |c| <= 16^2 + 3: far from float's limits. */
static const fr_param_desc bailout = FR_FLOAT_PARAM("bailout", "Bailout radius", "Fractal",
                                                    "Escape radius.", 4, 2, 16, FR_PARAM_LOG_SCALE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where orbits stay small.", 0.75, 0.22, 0.15);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where orbits stay large.", 0.78, 0.68, 0.52);
static const fr_param_desc animate = FR_BOOL_PARAM("animate_c", "Animate c", "Animation",
                                                   "Move c around a circle in its xy plane.", 0, 0);
static const fr_param_desc path_center =
    FR_VEC3_PARAM("path_center", "Path centre", "Animation", "Centre of c's circle.", -0.125,
                  -0.256, 0.847, -1.5, 1.5, 0);
static const fr_param_desc path_radius = FR_FLOAT_PARAM("path_radius", "Path radius", "Animation",
                                                        "Radius of c's circle.", 0.12, 0, 1, 0);
static const fr_param_desc path_speed =
    FR_FLOAT_PARAM("path_speed", "Path speed", "Animation", "Turns per second.", 0.05, 0.001, 1, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &c,         &c_w,     &slice_w,     &iterations,  &bailout,   &color_near,
    &color_far, &animate, &path_center, &path_radius, &path_speed};

static const fr_camera camera = FR_CAMERA(1.4, 1.9, 4.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.5, -0.9, -0.4, 1.0, 0.95, 0.9, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, 0.2, 0.5, 0.4, 0.5, 0.75, 0.25);
static const fr_light* const lights[] = {&key, &fill};

/* The filled Julia set lies inside |p| <= (1 + sqrt(1 + 4|c|)) / 2: beyond it |z^2 + c| > |z|. */
static double bounding_radius_for(const double* cxyz, double cw) {
  double len = sqrt(cxyz[0] * cxyz[0] + cxyz[1] * cxyz[1] + cxyz[2] * cxyz[2] + cw * cw);
  return 1.02 * (1.0 + sqrt(1.0 + 4.0 * len)) / 2.0 + 0.02;
}

static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  if (state->params[P_ANIMATE].v[0] != 0.0) {
    const double* centre = state->params[P_PATH_CENTER].v;
    double radius = state->params[P_PATH_RADIUS].v[0];
    double angle = 2.0 * 3.14159265358979323846 * state->params[P_PATH_SPEED].v[0] * state->time_s;
    state->params[P_C].v[0] = centre[0] + radius * cos(angle);
    state->params[P_C].v[1] = centre[1] + radius * sin(angle);
    state->params[P_C].v[2] = centre[2];
  }
  state->bounding_radius = bounding_radius_for(state->params[P_C].v, state->params[P_C_W].v[0]);
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "julia",
    .name = "Quaternion Julia set",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "A 3D slice of the quaternion Julia set z <- z^2 + c.",
    .tags = "hypercomplex quaternion julia",
    .credit =
        "Alan Norton, 'Generation and Display of Geometric Fractals in 3-D', SIGGRAPH 1982; DE "
        "after Hart, Sandin and Kauffman, 1989",
    .de_source = fr_de_source,
    .de_source_name = "julia.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "julia_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.1,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
