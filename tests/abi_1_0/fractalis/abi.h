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
 * Versioning: a plugin records the ABI major it was built for and the lowest host minor it needs.
 * The host loads it when the majors are equal and the host's minor is at least the plugin's.
 * Structs only grow at the end; each starts with its size so an older host can tell what a
 * newer plugin filled in, and the other way round.
 */
#ifndef FRACTALIS_ABI_H
#define FRACTALIS_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FR_ABI_VERSION_MAJOR 1u
#define FR_ABI_VERSION_MINOR 0u

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

/* What the host offers a plugin during a callback. [host-owned], valid during that call only. */
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
} fr_host;

#ifdef __cplusplus
}
#endif

#endif /* FRACTALIS_ABI_H */
