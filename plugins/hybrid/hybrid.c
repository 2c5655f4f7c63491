/* hybrid.c — the hybrid composer: up to six formula steps, each chosen from twelve kinds (or none)
 * (fr/hybrid.cl) with its own parameters and repeat count, applied in order every iteration, as
 * Mandelbulber's hybrids chain formulas. Each step's kind and repeat count are compiled into the
 * kernel (FR_PARAM_SPECIALIZE), so a step set to "none" and every kind not chosen cost nothing.
 *
 * The default is a Mandelbox folded with a quadratic bulb. A hybrid's estimate is first order;
 * the safety factor `de_factor` keeps it below the distance, which `fractalis check` measures
 * (the shipped presets each pass with theirs). The bounding radius is a parameter too: no formula
 * bounds an arbitrary chain, so each preset states its own and check confirms it. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

/* In the order of fr/hybrid.cl's HYBRID_* kinds; hybrid.cl refuses to compile otherwise. */
static const char* const kinds[] = {
    "none",       "bulb",        "box_fold",    "sphere_fold", "scale_translate",   "menger",
    "octahedral", "icosahedral", "tetrahedral", "rotate",      "quaternion_square", "kali",
    "abs_fold"};
static const char* const estimates[] = {"logarithmic", "linear", "box"};

#define STEP_KIND_TEXT                                                                          \
  "bulb: z^a + p; box_fold: to +-a; sphere_fold: radii a, b; scale_translate: a z + v + p; "    \
  "menger, octahedral, icosahedral, tetrahedral: fold, scale a about v; rotate: by v degrees; " \
  "quaternion_square: z^2 + p; kali: a |z| / |z|^2 + v; abs_fold: |z| + v."

#define STEP(n, kind, a, b, vx, vy, vz)                                                            \
  static const fr_param_desc step##n =                                                             \
      FR_CHOICE_PARAM("step" #n, "Step " #n, "Step " #n, "What step " #n " does. " STEP_KIND_TEXT, \
                      kind, kinds, FR_PARAM_SPECIALIZE);                                           \
  static const fr_param_desc step##n##_repeat =                                                    \
      FR_INT_PARAM("step" #n "_repeat", "Repeat", "Step " #n,                                      \
                   "How many times the step is applied in a row.", 1, 1, 8, FR_PARAM_SPECIALIZE);  \
  static const fr_param_desc step##n##_a = FR_FLOAT_PARAM(                                         \
      "step" #n "_a", "a", "Step " #n, "Power, scale, fold limit or min radius (see the step).",   \
      a, -4, 16, FR_PARAM_ANIMATABLE);                                                             \
  static const fr_param_desc step##n##_b =                                                         \
      FR_FLOAT_PARAM("step" #n "_b", "b", "Step " #n, "The sphere fold's fixed radius.", b, 0, 4,  \
                     FR_PARAM_ANIMATABLE);                                                         \
  static const fr_param_desc step##n##_v = FR_VEC3_PARAM(                                          \
      "step" #n "_v", "v", "Step " #n, "Offset, translation or rotation angles (degrees).", vx,    \
      vy, vz, -180, 180, FR_PARAM_ANIMATABLE);

/* Kind indices, for the defaults below. */
enum { NONE, BULB, BOX_FOLD, SPHERE_FOLD, SCALE_TRANSLATE };

STEP(1, BOX_FOLD, 1, 0, 0, 0, 0)
STEP(2, SPHERE_FOLD, 0.5, 1, 0, 0, 0)
STEP(3, SCALE_TRANSLATE, 2, 0, 0, 0, 0)
STEP(4, BULB, 2, 0, 0, 0, 0)
STEP(5, NONE, 1, 1, 0, 0, 0)
STEP(6, NONE, 1, 1, 0, 0, 0)

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Hybrid", "Times the whole chain of steps runs.", 8, 1,
                 100, FR_PARAM_SPECIALIZE);
static const fr_param_desc bailout =
    FR_FLOAT_PARAM("bailout", "Bailout", "Hybrid",
                   "An orbit this far out has escaped; larger is more exact for the estimate.", 64,
                   2, 1000, FR_PARAM_LOG_SCALE);
static const fr_param_desc estimate = FR_CHOICE_PARAM(
    "estimate", "Estimate", "Hybrid",
    "logarithmic: 0.5 r ln r / dr (bulbs, quaternions); linear: r / dr (boxes); box: the unit "
    "box's distance / dr (Menger-like IFS).",
    1, estimates, FR_PARAM_SPECIALIZE);
static const fr_param_desc de_factor =
    FR_FLOAT_PARAM("de_factor", "Safety factor", "Hybrid",
                   "Multiplies the estimate; lower it if `fractalis check` finds an over-estimate.",
                   0.5, 0.05, 1, 0);
static const fr_param_desc bound =
    FR_FLOAT_PARAM("bound", "Bounding radius", "Hybrid",
                   "The radius outside which the set is not (check measures it).", 6, 0.5, 100,
                   FR_PARAM_LOG_SCALE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.72, 0.45);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.25, 0.35, 0.55);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1, 0.25, 8, 0);

#define STEP_LIST(n) &step##n, &step##n##_repeat, &step##n##_a, &step##n##_b, &step##n##_v
static const fr_param_desc* const params[] = {
    STEP_LIST(1), STEP_LIST(2), STEP_LIST(3), STEP_LIST(4),   STEP_LIST(5),
    STEP_LIST(6), &iterations,  &bailout,     &estimate,      &de_factor,
    &bound,       &color_near,  &color_far,   &color_contrast};
enum { P_BOUND = 5 * 6 + 4 };

static const fr_camera camera = FR_CAMERA(7.5, 5.4, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&key, &fill};

static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  state->bounding_radius = state->params[P_BOUND].v[0];
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "hybrid",
    .name = "Hybrid composer",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Six formula steps of twelve kinds, chained: bulbs, folds, KIFS, "
        "rotations, Kali's inversion. Make your own hybrid.",
    .tags = "hybrid composer bulb box kifs",
    .credit =
        "Hybrids as in Mandelbulber (Krzysztof Marczak); the steps' own credits in "
        "fr/hybrid.cl",
    .de_source = fr_de_source,
    .de_source_name = "hybrid.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "hybrid_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 6,
    .update = update,
};

FR_SCENE_ENTRY_V1_2(&scene);
