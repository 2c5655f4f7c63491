/* mandelbulb.c — the Mandelbulb scene: parameters, default view, and an update callback that can
 * animate the power. The distance estimator is mandelbulb.cl, embedded by the SDK's CMake helper.
 */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];

enum {
  P_POWER,
  P_ITERATIONS,
  P_BAILOUT,
  P_ANIMATE,
  P_ANIMATE_CENTER,
  P_ANIMATE_SPEED,
  P_ANIMATE_DEPTH,
  P_COUNT
};

static const fr_param_desc power = {sizeof(fr_param_desc),
                                    FR_PARAM_FLOAT,
                                    FR_PARAM_ANIMATABLE,
                                    0,
                                    "power",
                                    "Power",
                                    "Fractal",
                                    "Exponent n of z <- z^n + p; 8 gives the classic bulb.",
                                    {{8, 0, 0}},
                                    {{2, 0, 0}},
                                    {{16, 0, 0}}};
static const fr_param_desc iterations = {
    sizeof(fr_param_desc),
    FR_PARAM_INT,
    FR_PARAM_SPECIALIZE,
    0,
    "iterations",
    "Iterations",
    "Fractal",
    "Maximum escape-time iterations; more gives finer detail and costs time.",
    {{8, 0, 0}},
    {{1, 0, 0}},
    {{64, 0, 0}}};
/* With r < B before a step, the next |z| is at most B^n + B, and the DE squares it to take its
 * length: (B^n + B)^2 must stay below FLT_MAX = 2^128 for n up to 16, so B^16 < 2^63 or so.
 * B = 12 gives 12^16 = 1.8e17 and (1.8e17)^2 = 3.4e34, with room to spare; 16 would overflow. */
static const fr_param_desc bailout = {
    sizeof(fr_param_desc),
    FR_PARAM_FLOAT,
    FR_PARAM_LOG_SCALE,
    0,
    "bailout",
    "Bailout radius",
    "Fractal",
    "Escape radius; at most 12 so that bailout^power, squared, stays finite in float.",
    {{2, 0, 0}},
    {{1.5, 0, 0}},
    {{12, 0, 0}}};
static const fr_param_desc animate = {sizeof(fr_param_desc),
                                      FR_PARAM_BOOL,
                                      0,
                                      0,
                                      "animate_power",
                                      "Animate power",
                                      "Animation",
                                      "Swing the power around its value over time.",
                                      {{0, 0, 0}},
                                      {{0, 0, 0}},
                                      {{1, 0, 0}}};
static const fr_param_desc animate_center = {sizeof(fr_param_desc),
                                             FR_PARAM_FLOAT,
                                             0,
                                             0,
                                             "animate_center",
                                             "Animation centre",
                                             "Animation",
                                             "The power the animation swings around.",
                                             {{8, 0, 0}},
                                             {{2, 0, 0}},
                                             {{16, 0, 0}}};
static const fr_param_desc animate_speed = {
    sizeof(fr_param_desc), FR_PARAM_FLOAT,    0,           0,
    "animate_speed",       "Animation speed", "Animation", "Swings per second.",
    {{0.1, 0, 0}},         {{0.01, 0, 0}},    {{2, 0, 0}}};
static const fr_param_desc animate_depth = {sizeof(fr_param_desc),
                                            FR_PARAM_FLOAT,
                                            0,
                                            0,
                                            "animate_depth",
                                            "Animation depth",
                                            "Animation",
                                            "How far the power swings either side of its value.",
                                            {{2, 0, 0}},
                                            {{0, 0, 0}},
                                            {{6, 0, 0}}};

static const fr_param_desc* const params[P_COUNT] = {
    &power, &iterations, &bailout, &animate, &animate_center, &animate_speed, &animate_depth};

/* The bulb's polar axis is z: look at it with z up, slightly from above. */
static const fr_camera camera = {sizeof(fr_camera), 0,   {3.4, -4.4, 1.5}, {0.0, 0.0, -0.12},
                                 {0.0, 0.0, 1.0},   45.0};

static const fr_light sun = {
    sizeof(fr_light), FR_LIGHT_DIRECTIONAL, {0.45, 0.92, -1.18}, {1.0, 0.94, 0.84}, 1.5};
static const fr_light* const lights[] = {&sun};

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
    sizeof(fr_scene_desc),
    0,
    "mandelbulb",
    "Mandelbulb",
    "1.0.0",
    "The Fractalis developers",
    "MIT",
    "The power-n Mandelbulb: a 3D analogue of the Mandelbrot set built on spherical powers.",
    fr_de_source,
    "mandelbulb.cl",
    params,
    P_COUNT,
    1,
    FR_FEATURE_AO,
    &camera,
    lights,
    2.06, /* the bound for the smallest power, 2 */
    NULL,
    NULL,
    update};

FR_SCENE_ENTRY(&scene);
