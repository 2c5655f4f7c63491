/* quaternion_cubic_julia.c — The cubic quaternion Julia set q <- q^3 + c (after Norton, SIGGRAPH
 * 1982, and Hart, Sandin and Kauffman's distance estimate, 1989), sliced at w = slice_w: threefold
 * where the quadratic set is twofold. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_C, P_C_W, P_SLICE_W, P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc c =
    FR_VEC3_PARAM("c", "c (real, i, j)", "Fractal", "The constant c: its real, i and j parts.",
                  -0.36, 0.62, 0.0, -1.5, 1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc c_w = FR_FLOAT_PARAM("c_w", "c (k)", "Fractal", "The k part of c.", 0.0,
                                                -1.5, 1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc slice_w =
    FR_FLOAT_PARAM("slice_w", "Slice", "Fractal", "The k part the 3D slice is taken at.", 0.0, -1.5,
                   1.5, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Escape-time iterations.", 24, 3, 60,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.8, 0.55);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.45, 0.25, 0.55);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &c, &c_w, &slice_w, &iterations, &color_near, &color_far, &color_contrast};

/* Three quarters, the whole set and its spirals. */
static const fr_camera camera = FR_CAMERA(2.4, 1.7, 2.9, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* A point with |q| > 1 + |c| escapes (|q^3 + c| >= |q|^3 - |c| > |q|), so the set lies inside. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  const double* c = v[P_C].v;
  const double cw = v[P_C_W].v[0];
  state->bounding_radius =
      1.02 * (1.0 + sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + cw * cw)) + 0.02;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "quaternion_cubic_julia",
    .name = "Cubic quaternion Julia",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The quaternion Julia set of q^3 + c: threefold lobes and spirals, sliced to 3D.",
    .tags = "hypercomplex quaternion julia",
    .credit =
        "Alan Norton, SIGGRAPH 1982; DE after John Hart, Daniel Sandin and Louis Kauffman, 'Ray "
        "tracing deterministic 3-D fractals', SIGGRAPH 1989",
    .de_source = fr_de_source,
    .de_source_name = "quaternion_cubic_julia.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "quaternion_cubic_julia_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.12,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
