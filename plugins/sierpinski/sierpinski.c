/* sierpinski.c — the Sierpinski tetrahedron by folding: iterations, scale and offset. With the
 * defaults (scale 2, offset 1,1,1) the surface is exactly the union of the 4^n level-n tetrahedra
 * of the regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1). */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_ITERATIONS, P_SCALE, P_OFFSET, P_COLOR_NEAR, P_COLOR_FAR, P_COUNT };

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Level", "Fractal", "Recursion level n: 4^n tetrahedra.", 7, 1, 16,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc scale = FR_FLOAT_PARAM(
    "scale", "Scale", "Fractal", "Scale per fold; 2 is the classic tetrahedron.", 2, 1.5, 3, 0);
static const fr_param_desc offset =
    FR_VEC3_PARAM("offset", "Fold offset", "Fractal",
                  "Vertex the scale is taken about; 1,1,1 is classic.", 1, 1, 1, 0, 2, 0);
static const fr_param_desc color_near = FR_COLOR_PARAM(
    "color_near", "Colour A", "Colour", "Albedo of one end of the palette.", 0.85, 0.78, 0.55);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour B", "Colour", "Albedo of the other end.", 0.25, 0.45, 0.55);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &scale, &offset, &color_near,
                                                     &color_far};

static const fr_camera camera = FR_CAMERA(3.0, 1.4, 4.1, 0.0, -0.2, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.4, -0.9, -0.3, 1.0, 0.96, 0.9, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.5, 0.1, 0.6, 0.45, 0.5, 0.7, 0.25);
static const fr_light* const lights[] = {&key, &fill};

/* As for the sponge: the attractor lies within |offset| of the origin, the base tetrahedron
 * within sqrt 3. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  const double* c = state->params[P_OFFSET].v;
  double length = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  state->bounding_radius = 1.05 * fmax(sqrt(3.0), length) + 0.05;
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "sierpinski",
    .name = "Sierpinski tetrahedron",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "The Sierpinski tetrahedron by folding: four half-size copies, recursively.",
    .tags = "ifs tetrahedron",
    .credit =
        "Waclaw Sierpinski, 1915 (the triangle); the tetrahedron by folding after Knighty, "
        "fractalforums.com, 2010",
    .de_source = fr_de_source,
    .de_source_name = "sierpinski.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "sierpinski_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.87,
    .update = update,
};

FR_SCENE_ENTRY(&scene);
