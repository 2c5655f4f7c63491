// camera_up.hpp — the up direction a camera's image is built with.
//
// A camera's up vector only has to say which way is up; when it is parallel to the view (looking
// straight down or up the default up axis: --eye 0,0,3 --target 0,0,0 with up +z), it says
// nothing, and the camera takes a stable perpendicular instead of refusing: the world axis least
// aligned with the view, preferring y, then z, then x on ties. So looking along +-z, image up is
// +y; along +-y, +z.
#pragma once

#include <fractalis/fractalis.h>

#include <glm/vec3.hpp>

namespace fr {

// The camera's up, or the stable perpendicular when up is zero or within 1e-6 rad of the view
// direction (or its opposite). Not normalised; never parallel to target - eye.
glm::dvec3 effective_up(const fr_camera& camera);

}  // namespace fr
