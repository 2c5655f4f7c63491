/* quaternion_mandelbrot.c — the Mandelbrot set of quaternions, q <- q^2 + c, sliced to 3D at a
 * chosen w (the quaternion Julia sets' parameter space; Alan Norton's quaternion fractals, 1982,
 * and John Hart's ray-traced ones, 1989). At w = 0 it is the Mandelbrot set spun about its real
 * axis; other slices break that symmetry. */
#include <math.h>

#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_SLICE_W, P_ITERATIONS, P_BAILOUT, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc slice_w = FR_FLOAT_PARAM(
    "slice_w", "Slice w", "Fractal", "The fourth coordinate of c: 0 is the spun Mandelbrot set.",
    0.0, -1.0, 1.0, FR_PARAM_ANIMATABLE);
static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Maximum escape-time iterations.", 14, 2,
                 64, FR_PARAM_SPECIALIZE);
static const fr_param_desc bailout =
    FR_FLOAT_PARAM("bailout", "Bailout radius", "Fractal",
                   "Escape radius (the set lies inside |c| <= 2).", 4, 2, 1000, FR_PARAM_LOG_SCALE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the origin.", 0.20, 0.35, 0.75);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.95, 0.80, 0.45);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&slice_w,    &iterations, &bailout,
                                                     &color_near, &color_far,  &color_contrast};

static const fr_camera camera = FR_CAMERA(-0.5, 2.0, 2.9, -0.5, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.4, -0.9, -0.4, 1.0, 0.95, 0.88, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.25);
static const fr_light* const lights[] = {&key, &fill};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "quaternion_mandelbrot",
    .name = "Quaternion Mandelbrot",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "The Mandelbrot set of quaternions, sliced to 3D: the classic set spun and warped.",
    .tags = "hypercomplex quaternion mandelbrot",
    .credit = "Alan Norton, SIGGRAPH 1982; DE after Hart, Sandin and Kauffman, 1989",
    .de_source = fr_de_source,
    .de_source_name = "quaternion_mandelbrot.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "quaternion_mandelbrot_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.06, /* |c| <= 2, with a margin */
    .update = NULL,
};

FR_SCENE_ENTRY(&scene);
