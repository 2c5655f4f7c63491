/* my_scene.c — the scene's descriptor: its parameters, its default camera and lights, and an
 * update callback that animates the ripple from the time alone (never from hidden state, so the
 * same time gives the same picture). */
#include <fractalis/fractalis.h>
#include <math.h>

extern const char fr_de_source[]; /* my_scene.cl, embedded by fractalis_add_scene */

static const fr_param_desc radius =
    FR_FLOAT_PARAM("radius", "Radius", "Shape", "Radius of the sphere.", 1.0, 0.5, 1.5, 0);
static const fr_param_desc ripple = FR_FLOAT_PARAM(
    "ripple", "Ripple", "Shape", "Depth of the ripple.", 0.05, 0.0, 0.1, FR_PARAM_ANIMATABLE);
static const fr_param_desc waves =
    FR_FLOAT_PARAM("waves", "Waves", "Shape", "Ripples per unit length.", 4.0, 1.0, 8.0, 0);
static const fr_param_desc* const params[] = {&radius, &ripple, &waves};

static const fr_camera camera = FR_CAMERA(0.0, 1.0, 4.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 45.0);
static const fr_light sun = FR_DIRECTIONAL_LIGHT(-0.5, -1.0, -0.3, 1.0, 0.97, 0.9, 3.0);
static const fr_light* const lights[] = {&sun};

/* The ripple breathes with a period of 4 s: state is a function of time_s. */
static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance, (void)host;
  state->params[1].v[0] = 0.05 + 0.04 * sin(state->time_s * 1.5707963267948966);
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "my_scene",
    .name = "My scene",
    .version = "0.1.0",
    .author = "You",
    .license = "MIT",
    .description = "A rippled sphere: the Fractalis scene template.",
    .tags = "showcase template", /* family first, then traits: `fractalis list --tag` */
    .credit = "You",             /* who found the formula, and where it was published */
    .de_source = fr_de_source,
    .de_source_name = "my_scene.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_SHADOWS | FR_FEATURE_AO,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 1.7, /* radius max 1.5 + ripple max 0.1, with room to spare */
    .update = update,
};
FR_SCENE_ENTRY(&scene);
