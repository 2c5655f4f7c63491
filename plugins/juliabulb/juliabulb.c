/* juliabulb.c — the Mandelbulb's Julia set (after Daniel White and Paul Nylander's Mandelbulb,
 * 2009): z <- z^n + c with a constant c, z starting at the point. Each c is a different
 * sculpture; c near the bulb's own boundary gives the richest ones. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_POWER,
  P_C,
  P_ITERATIONS,
  P_BAILOUT,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc power = FR_FLOAT_PARAM(
    "power", "Power", "Fractal", "Exponent n of z <- z^n + c.", 8, 2, 16, FR_PARAM_ANIMATABLE);
static const fr_param_desc c =
    FR_VEC3_PARAM("c", "Julia constant c", "Fractal", "The constant added each iteration.", -0.55,
                  0.45, -0.25, -1.5, 1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Maximum escape-time iterations.", 10, 1,
                 64, FR_PARAM_SPECIALIZE);
/* As the Mandelbulb's: (B^n + |c|)^2 must stay finite in float for n up to 16. */
static const fr_param_desc bailout =
    FR_FLOAT_PARAM("bailout", "Bailout radius", "Fractal",
                   "Escape radius; at most 12 so that bailout^power, squared, stays finite.", 4,
                   2.6, 12, FR_PARAM_LOG_SCALE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the origin.", 0.95, 0.55, 0.30);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.35, 0.22, 0.55);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 2, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &power, &c, &iterations, &bailout, &color_near, &color_far, &color_contrast};

static const fr_camera camera = FR_CAMERA(2.6, -3.2, 1.4, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 45.0);
static const fr_light sun = FR_DIRECTIONAL_LIGHT(0.4, 0.9, -1.1, 1.0, 0.94, 0.84, 1.25);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(-0.6, -0.3, 0.5, 0.4, 0.45, 0.7, 0.25);
static const fr_light* const lights[] = {&sun, &fill};

/* With R = 1 + |c| and n >= 2, a point with r > R has |z^n + c| >= r^n - |c| > r: it escapes, so
 * the set lies in r <= 1 + |c|. The margin covers the hit threshold's shell. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const double* k = state->params[P_C].v;
  state->bounding_radius = 1.02 * (1.0 + sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2])) + 0.02;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "juliabulb",
    .name = "Juliabulb",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The Mandelbulb's Julia set: the bulb's power with a constant c, a new shape per c.",
    .tags = "bulb julia power",
    .credit = "Daniel White and Paul Nylander's Mandelbulb (2009), as a Julia set",
    .de_source = fr_de_source,
    .de_source_name = "juliabulb.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "juliabulb_surface.cl",
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
