/* benchmark.c — the scene `fractalis bench` renders by default: fractal and
 * primitive geometry (a Mandelbulb and a Menger sponge on a reflective floor with spheres), two
 * coloured point lights with attenuation, ambient occlusion, soft shadows and reflections. Its
 * fixed camera route is the ordinary camera path config/paths/benchmark.toml, which
 * `fractalis bench` flies for this scene: a function of time only, so every run renders the
 * same frames. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

enum {
  P_BULB_POWER,
  P_BULB_ITERATIONS,
  P_SPONGE_LEVEL,
  P_FLOOR_REFLECTIVITY,
  P_SPHERE_REFLECTIVITY,
  P_COUNT
};

static const fr_param_desc bulb_power =
    FR_FLOAT_PARAM("bulb_power", "Bulb power", "Geometry", "Power of the Mandelbulb.", 8, 2, 16,
                   FR_PARAM_ANIMATABLE);
static const fr_param_desc bulb_iterations =
    FR_INT_PARAM("bulb_iterations", "Bulb iterations", "Geometry",
                 "Escape-time iterations of the Mandelbulb.", 8, 1, 32, FR_PARAM_SPECIALIZE);
static const fr_param_desc sponge_level =
    FR_INT_PARAM("sponge_level", "Sponge level", "Geometry",
                 "Recursion level of the Menger sponge.", 4, 1, 7, FR_PARAM_SPECIALIZE);
static const fr_param_desc floor_reflectivity =
    FR_FLOAT_PARAM("floor_reflectivity", "Floor reflectivity", "Materials",
                   "Fraction of light the floor mirrors.", 0.3, 0, 1, 0);
static const fr_param_desc sphere_reflectivity =
    FR_FLOAT_PARAM("sphere_reflectivity", "Sphere reflectivity", "Materials",
                   "Fraction of light the spheres mirror.", 0.65, 0, 1, 0);
static const fr_param_desc* const params[P_COUNT] = {&bulb_power, &bulb_iterations, &sponge_level,
                                                     &floor_reflectivity, &sphere_reflectivity};

static const fr_camera camera = FR_CAMERA(0.0, 1.8, 7.4, 0.0, -0.1, 0.0, 0.0, 1.0, 0.0, 50.0);
/* k / (1 + a d^2): warm and cool lights on either side, a little above the objects. */
static const fr_light warm = FR_POINT_LIGHT(-3.2, 3.4, 2.6, 1.0, 0.72, 0.45, 5.0, 0.12, 2.0);
static const fr_light cool = FR_POINT_LIGHT(3.4, 2.6, -2.2, 0.45, 0.62, 1.0, 4.5, 0.12, 2.0);
static const fr_light* const lights[] = {&warm, &cool};

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "benchmark",
    .name = "Benchmark",
    /* 2.0.0: the route left the update callback for config/paths/benchmark.toml */
    .version = "2.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "A Mandelbulb and a Menger sponge on a reflective floor with spheres, two "
        "coloured lights and every effect on; `fractalis bench` flies its fixed route, "
        "config/paths/benchmark.toml.",
    .tags = "showcase primitives lights reflections",
    .credit = "The Fractalis developers (a composed benchmark scene)",
    .de_source = fr_de_source,
    .de_source_name = "benchmark.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "benchmark_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS | FR_FEATURE_REFLECTIONS | FR_FEATURE_FOG |
                FR_FEATURE_GLOW,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 9.0,
};

FR_SCENE_ENTRY(&scene);
