/* fractalis/entry.h — the one symbol a scene plugin exports.
 *
 * The host finds `fractalis_scene_entry` with dlsym and reads its first fields — ABI version and
 * struct size — before it calls any plugin code, so an incompatible plugin is refused with both
 * versions in the message instead of crashing the host. Define it with FR_SCENE_ENTRY:
 *
 *   FR_SCENE_ENTRY(&my_scene);
 *
 * The SDK's CMake helper (fractalis_add_scene) builds the plugin so that this is its only
 * exported symbol.
 */
#ifndef FRACTALIS_ENTRY_H
#define FRACTALIS_ENTRY_H

#include "fractalis/abi.h"
#include "fractalis/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FR_SCENE_ENTRY_SYMBOL "fractalis_scene_entry"

/* [plugin-owned], static. Field order of the first three fields is frozen for all majors. */
typedef struct fr_scene_entry {
  uint32_t abi_major;   /* FR_ABI_VERSION_MAJOR the plugin was built with */
  uint32_t abi_minor;   /* lowest host minor the plugin needs */
  uint32_t struct_size; /* sizeof(fr_scene_entry) as the plugin was built */
  uint32_t reserved;    /* zero */
  const fr_scene_desc* scene; /* never null */
} fr_scene_entry;

#if defined(_WIN32)
#define FR_EXPORT __declspec(dllexport)
#else
#define FR_EXPORT __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
#define FR_SCENE_ENTRY(scene_ptr)                                                        \
  extern "C" FR_EXPORT const fr_scene_entry fractalis_scene_entry;                      \
  extern "C" FR_EXPORT const fr_scene_entry fractalis_scene_entry = {                   \
      FR_ABI_VERSION_MAJOR, FR_ABI_VERSION_MINOR, sizeof(fr_scene_entry), 0, (scene_ptr)}
#else
#define FR_SCENE_ENTRY(scene_ptr)                                 \
  FR_EXPORT extern const fr_scene_entry fractalis_scene_entry;   \
  FR_EXPORT const fr_scene_entry fractalis_scene_entry = {       \
      FR_ABI_VERSION_MAJOR, FR_ABI_VERSION_MINOR, sizeof(fr_scene_entry), 0, (scene_ptr)}
#endif

#ifdef __cplusplus
}
#endif

#endif /* FRACTALIS_ENTRY_H */
