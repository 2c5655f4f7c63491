/* bulb_pool.c — A Mandelbulb hovering over a still pool in a stone rim, mirrored in the water: a
 * composed scene from the DE library, with reflections. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_POWER,
  P_ITERATIONS,
  P_WATER_REFLECTIVITY,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc power = FR_FLOAT_PARAM(
    "power", "Power", "Fractal", "The bulb's power n.", 8.0, 2, 16, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Escape-time iterations.", 8, 3, 20,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc water_reflectivity = FR_FLOAT_PARAM(
    "water_reflectivity", "Water", "Colour", "How much the water mirrors.", 0.7, 0, 1, 0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.6, 0.25);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.3, 0.4, 0.65);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 3.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&power,      &iterations, &water_reflectivity,
                                                     &color_near, &color_far,  &color_contrast};

/* Low over the water, the bulb and its reflection. */
static const fr_camera camera = FR_CAMERA(3.4, 0.1, 4.6, 0.0, -0.1, 0.0, 0.0, 1.0, 0.0, 50.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.5, -0.8, -0.3, 1.0, 0.93, 0.85, 1.2);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.3, 0.6, 0.4, 0.5, 0.75, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* The ground disc bounds everything, the bulb (radius 2^(1/(n-1)) <= 2 at y 0.35) too. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  state->bounding_radius = 7.5;
  (void)v;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "bulb_pool",
    .name = "Bulb over a pool",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "A Mandelbulb hovering over a still pool that mirrors it, in a ring of stone.",
    .tags = "showcase bulb reflections water",
    .credit =
        "Daniel White and Paul Nylander's Mandelbulb (2009); composed by the Fractalis developers",
    .de_source = fr_de_source,
    .de_source_name = "bulb_pool.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "bulb_pool_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_REFLECTIONS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 7.5, /* the ground disc, radius 7 */
    .update = update,
};

FR_SCENE_ENTRY(&scene);
