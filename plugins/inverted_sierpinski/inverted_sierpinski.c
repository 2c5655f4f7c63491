/* inverted_sierpinski.c — Sierpinski's tetrahedron turned inside out by inversion in a sphere about
 * its centre (a point of its central hollow): its triangular windows become a dome of crowding
 * arches. The DE is carried through the inversion by an exact bound (op_invert_de in
 * fr/operators.cl). */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_RADIUS2, P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc radius2 = FR_FLOAT_PARAM(
    "radius2", "Inversion radius^2", "Fractal",
    "Squared radius of the inversion sphere about the centre.", 1.0, 0.2, 4, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations = FR_INT_PARAM(
    "iterations", "Levels", "Fractal", "The tetrahedron's levels.", 9, 1, 20, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.82, 0.6);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.3, 0.45, 0.5);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&radius2, &iterations, &color_near, &color_far,
                                                     &color_contrast};

/* The dome from above a corner. */
static const fr_camera camera = FR_CAMERA(3.0, 2.2, 3.6, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* The tetrahedron keeps at least 1/sqrt(3) from its centre (the centres of its hollow's
 * faces), so its image lies within radius2 sqrt(3). */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  state->bounding_radius = 1.02 * v[P_RADIUS2].v[0] * sqrt(3.0) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "inverted_sierpinski",
    .name = "Inverted Sierpinski",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Sierpinski's tetrahedron inverted in a sphere: its windows become a dome of crowding "
        "arches.",
    .tags = "kleinian inversion tetrahedron",
    .credit = "Waclaw Sierpinski, 1915; inversion in a sphere after Apollonius of Perga",
    .de_source = fr_de_source,
    .de_source_name = "inverted_sierpinski.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "inverted_sierpinski_surface.cl",
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
