/* tetrabrot.c — The Tetrabrot (Dominic Rochon, "A generalized Mandelbrot set for bicomplex
 * numbers", Fractals 8(4), 2000): the bicomplex Mandelbrot set sliced to 3D. In the idempotent
 * basis it is two ordinary Mandelbrot sets at once, which gives its boxy, terraced shape and a DE
 * that is a proven lower bound (fr/hypercomplex.cl). */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal",
                 "Escape-time iterations of each Mandelbrot set.", 24, 4, 100, FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.45, 0.25);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.25, 0.45, 0.8);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 0.8, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &color_near, &color_far,
                                                     &color_contrast};

/* Three quarters from above. */
static const fr_camera camera = FR_CAMERA(2.4, 1.9, 2.8, -0.4, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "tetrabrot",
    .name = "Tetrabrot",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Rochon's Tetrabrot: the bicomplex Mandelbrot set, two Mandelbrot sets crossed into "
        "terraces.",
    .tags = "hypercomplex bicomplex mandelbrot",
    .credit =
        "Dominic Rochon, 'A generalized Mandelbrot set for bicomplex numbers', Fractals 8(4), 2000",
    .de_source = fr_de_source,
    .de_source_name = "tetrabrot.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "tetrabrot_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2.95, /* both complex points lie in |c| <= 2, so |p|^2 <= 8 */
};

FR_SCENE_ENTRY(&scene);
