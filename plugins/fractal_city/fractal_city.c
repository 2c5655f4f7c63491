/* fractal_city.c — A city of Menger-sponge towers on a grid, each of its own height, in haze: a
 * composed scene from the DE library. The DE stays a lower bound across cells of different heights.
 */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_LEVEL,
  P_COLOR_NEAR,
  P_COLOR_FAR,
  P_COLOR_CONTRAST,
  P_WINDOW_GLOW,
  P_WINDOW_COLOR,
  P_COUNT
};

static const fr_param_desc level =
    FR_INT_PARAM("level", "Sponge levels", "Fractal", "Each storey's sponge levels.", 3, 1, 5,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.8, 0.78, 0.72);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.35, 0.38, 0.45);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1.0, 0.25, 8, 0);

/* Path tracing (the material function in fractal_city_surface.cl): lit windows. */
static const fr_param_desc window_glow =
    FR_FLOAT_PARAM("window_glow", "Window glow", "Material",
                   "Path tracing: radiance of the lit windows (the sponge's holes); 0: all dark.",
                   1.5, 0, 50, FR_PARAM_ANIMATABLE);
static const fr_param_desc window_color =
    FR_COLOR_PARAM("window_color", "Window colour", "Material",
                   "Path tracing: the colour of the windows' light.", 1.0, 0.62, 0.3);

static const fr_param_desc* const params[P_COUNT] = {&level,          &color_near,  &color_far,
                                                     &color_contrast, &window_glow, &window_color};

/* Over the city from its edge. */
static const fr_camera camera = FR_CAMERA(6.5, 3.2, 7.0, 0.0, -0.2, 0.0, 0.0, 1.0, 0.0, 50.0);
static const fr_light light_0 = FR_DIRECTIONAL_LIGHT(-0.35, -0.6, -0.7, 1.0, 0.85, 0.7, 1.3);
static const fr_light light_1 = FR_DIRECTIONAL_LIGHT(0.5, -0.4, 0.6, 0.4, 0.5, 0.8, 0.35);
static const fr_light* const lights[] = {&light_0, &light_1};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "fractal_city",
    .name = "Fractal city",
    .version = "1.1.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "A city of Menger-sponge towers, each of its own height, on a round plain in haze.",
    .tags = "showcase sponge city architecture",
    .credit = "Karl Menger, 1926 (the sponge); composed by the Fractalis developers",
    .de_source = fr_de_source,
    .de_source_name = "fractal_city.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "fractal_city_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_FOG,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 7.0, /* the ground disc, radius 6.5 */
};

FR_SCENE_ENTRY(&scene);
