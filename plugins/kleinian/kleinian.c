/* kleinian.c — Jos Leys' Kleinian group limit set in the Maskit slice t = a + b i (josleys.com,
 * 2014; after Mumford, Series and Wright, "Indra's Pearls", 2002): a wrap into the fundamental
 * strip, a half-turn above the separation line, and the generator's inversion. Pearls of every size
 * in a slab 0 <= y <= a, cut to a ball of radius `extent`. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_ITERATIONS,
  P_TRACE_RE,
  P_TRACE_IM,
  P_BOX_X,
  P_BOX_Z,
  P_EXTENT,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Steps of the group action; more is finer.",
                 60, 5, 200, FR_PARAM_SPECIALIZE);
static const fr_param_desc trace_re =
    FR_FLOAT_PARAM("trace_re", "Trace (real)", "Fractal", "a of the Maskit parameter t = a + b i.",
                   1.95859103011179, 1.6, 2.2, FR_PARAM_ANIMATABLE);
static const fr_param_desc trace_im = FR_FLOAT_PARAM(
    "trace_im", "Trace (imaginary)", "Fractal", "b of the Maskit parameter t = a + b i.",
    0.0112785606117658, -0.2, 0.2, FR_PARAM_ANIMATABLE);
static const fr_param_desc box_x =
    FR_FLOAT_PARAM("box_x", "Period x", "Fractal", "Half the wrap period along x.", 1.0, 0.5, 2, 0);
static const fr_param_desc box_z =
    FR_FLOAT_PARAM("box_z", "Period z", "Fractal", "Half the wrap period along z.", 1.0, 0.5, 2, 0);
static const fr_param_desc extent = FR_FLOAT_PARAM(
    "extent", "Extent", "Fractal", "Radius of the ball the endless set is cut to.", 3, 1, 20, 0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.85, 0.7);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.25, 0.4, 0.7);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &trace_re,  &trace_im,
                                                     &box_x,      &box_z,     &extent,
                                                     &color_near, &color_far, &color_contrast};

/* Inside the slab, over the pearls on its floor. */
static const fr_camera camera = FR_CAMERA(1.2, 1.75, 2.2, 0.0, 0.3, 0.0, 0.0, 1.0, 0.0, 70.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* The set fills space; the DE cuts it to the ball |p| <= extent, so that is the bound. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  state->bounding_radius = 1.02 * v[P_EXTENT].v[0] + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "kleinian",
    .name = "Kleinian limit set",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Jos Leys' Kleinian limit set: strings of pearls of every size, in the Maskit slice.",
    .tags = "kleinian inversion pearls",
    .credit =
        "Jos Leys, 3D Kleinian limit sets (josleys.com, 2014), after Mumford, Series and Wright, "
        "'Indra's Pearls', 2002",
    .de_source = fr_de_source,
    .de_source_name = "kleinian.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "kleinian_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 3.11,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
