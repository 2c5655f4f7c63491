/* The ABI headers compiled as strict C11 (-pedantic -Werror), reporting the layout C sees so the
 * C++ test can compare it with its own. */
#include <stddef.h>

#include "fractalis/fractalis.h"

size_t fr_test_c_layout(int what);

#define LAYOUT(i, expr) \
  case i: return (expr);

size_t fr_test_c_layout(int what) {
  switch (what) {
    LAYOUT(0, sizeof(fr_scene_entry))
    LAYOUT(1, sizeof(fr_scene_desc))
    LAYOUT(2, sizeof(fr_param_desc))
    LAYOUT(3, sizeof(fr_camera))
    LAYOUT(4, sizeof(fr_light))
    LAYOUT(5, sizeof(fr_frame_state))
    LAYOUT(6, sizeof(fr_host))
    LAYOUT(7, sizeof(fr_value))
    LAYOUT(8, offsetof(fr_scene_desc, de_source))
    LAYOUT(9, offsetof(fr_scene_desc, features))
    LAYOUT(10, offsetof(fr_scene_desc, bounding_radius))
    LAYOUT(11, offsetof(fr_scene_desc, update))
    LAYOUT(12, offsetof(fr_param_desc, default_value))
    LAYOUT(13, offsetof(fr_frame_state, params))
    LAYOUT(14, offsetof(fr_frame_state, bounding_radius))
    LAYOUT(15, offsetof(fr_scene_entry, scene))
    default: return 0;
  }
}
