/* fractalis/param.h — the parameter table a scene declares, and the values the host keeps.
 *
 * A scene declares its parameters once, statically. The host owns their values: it creates them
 * from the defaults, lets the user change them within [min, max], passes them to the scene's
 * update callback, and hands them to the OpenCL kernel as a struct it generates from this table
 * (see sdk/docs/writing-a-scene.md). Because the values live in the host, a reloaded scene keeps
 * them by key.
 */
#ifndef FRACTALIS_PARAM_H
#define FRACTALIS_PARAM_H

#include "fractalis/abi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Parameter type. In OpenCL, PARAM(key) reads a parameter as:
 *   FR_PARAM_FLOAT  scalar_t (float or double, the kernel's precision)
 *   FR_PARAM_INT    int
 *   FR_PARAM_BOOL   int, 0 or 1
 *   FR_PARAM_VEC3   vec3_t, the same value in every lane
 *   FR_PARAM_COLOR  vec3_t, linear RGB in [0, 1]
 *   FR_PARAM_CHOICE int, the index of one of the parameter's named values (ABI 1.2); the kernel
 *                   also gets FR_CHOICE_<key>_<name> for each name, so a scene compares
 *                   PARAM(step) == FR_CHOICE_step_box_fold rather than a bare number */
typedef uint32_t fr_param_type;
#define FR_PARAM_FLOAT 1u
#define FR_PARAM_INT 2u
#define FR_PARAM_BOOL 3u
#define FR_PARAM_VEC3 4u
#define FR_PARAM_COLOR 5u
#define FR_PARAM_CHOICE 6u /* ABI 1.2: needs a 1.2 host (FR_SCENE_ENTRY_V1_2) */

/* Parameter flags, OR-ed together. */
typedef uint32_t fr_param_flags;
#define FR_PARAM_ANIMATABLE (1u << 0) /* the update callback may change it every frame */
#define FR_PARAM_SPECIALIZE                                                                   \
  (1u << 1)                          /* baked into the kernel as a constant: faster, but each \
                                        new value builds a new program. Not with ANIMATABLE. */
#define FR_PARAM_LOG_SCALE (1u << 2) /* a UI shows it on a logarithmic slider (min > 0) */

/* One value of any parameter type: float, int and bool use v[0] (int and bool hold whole
 * numbers; bool is 0 or 1); vec3 and color use v[0..2]. Double so that every int32 is exact. */
typedef struct fr_value {
  double v[3];
} fr_value;

/* One parameter. [plugin-owned]; the host copies it when it loads the plugin. */
typedef struct fr_param_desc {
  uint32_t struct_size; /* sizeof(fr_param_desc) as the plugin was built */
  fr_param_type type;
  fr_param_flags flags;
  uint32_t reserved; /* zero */

  /* Identifier used in OpenCL (PARAM(key)), on the command line (--param key=value) and in
   * settings files: [a-z][a-z0-9_]*, at most 63 bytes, unique within the scene. Never null. */
  const char* key;
  const char* name;        /* display name, never null */
  const char* group;       /* UI group ("Fractal", "Colour"); null: no group */
  const char* description; /* one sentence for tooltips and `fractalis list`; may be null */

  /* min <= default <= max component by component. For FR_PARAM_BOOL min is 0 and max is 1.
   * Choose limits that keep the scene's float math finite over the whole range. */
  fr_value default_value;
  fr_value min_value;
  fr_value max_value;

  /* ABI 1.2. For FR_PARAM_CHOICE: the names of its values, choice_count of them (1 to 64), each
   * [a-z][a-z0-9_]* and at most 63 bytes, none twice. The value is an index: min 0, max
   * choice_count - 1, and the default one of them. Users see and type only the names (the
   * overlay's combo box, --param key=name, path files). Null and 0 for every other type.
   * [plugin-owned] */
  const char* const* choices;
  uint32_t choice_count;
  uint32_t reserved2; /* zero */

  /* ABI 1.4. For an FR_PARAM_INT iteration count (the orbit's steps, a sponge's levels): the
   * factor by which each one more resolves finer detail, as a multiple of the scene's bounding
   * radius (2 for the Mandelbox, 3 for the Menger sponge: detail of size R / ratio^n after n).
   * With render.auto_iterations the host adds log(R / d) / log(ratio) to the value as the eye
   * closes in to a distance d from the surface (a deep zoom), up to what the view's pixel
   * footprint resolves, never lowers it, and says so. 0: not such a count (and every parameter of a plugin built before
   * 1.4). Finite and above 1 otherwise. FR_ITERATIONS_PARAM (helpers.h) sets it. */
  double detail_ratio;
} fr_param_desc;

#ifdef __cplusplus
}
#endif

#endif /* FRACTALIS_PARAM_H */
