/* apollonian.c — The Apollonian network by sphere inversion (after Inigo Quilez, "Apollonian",
 * Shadertoy, 2013, and Knighty's Apollonian DEs): mirror-tiled cells inverted in a sphere, again
 * and again; spheres nest in the gaps between spheres. Cut to a ball of radius `extent`. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_ITERATIONS,
  P_INVERSION_K,
  P_EXTENT,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Folds per evaluation; more is finer.", 8,
                 3, 16, FR_PARAM_SPECIALIZE);
static const fr_param_desc inversion_k =
    FR_FLOAT_PARAM("inversion_k", "Inversion radius^2", "Fractal",
                   "Squared radius of the inversion; 1.1 to 1.6 give the classic shapes.", 1.3, 1.0,
                   1.8, FR_PARAM_ANIMATABLE);
static const fr_param_desc extent = FR_FLOAT_PARAM(
    "extent", "Extent", "Fractal", "Radius of the ball the endless set is cut to.", 2.4, 1, 20, 0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.6, 0.35);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.35, 0.55, 0.75);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.5, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &inversion_k, &extent,
                                                     &color_near, &color_far,   &color_contrast};

/* The carved ball from above a corner. */
static const fr_camera camera = FR_CAMERA(3.2, 2.2, 3.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
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
    .id = "apollonian",
    .name = "Apollonian network",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Spheres in the gaps between spheres, by repeated inversion: an Apollonian network.",
    .tags = "kleinian inversion apollonian spheres",
    .credit =
        "Inigo Quilez, 'Apollonian', Shadertoy, 2013, after Knighty's Apollonian DEs "
        "(fractalforums.com); packings after Apollonius of Perga",
    .de_source = fr_de_source,
    .de_source_name = "apollonian.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "apollonian_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.5,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
