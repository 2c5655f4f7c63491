/* pseudo_kleinian.c — Knighty's pseudo-Kleinian (fractalforums.com, "Pseudo Kleinian groups",
 * 2011): box folds and an inversion in the unit sphere, ending on a thin tube. Endless corridors of
 * arches and pillars; the set is cut to a ball of radius `extent`. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_ITERATIONS,
  P_BOX_SIZE,
  P_INVERSION_K,
  P_OFFSET,
  P_TUBE_RADIUS,
  P_EXTENT,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_COUNT
};

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Folds per evaluation; more is finer.", 10,
                 3, 30, FR_PARAM_SPECIALIZE);
static const fr_param_desc box_size =
    FR_VEC3_PARAM("box_size", "Box size", "Fractal", "Half-sides of the box fold.", 0.92436,
                  0.90756, 0.92436, 0.3, 2, FR_PARAM_ANIMATABLE);
static const fr_param_desc inversion_k =
    FR_FLOAT_PARAM("inversion_k", "Inversion radius^2", "Fractal",
                   "Squared radius of the inversion sphere.", 1.0, 0.3, 2, FR_PARAM_ANIMATABLE);
static const fr_param_desc offset =
    FR_VEC3_PARAM("offset", "Offset", "Fractal", "Added after each inversion.", 0.0, 0.0, 0.0, -1,
                  1, FR_PARAM_ANIMATABLE);
static const fr_param_desc tube_radius = FR_FLOAT_PARAM(
    "tube_radius", "Tube radius", "Fractal", "Radius of the final cylinder.", 0.92784, 0.1, 2, 0);
static const fr_param_desc extent = FR_FLOAT_PARAM(
    "extent", "Extent", "Fractal", "Radius of the ball the endless set is cut to.", 8, 1, 20, 0);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.85, 0.7, 0.45);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.3, 0.35, 0.45);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &box_size,    &inversion_k,
                                                     &offset,     &tube_radius, &extent,
                                                     &color_near, &color_far,   &color_contrast};

/* Inside the halls, looking along a corridor. */
static const fr_camera camera = FR_CAMERA(1.6, 0.3, 0.9, 0.0, 0.0, 0.4, 0.0, 0.0, 1.0, 70.0);
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
    .id = "pseudo_kleinian",
    .name = "Pseudo-Kleinian",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Knighty's pseudo-Kleinian: box folds and sphere inversions build endless halls of arches.",
    .tags = "kleinian inversion architecture",
    .credit = "Knighty, 'Pseudo Kleinian groups', fractalforums.com, 2011",
    .de_source = fr_de_source,
    .de_source_name = "pseudo_kleinian.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "pseudo_kleinian_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_FOG,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 8.21,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
