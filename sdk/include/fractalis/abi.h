/* fractalis/abi.h — version, result codes, and the tags every other header uses.
 *
 * Fractalis scenes are shared libraries that export one data symbol (see entry.h). This header
 * holds what every part of the ABI shares. It is plain C11 and compiles as C++ too.
 *
 * Tags used in comments throughout the SDK:
 *   [main-thread]  called only on the host's main thread (the thread that runs the game loop and
 *                  loaded the plugin), never concurrently with another call into the same plugin.
 *   [host-owned]   memory owned by the host; a plugin may read (and, where the comment says so,
 *                  write) it only during the call it was passed to, and must not keep the pointer.
 *   [plugin-owned] memory owned by the plugin; it must stay valid and unchanged from the moment
 *                  the library is loaded until it is unloaded (static storage is the normal case).
 *                  The host copies every string and table it reads, so nothing dangles after
 *                  unload.
 *
 * Where plugin code runs: the host loads each plugin in a scene-host process of its own
 * (fractalis-scene-host), never in itself unless the user asks for that to debug a plugin
 * (plugins.isolation = "none"). The library's constructors and its callbacks run there; a crash,
 * hang or exit fails that scene alone. Each callback has a time limit (plugins.call_timeout_s,
 * 2 s by default); one that fails, crashes, hangs or leaves an invalid camera or light is not
 * called again until the scene is reloaded. C++ exceptions must not cross this ABI: catch
 * everything inside each callback (the host reports one that escapes as the callback's failure).
 *
 * Checked at load, before any value is used: every reserved field is zero; strings are valid
 * UTF-8 without control characters (sources may hold newlines and tabs), at most 63 bytes for
 * ids and keys, 256 for names, versions, authors, licences and groups, 4096 for descriptions and
 * 1 MiB for OpenCL sources; at most 256 parameters and FR_MAX_SCENE_LIGHTS lights.
 *
 * Versioning: a plugin records the ABI major it was built for and the lowest host minor it needs
 * — not the SDK's minor: FR_SCENE_ENTRY records 0 unless the plugin asks for more (entry.h), so a
 * plugin built with SDK 1.1 that uses nothing new loads on a 1.0 host. The host loads it when the
 * majors are equal and the host's minor is at least the plugin's. Structs only grow at the end;
 * each starts with its size so an older host can tell what a newer plugin filled in, and the
 * other way round (FR_STRUCT_HAS). New features are found by extension ids rather than by
 * version numbers: fr_host.get_extension (the host's, 1.1) and fr_scene_entry.get_extension (the
 * plugin's, 1.1) return NULL for an id they do not know.
 *
 * ABI 1.1 added: fr_host.host_name, host_version and get_extension; the host extension
 * FR_EXT_THREAD_LOG; fr_scene_entry.init, deinit and get_extension; fr_frame_state.light_stride.
 * ABI 1.2 added: fr_scene_desc.tags and credit; FR_PARAM_CHOICE with fr_param_desc.choices and
 * choice_count; FR_SCENE_ENTRY_V1_2.
 * ABI 1.3 added: fr_light.radius (area lights). A plugin that sets it still loads on an older
 * host, whose lights stay points.
 * ABI 1.4 added: fr_param_desc.detail_ratio (iteration counts that follow a deep zoom). A plugin
 * that sets it still loads on an older host, whose counts stay as set.
 */
#ifndef FRACTALIS_ABI_H
#define FRACTALIS_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FR_ABI_VERSION_MAJOR 1u
#define FR_ABI_VERSION_MINOR 4u

/* Whether a struct that starts with struct_size, as the other side built it, has `field`:
 * a 1.1 plugin on a 1.0 host must not read fields the host does not have, e.g.
 *   if (FR_STRUCT_HAS(host, fr_host, get_extension) && host->get_extension) ... */
#define FR_STRUCT_HAS(ptr, type, field) \
  ((ptr)->struct_size >= offsetof(type, field) + sizeof(((type*)0)->field))

/* Result of a plugin callback. Fixed-size integer, not an enum, so its size never changes. */
typedef int32_t fr_result;
#define FR_OK 0
#define FR_ERROR 1 /* the callback failed; it should have said why through fr_host.log first */

/* Log levels for fr_host.log. */
typedef int32_t fr_log_level;
#define FR_LOG_DEBUG 0
#define FR_LOG_INFO 1
#define FR_LOG_WARNING 2
#define FR_LOG_ERROR 3

/* What the host offers a plugin during a callback. [host-owned], valid during that call only
 * (what get_extension returns lives longer; see there). */
typedef struct fr_host {
  uint32_t struct_size; /* sizeof(fr_host) as the host was built */
  uint32_t reserved;    /* zero */

  /* Opaque to the plugin; pass it back unchanged as the first argument of log. */
  void* host_data;

  /* Writes one message to the host's log, attributed to the calling scene. `message` is a
   * NUL-terminated UTF-8 string that the host copies before returning. An FR_LOG_ERROR message
   * logged by a callback that then returns FR_ERROR becomes that error's reason in the host.
   * [main-thread] (from inside a callback). Never null. */
  void (*log)(void* host_data, fr_log_level level, const char* message);

  /* ABI 1.1 (check with FR_STRUCT_HAS before reading on an older host): */
  const char* host_name;    /* "fractalis" */
  const char* host_version; /* the host's version, e.g. "0.2.0" */
  /* A host extension by id, or NULL when this host does not have it. The pointer stays valid
   * until the library is unloaded. [any thread] */
  const void* (*get_extension)(const struct fr_host* host, const char* id);
} fr_host;

/* Host extension: a log that any thread of the plugin may call at any time between
 * fr_scene_entry.init and deinit (for example from a worker thread). Messages are passed on with
 * the next callback's answer. */
#define FR_EXT_THREAD_LOG "fractalis.host.thread-log/1"
typedef struct fr_thread_log {
  uint32_t struct_size; /* sizeof(fr_thread_log) as the host was built */
  uint32_t reserved;    /* zero */
  /* NUL-terminated UTF-8, copied before it returns. [any thread] */
  void (*log)(fr_log_level level, const char* message);
} fr_thread_log;

#ifdef __cplusplus
}
#endif

#endif /* FRACTALIS_ABI_H */
