/* burning_bulb.c — The Mandelbulb with the Burning Ship's absolute value (Michelitsch and Rossler,
 * 1992): z <- |z|^n + p, the coordinates folded positive before each power. The bulb's symmetry
 * breaks into flames and ridges. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_POWER, P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc power = FR_FLOAT_PARAM(
    "power", "Power", "Fractal", "The triplex exponent n.", 8.0, 2, 16, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Escape-time iterations.", 10, 3, 40,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.98, 0.62, 0.25);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.35, 0.12, 0.1);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.2, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&power, &iterations, &color_near, &color_far,
                                                     &color_contrast};

/* Its polar axis up (z), from below the equator. */
static const fr_camera camera = FR_CAMERA(2.4, 1.7, -2.6, 0.0, 0.0, 0.1, 0.0, 0.0, 1.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* |z| is unchanged by the fold, so the Mandelbulb's bound holds: 2^(1/(n-1)). */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  state->bounding_radius = 1.02 * pow(2.0, 1.0 / (v[P_POWER].v[0] - 1.0)) + 0.02;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "burning_bulb",
    .name = "Burning bulb",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The Mandelbulb with the Burning Ship's absolute value: bulbs torn into ridges and flames.",
    .tags = "bulb burning-ship power",
    .credit =
        "Michael Michelitsch and Otto Rossler, the Burning Ship (1992), on Daniel White and Paul "
        "Nylander's Mandelbulb (2009)",
    .de_source = fr_de_source,
    .de_source_name = "burning_bulb.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "burning_bulb_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.06,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
