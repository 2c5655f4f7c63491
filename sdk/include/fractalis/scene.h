/* fractalis/scene.h — what a scene is: its descriptor, its camera and lights, and its callbacks.
 *
 * A scene supplies an OpenCL distance estimator and a parameter table; the host does everything
 * else (camera, marching, lighting, output). All mutable state — parameter values, camera,
 * lights, time — belongs to the host and is lent to the scene's update callback each frame, so
 * a scene keeps no hidden globals and its animation is a function of time and inputs alone.
 */
#ifndef FRACTALIS_SCENE_H
#define FRACTALIS_SCENE_H

#include "fractalis/abi.h"
#include "fractalis/param.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Renderer features a scene needs, OR-ed together. The host compiles a stage only when the scene
 * needs it and the user has not switched it off; code for other stages is not in the kernel. */
typedef uint64_t fr_features;
#define FR_FEATURE_SHADOWS (1ull << 0)     /* soft shadows towards each light */
#define FR_FEATURE_AO (1ull << 1)          /* ambient occlusion */
#define FR_FEATURE_GLOW (1ull << 2)        /* glow from the closest approach of missing rays */
#define FR_FEATURE_FOG (1ull << 3)         /* distance fog */
#define FR_FEATURE_REFLECTIONS (1ull << 4) /* mirror bounces */

/* A pinhole camera. World space is right-handed with +y up by convention. */
typedef struct fr_camera {
  uint32_t struct_size; /* sizeof(fr_camera) */
  uint32_t reserved;    /* zero */
  double eye[3];        /* world-space position of the eye */
  double target[3];     /* the point looked at; never equal to eye */
  double up[3];         /* approximate up direction; not parallel to target - eye */
  double fov_deg;       /* horizontal field of view in degrees, in (0, 180) */
} fr_camera;

/* The most lights a scene may declare; the host refuses a scene with more. */
#define FR_MAX_SCENE_LIGHTS 8u

typedef uint32_t fr_light_kind;
#define FR_LIGHT_DIRECTIONAL 1u /* `vector` is the direction the light travels (towards scene) */
#define FR_LIGHT_POINT 2u       /* `vector` is the light's world-space position */

/* A light. A point light at distance d delivers color * intensity / (1 + attenuation * d^falloff)
 * (k / (1 + a d^e): k, a and e below); directional lights do not fall
 * off. Either way, the light delivered is what a white surface facing the light reflects. */
typedef struct fr_light {
  uint32_t struct_size; /* sizeof(fr_light) */
  fr_light_kind kind;
  double vector[3];   /* direction or position, see fr_light_kind */
  double color[3];    /* linear RGB */
  double intensity;   /* k: multiplies color */
  double attenuation; /* a >= 0; 0: no falloff */
  double falloff;     /* e > 0; 2 is physical */
  /* ABI 1.3 (an older host reads a point; a plugin built before reads 0 here): the light's size,
   * which the path integrator gives it (the fast one lights from its centre). A point light is a
   * glowing sphere of this radius in world units around `vector`; a directional light a disc of
   * this angular radius in radians (the sun: 0.0047), below 0.5. 0: a point, which casts hard
   * shadows and which no ray can see. Soft shadows and highlights come from the size. */
  double radius;
} fr_light;

/* What the update callback receives each frame. [host-owned]: the callback may change the
 * parameter values (within their limits), the camera, the lights and the bounding radius; the
 * host clamps parameter values to their limits afterwards. Valid during the call only. */
typedef struct fr_frame_state {
  uint32_t struct_size; /* sizeof(fr_frame_state) */
  uint32_t param_count; /* equals the scene's param_count */
  double time_s;        /* scene time in seconds since the scene started; deterministic */
  double dt_s;          /* time since the previous update, seconds; 0 on the first */
  uint64_t frame_index; /* 0 on the first update */

  fr_value* params;     /* param_count values, in the order of fr_scene_desc.params */
  fr_camera* camera;    /* the current camera */
  fr_light* lights;     /* light_count lights */
  uint32_t light_count; /* may not be changed by the callback */
  uint32_t reserved;    /* zero */

  /* Radius of a sphere around the origin outside which the surface provably is not. The host
   * marches only inside it, which is what keeps over-estimating DEs honest. Starts at
   * fr_scene_desc.bounding_radius; an update callback may tighten it from the parameters. */
  double bounding_radius;

  /* ABI 1.1: bytes from one light to the next in `lights` (sizeof(fr_light) as the host built
   * it), so fr_light can grow; index lights with FR_FRAME_LIGHT. */
  uint32_t light_stride;
  uint32_t reserved2; /* zero */
} fr_frame_state;

