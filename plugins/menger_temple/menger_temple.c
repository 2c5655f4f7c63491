/* menger_temple.c — A temple of Menger sponges on a stepped plinth, with sponge pillars and warm
 * lamps: a composed scene from the DE library, like the benchmark. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum { P_SPONGE_LEVEL, P_PILLAR_LEVEL, P_STONE_COLOR, P_STONE_SHADE, P_FLOOR_COLOR, P_COUNT };

static const fr_param_desc sponge_level =
    FR_INT_PARAM("sponge_level", "Sponge levels", "Fractal", "The great sponge's levels.", 4, 1, 7,
                 FR_PARAM_SPECIALIZE);
static const fr_param_desc pillar_level =
    FR_INT_PARAM("pillar_level", "Pillar levels", "Fractal", "The pillars' sponges' levels.", 3, 1,
                 6, FR_PARAM_SPECIALIZE);
static const fr_param_desc stone_color =
    FR_COLOR_PARAM("stone_color", "Stone", "Colour", "Albedo of the sponges.", 0.86, 0.8, 0.7);
static const fr_param_desc stone_shade =
    FR_COLOR_PARAM("stone_shade", "Stone (deep)", "Colour",
                   "Albedo deep inside the sponges, and of the plinth.", 0.55, 0.45, 0.38);
static const fr_param_desc floor_color =
    FR_COLOR_PARAM("floor_color", "Floor", "Colour", "Albedo of the floor.", 0.42, 0.38, 0.33);

static const fr_param_desc* const params[P_COUNT] = {&sponge_level, &pillar_level, &stone_color,
                                                     &stone_shade, &floor_color};

/* From the temple steps, a little above. */
static const fr_camera camera = FR_CAMERA(5.2, 2.2, 6.0, 0.0, -0.2, 0.0, 0.0, 1.0, 0.0, 50.0);
static const fr_light light_0 = FR_POINT_LIGHT(0.0, 2.6, 3.2, 1.0, 0.75, 0.45, 6.0, 0.15, 2.0);
static const fr_light light_1 = FR_POINT_LIGHT(-3.5, 1.2, -2.5, 1.0, 0.6, 0.3, 3.0, 0.2, 2.0);
static const fr_light light_2 = FR_DIRECTIONAL_LIGHT(0.3, -0.8, -0.5, 0.55, 0.65, 0.9, 0.5);
static const fr_light* const lights[] = {&light_0, &light_1, &light_2};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "menger_temple",
    .name = "Menger temple",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "A temple of Menger sponges: a great sponge on a plinth, sponge pillars, lamplight and "
        "haze.",
    .tags = "showcase sponge architecture lights",
    .credit = "Karl Menger, 1926 (the sponge); composed by the Fractalis developers",
    .de_source = fr_de_source,
    .de_source_name = "menger_temple.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "menger_temple_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_FOG,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 7.0, /* the floor disc, radius 6.5 */
};

FR_SCENE_ENTRY(&scene);
