// camera_controller.hpp — flying and orbiting the camera from the user's input.
//
// Fly: W/A/S/D move along the view and sideways, up/down along the camera's up; the mouse turns
// the view (yaw about up, pitch about right). Orbit: the mouse turns the eye around the target
// at a fixed distance; the wheel (or forward/back) changes the distance. Speeds are in units of
// the distance to the nearest surface per second, so the same keys cross the whole scene from
// afar and creep through fine detail up close, never stepping through the surface.
#pragma once

#include "app/input.hpp"

#include "scene/scene_data.hpp"

#include <fractalis/scene.h>

namespace fr {

enum class CameraMode { Fly, Orbit };

struct CameraControls {
  double mouse_sensitivity_deg_per_px = 0.15;
  bool invert_y = false;
  double speed_per_distance = 1.0;  // fly speed = this x distance to the surface, per second
  double speed_up_factor = 4.0;     // while SpeedUp is held
  double min_speed = 1e-5;          // world units per second (less, near a deep view's target)
  double max_speed = 10.0;
};

struct CameraMotion {
  bool moved = false;  // the camera changed this frame
};

// The surface under the pointer, for a zoom towards it: the unit direction of the ray through
// the pointer's pixel and the distance along it to the surface.
struct ZoomPoint {
  double dir[3] = {0, 0, 1};
  double distance = 0;
};

// Moves `camera` by one frame of `input` over dt_s seconds. `surface_distance` is the scene's
// distance estimate at the eye (negative or zero: at or inside the surface); steps never exceed
// 0.9 of it, so the camera cannot pass through the surface. `look` says whether mouse movement
// turns the view (the pointer is captured).
//
// The wheel, and ZoomIn and ZoomOut held (four notches a second), zoom: in orbit mode towards
// the target, otherwise towards `zoom_point` (the surface under the pointer: the eye moves along
// the pointer's ray, so the point stays under it, and the view keeps its direction), a quarter of
// the remaining distance a notch in, back by as much out. The camera moves in pairs
// (scene_data.hpp, CameraLow: the moves are worked out relative to the eye and added to its
// double-double), so a zoom goes on past what double resolves.
CameraMotion update_camera(fr_camera& camera, CameraLow& low, CameraMode mode,
                           const InputState& input, bool look, double dt_s, double surface_distance,
                           const CameraControls& controls, const ZoomPoint* zoom_point = nullptr);

// The same for a camera in double alone (what the pairs add is dropped).
inline CameraMotion update_camera(fr_camera& camera, CameraMode mode, const InputState& input,
                                  bool look, double dt_s, double surface_distance,
                                  const CameraControls& controls) {
  CameraLow low;
  return update_camera(camera, low, mode, input, look, dt_s, surface_distance, controls);
}

// Wheel notches a frame of `input` zooms by: the wheel's, and ZoomIn/ZoomOut held (four a
// second).
double zoom_notches(const InputState& input, double dt_s);

}  // namespace fr