/* Light i of a frame state, on any 1.x host (1.0 hosts pass 1.0-sized lights). */
#define FR_FRAME_LIGHT(state, i)                                                                \
  ((fr_light*)((char*)(state)->lights +                                                         \
               (size_t)(i) *                                                                    \
                   (FR_STRUCT_HAS(state, fr_frame_state, light_stride) && (state)->light_stride \
                        ? (state)->light_stride                                                 \
                        : sizeof(fr_light))))

/* Creates one instance of the scene's private state (for example caches). Optional: may be null,
 * and then the instance pointer is null. Returns FR_OK and sets *out_instance, or FR_ERROR after
 * logging why. [main-thread] */
typedef fr_result (*fr_create_fn)(const fr_host* host, void** out_instance);

/* Destroys what create made. Called exactly once per successful create, before unload.
 * Optional. [main-thread] */
typedef void (*fr_destroy_fn)(void* instance);

/* Advances the scene to state->time_s. Called once per frame before rendering (also once before
 * a headless render). Must be deterministic: the same time and inputs give the same state.
 * Returns FR_OK, or FR_ERROR after logging why; the host then stops using the scene. Optional.
 * [main-thread] */
typedef fr_result (*fr_update_fn)(void* instance, const fr_host* host, fr_frame_state* state);

/* The scene. [plugin-owned]. Strings are NUL-terminated UTF-8. */
typedef struct fr_scene_desc {
  uint32_t struct_size; /* sizeof(fr_scene_desc) as the plugin was built */
  uint32_t reserved;    /* zero */

  const char* id;          /* stable, unique: [a-z][a-z0-9_-]*, at most 63 bytes. Never null. */
  const char* name;        /* display name. Never null. */
  const char* version;     /* the scene's own version, e.g. "1.2.0". Never null. */
  const char* author;      /* may be null */
  const char* license;     /* SPDX identifier, e.g. "MIT"; may be null */
  const char* description; /* one or two sentences; may be null */

  /* OpenCL C source, lane-generic (sdk/docs/writing-a-scene.md), defining
   *   real_t scene_de(vec3_t p, __constant const scene_params_t* params);
   * It may pull in the DE helper library with lines such as #include "fr/primitives.cl".
   * Never null. `de_source_name` names it in compiler messages ("mandelbulb.cl"); may be null. */
  const char* de_source;
  const char* de_source_name;

  /* Optional OpenCL C, compiled after de_source (so it may call what that defines), defining
   *   surface_t scene_surface(vec3_t p, __constant const scene_params_t* params);
   * the albedo and reflectivity at a surface point — for example colouring by orbit trap. Null:
   * the host's material settings apply. It may also define
   *   material_t scene_material(vec3_t p, material_t m, __constant const scene_params_t* params);
   * the path tracer's full material at p (glass, metal, subsurface, emission; material_t in
   * kernels/prelude.cl), given the default one; the host calls it when the function exists.
   * `surface_source_name` as for de_source_name. */
  const char* surface_source;
  const char* surface_source_name;

  const fr_param_desc* const* params; /* param_count pointers; may be null when param_count is 0 */
  uint32_t param_count;
  uint32_t light_count; /* number of default lights, at most FR_MAX_SCENE_LIGHTS */

  fr_features features;          /* what the scene needs from the renderer */
  const fr_camera* camera;       /* default camera; null: the host's default view */
  const fr_light* const* lights; /* light_count pointers to default lights; may be null if 0 */
  double bounding_radius;        /* see fr_frame_state.bounding_radius; must be > 0 */

  fr_create_fn create;   /* optional */
  fr_destroy_fn destroy; /* optional */
  fr_update_fn update;   /* optional */

  /* ABI 1.2 (a 1.0 or 1.1 host ignores them; a plugin that sets them still loads there): */
  /* Words that file the scene for browsing and `fractalis list --tag`: its family first, then
   * its traits, space-separated, e.g. "box julia animated". Each word matches [a-z0-9][a-z0-9-]*;
   * at most 16 words and 256 bytes. The in-tree families: bulb, box, kifs, kleinian,
   * hypercomplex, ifs, kali, hybrid, showcase. May be null. */
  const char* tags;
  /* Who found the formula and where it was published, one line, e.g. "Tom Lowe, 'Amazing
   * Box', fractalforums.com, 2010". At most 256 bytes; may be null (then `author` is all). */
  const char* credit;
} fr_scene_desc;

#ifdef __cplusplus
}
#endif

#endif /* FRACTALIS_SCENE_H */
