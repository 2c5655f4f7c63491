/* mandelbulb.c — the Mandelbulb scene: parameters, default view, orbit-trap colours, and an
 * update callback that can animate the power. The OpenCL sources (mandelbulb.cl and
 * mandelbulb_surface.cl) are embedded by the SDK's CMake helper. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_POWER,
  P_ITERATIONS,
  P_BAILOUT,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_ANIMATE,
  P_ANIMATE_CENTER,
  P_ANIMATE_SPEED,
  P_ANIMATE_DEPTH,
  P_COUNT
};

static const fr_param_desc power = FR_FLOAT_PARAM(
    "power", "Power", "Fractal", "Exponent n of z <- z^n + p; 8 gives the classic bulb.", 8, 2, 16,
    FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_ITERATIONS_PARAM("iterations", "Iterations", "Fractal",
                        "Maximum escape-time iterations; more gives finer detail and costs time "
                        "(render.auto_iterations raises it for a deep view).",
                        8, 1, 100, FR_PARAM_SPECIALIZE, 3.0);
/* With r < B before a step, the next |z| is at most B^n + B, and the DE squares it to take its
 * length: (B^n + B)^2 must stay below FLT_MAX = 2^128 for n up to 16, so B^16 < 2^63 or so.
 * B = 12 gives 12^16 = 1.8e17 and (1.8e17)^2 = 3.4e34, with room to spare; 16 would overflow. */
static const fr_param_desc bailout = FR_FLOAT_PARAM(
    "bailout", "Bailout radius", "Fractal",
    "Escape radius; at most 12 so that bailout^power, squared, stays finite in float.", 2, 1.5, 12,
    FR_PARAM_LOG_SCALE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the origin.", 0.9, 0.42, 0.12);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far from the origin.", 0.30, 0.42, 0.62);
static const fr_param_desc color_contrast = FR_FLOAT_PARAM(
    "color_contrast", "Colour contrast", "Colour",
    "Exponent of the orbit-trap blend; larger pushes towards the deep colour.", 4, 0.25, 8, 0);
static const fr_param_desc animate =
    FR_BOOL_PARAM("animate_power", "Animate power", "Animation",
                  "Swing the power around its centre over time.", 0, 0);
static const fr_param_desc animate_center =
    FR_FLOAT_PARAM("animate_center", "Animation centre", "Animation",
                   "The power the animation swings around.", 8, 2, 16, 0);
static const fr_param_desc animate_speed = FR_FLOAT_PARAM(
    "animate_speed", "Animation speed", "Animation", "Swings per second.", 0.1, 0.01, 2, 0);
static const fr_param_desc animate_depth =
    FR_FLOAT_PARAM("animate_depth", "Animation depth", "Animation",
                   "How far the power swings either side of its centre.", 2, 0, 6, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &power,          &iterations, &bailout,        &color_near,    &color_far,
    &color_contrast, &animate,    &animate_center, &animate_speed, &animate_depth};

/* The bulb's polar axis is z: look at it with z up, slightly from above. */
static const fr_camera camera = FR_CAMERA(3.4, -4.4, 1.5, 0.0, 0.0, -0.12, 0.0, 0.0, 1.0, 45.0);

static const fr_light sun = FR_DIRECTIONAL_LIGHT(0.45, 0.92, -1.18, 1.0, 0.94, 0.84, 1.25);
static const fr_light sky_fill = FR_DIRECTIONAL_LIGHT(-0.6, -0.3, 0.5, 0.35, 0.45, 0.7, 0.2);
static const fr_light* const lights[] = {&sun, &sky_fill};

/* The set lies inside |p| <= 2^(1/(n-1)): beyond it |z^n + p| >= |z|^n - |p| grows without bound,
 * since the triplex power keeps |z^n| = |z|^n. The margin covers the hit threshold's shell. */
static double bounding_radius_for_power(double n) {
  return 1.02 * pow(2.0, 1.0 / (n - 1.0)) + 0.02;
}

static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  /* Animation sets the power from time alone (centre + depth * sin), so a frame at time t is the
   * same however it was reached. */
  double n = state->params[P_POWER].v[0];
  if (state->params[P_ANIMATE].v[0] != 0.0) {
    double base = state->params[P_ANIMATE_CENTER].v[0];
    double depth = state->params[P_ANIMATE_DEPTH].v[0];
    double speed = state->params[P_ANIMATE_SPEED].v[0];
    n = base + depth * sin(2.0 * 3.14159265358979323846 * speed * state->time_s);
    if (n < power.min_value.v[0]) n = power.min_value.v[0];
    if (n > power.max_value.v[0]) n = power.max_value.v[0];
    state->params[P_POWER].v[0] = n;
  }
  state->bounding_radius = bounding_radius_for_power(n);
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "mandelbulb",
    .name = "Mandelbulb",
    .version = "1.1.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The power-n Mandelbulb: a 3D analogue of the Mandelbrot set built on spherical powers.",
    .tags = "bulb power animated",
    .credit =
        "Daniel White and Paul Nylander, 'The Unravelling of the Real 3D Mandelbulb', "
        "skytopia.com, 2009",
    .de_source = fr_de_source,
    .de_source_name = "mandelbulb.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "mandelbulb_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO, /* basic shading: the issue-2 benchmark view */
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.06, /* the bound for the smallest power, 2 */
    .update = update,
};

FR_SCENE_ENTRY(&scene);
