/* bristorbrot.c — Doug Bristor's Bristorbrot (fractalforums.com, 2012): a quadratic triplex map
 * with no trigonometry, z <- (x^2 - y^2 - z^2, y (2x - z), z (2x + y)) + p. Whorls and shells where
 * the Mandelbulb has bulbs. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_ITERATIONS, P_COLOR_NEAR, P_COLOR_FAR, P_COLOR_CONTRAST, P_COUNT };

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations", "Fractal", "Escape-time iterations.", 12, 3, 40,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.7, 0.5);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.2, 0.4, 0.5);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

static const fr_param_desc* const params[P_COUNT] = {&iterations, &color_near, &color_far,
                                                     &color_contrast};

/* From above and to the side. */
static const fr_camera camera = FR_CAMERA(1.6, 2.1, 2.6, -0.4, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.45, -0.85, -0.35, 1.0, 0.95, 0.88, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.6, -0.2, 0.5, 0.4, 0.5, 0.7, 0.3);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "bristorbrot",
    .name = "Bristorbrot",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description = "Doug Bristor's quadratic triplex map: shells and whorls without a single sine.",
    .tags = "bulb triplex quadratic",
    .credit = "Doug Bristor, 'Bristorbrot', fractalforums.com, 2012",
    .de_source = fr_de_source,
    .de_source_name = "bristorbrot.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "bristorbrot_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius =
        2.6, /* checked: the DE is positive from 2.6 to twice that (fractalis check, de-bounded) */
};

FR_SCENE_ENTRY(&scene);
