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
  uint32_t abi_major;         /* FR_ABI_VERSION_MAJOR the plugin was built with */
  uint32_t abi_minor;         /* lowest host minor the plugin needs (not the SDK's: see abi.h) */
  uint32_t struct_size;       /* sizeof(fr_scene_entry) as the plugin was built */
  uint32_t reserved;          /* zero */
  const fr_scene_desc* scene; /* never null; read after init returns */

  /* ABI 1.1, all optional (null). A 1.0 host ignores them, so a plugin that cannot work
   * without init must declare minor 1 (FR_SCENE_ENTRY_V1_1). */
  /* Once per load of the library, before the descriptor is read or any other call: `host` is
   * valid during the call only (host_name, host_version, get_extension); `plugin_path` is the
   * plugin's file as the user named it (for finding data files beside it). Returns FR_OK, or
   * FR_ERROR after logging why: the plugin is then reported as failed and not used. */
  fr_result (*init)(const fr_host* host, const char* plugin_path);
  /* Once, after the last callback, before the library is unloaded. Stop threads here. */
  void (*deinit)(void);
  /* A plugin extension by id, or NULL. Called after init, from the host's main thread. */
  const void* (*get_extension)(const char* id);
} fr_scene_entry;

#if defined(_WIN32)
#define FR_EXPORT __declspec(dllexport)
#else
#define FR_EXPORT __attribute__((visibility("default")))
#endif

/* FR_SCENE_ENTRY(&scene): needs host minor 0 (loads on every 1.x host).
 * FR_SCENE_ENTRY_V1_1(&scene, init, deinit, get_extension): uses 1.1's entry fields (any may be
 * NULL) and needs a 1.1 host. */
#ifdef __cplusplus
#define FR_ENTRY_DECL_ extern "C" FR_EXPORT const fr_scene_entry fractalis_scene_entry
#else
#define FR_ENTRY_DECL_ FR_EXPORT const fr_scene_entry fractalis_scene_entry
#endif
#define FR_SCENE_ENTRY(scene_ptr) \
  FR_ENTRY_DECL_;                 \
  FR_ENTRY_DECL_ = {              \
      FR_ABI_VERSION_MAJOR, 0, sizeof(fr_scene_entry), 0, (scene_ptr), NULL, NULL, NULL}
/* FR_SCENE_ENTRY_V1_2(&scene): uses what ABI 1.2 added to the descriptor that a 1.1 host could
 * not read right (FR_PARAM_CHOICE), so it needs a 1.2 host. Tags and credit alone do not: a 1.1
 * host ignores them. */
#define FR_SCENE_ENTRY_V1_2(scene_ptr) \
  FR_ENTRY_DECL_;                      \
  FR_ENTRY_DECL_ = {FR_ABI_VERSION_MAJOR, 2, sizeof(fr_scene_entry), 0, (scene_ptr), NULL, NULL, NULL}
#define FR_SCENE_ENTRY_V1_1(scene_ptr, init_fn, deinit_fn, extension_fn)                       \
  FR_ENTRY_DECL_;                                                                              \
  FR_ENTRY_DECL_ = {                                                                           \
      FR_ABI_VERSION_MAJOR, 1, sizeof(fr_scene_entry), 0, (scene_ptr), (init_fn), (deinit_fn), \
      (extension_fn)}

#ifdef __cplusplus
}
#endif

#endif /* FRACTALIS_ENTRY_H */
