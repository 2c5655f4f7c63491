/* kalibox.c — Kali's Kalibox (Pablo Roman Andrioli, fractalforums.com, 2011): the Mandelbox with
 * its box fold replaced by abs(z) + translation and a Julia constant: towers, lace and spirals. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_SCALE,
  P_MIN_RADIUS2,
  P_TRANSLATION,
  P_C,
  P_ANGLE_X_DEG,
  P_ANGLE_Y_DEG,
  P_ANGLE_Z_DEG,
  P_ITERATIONS,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc scale =
    FR_FLOAT_PARAM("scale", "Scale", "Fractal", "z <- scale * sphere fold(|z| + t) + c.", 2.04348,
                   -3, 3, FR_PARAM_ANIMATABLE);
static const fr_param_desc min_radius2 = FR_FLOAT_PARAM("min_radius2", "Min radius^2", "Fractal",
                                                        "Squared inner radius of the sphere fold.",
                                                        0.3492, 0.05, 1, FR_PARAM_ANIMATABLE);
static const fr_param_desc translation =
    FR_VEC3_PARAM("translation", "Translation", "Fractal", "Added after the abs fold.", 0.0365,
                  -1.8613, 0.0365, -3, 3, FR_PARAM_ANIMATABLE);
static const fr_param_desc c =
    FR_VEC3_PARAM("c", "Julia c", "Fractal", "The constant added each iteration.", -0.6691, -1.3028,
                  -0.45775, -3, 3, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_x_deg = FR_FLOAT_PARAM(
    "angle_x_deg", "Rotation x", "Fractal", "Rotation about x before each fold, degrees.", 0.0,
    -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_y_deg = FR_FLOAT_PARAM(
    "angle_y_deg", "Rotation y", "Fractal", "Rotation about y before each fold, degrees.", 0.0,
    -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc angle_z_deg = FR_FLOAT_PARAM(
    "angle_z_deg", "Rotation z", "Fractal", "Rotation about z before each fold, degrees.", 0.0,
    -180, 180, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Folds per evaluation; more is finer.", 17,
                 4, 40, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.95, 0.8, 0.55);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.15, 0.3, 0.45);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {
    &scale,       &min_radius2, &translation, &c,         &angle_x_deg,   &angle_y_deg,
    &angle_z_deg, &iterations,  &color_near,  &color_far, &color_contrast};

/* Close to its ornamented tower, looking down. */
static const fr_camera camera = FR_CAMERA(0.5, -1.2, 1.5, 0.0, -2.0, 0.0, 0.0, 1.0, 0.0, 70.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

/* Beyond radius 1 the sphere fold is the identity, so |z| grows by |scale| (|z| - |t|) - |c|
 * per step: a point beyond (|scale| |t| + |c|) / (|scale| - 1) escapes. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const fr_value* v = state->params;
  const double s = fabs(v[P_SCALE].v[0]);
  const double* t = v[P_TRANSLATION].v;
  const double* c = v[P_C].v;
  const double t_len = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  const double c_len = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  const double escape = s > 1.05 ? (s * t_len + c_len) / (s - 1.0) : 40.0;
  state->bounding_radius = 1.02 * fmax(escape, 1.0) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "kalibox",
    .name = "Kalibox",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "Kali's Kalibox: the Mandelbox's folds broken into towers, spirals and lace.",
    .tags = "kali box julia",
    .credit =
        "Kali (Pablo Roman Andrioli), 'Kalibox', fractalforums.com, 2011; estimate after Rrrola, "
        "2010",
    .de_source = fr_de_source,
    .de_source_name = "kalibox.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "kalibox_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 6.0,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
