// key_bindings.hpp — the explorer's actions and the keys bound to them: plain data the settings
// file configures ([controls.keys]) and the explorer (app/input.hpp) and overlay read.
#pragma once

#include "io/enum_names.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fr {

enum class Action {
  MoveForward,
  MoveBack,
  MoveLeft,
  MoveRight,
  MoveUp,
  MoveDown,
  ZoomIn,            // held: towards the surface under the pointer (deep zoom)
  ZoomOut,           // held: away from it
  SpeedUp,           // held: faster
  ToggleMouseLook,   // capture or release the pointer
  ToggleCameraMode,  // fly <-> orbit
  ToggleOverlay,
  ToggleFullscreen,
  NextScene,
  PreviousScene,
  ToggleBrowser,  // the scene browser (ui/scene_browser_view.hpp)
  Screenshot,
  AddKeyframe,  // the view on screen becomes the camera path's next keyframe
  PlayPath,     // play the camera path from its start, or stop it
  Quit,
};

// The names key bindings use in settings files ([controls.keys] action = "key name").
inline constexpr EnumName<Action> kActionNames[] = {
    {Action::MoveForward, "move_forward", "move forward", nullptr},
    {Action::MoveBack, "move_back", "move back", nullptr},
    {Action::MoveLeft, "move_left", "move left", nullptr},
    {Action::MoveRight, "move_right", "move right", nullptr},
    {Action::MoveUp, "move_up", "move up", nullptr},
    {Action::MoveDown, "move_down", "move down", nullptr},
    {Action::ZoomIn, "zoom_in", "zoom in (held)", nullptr},
    {Action::ZoomOut, "zoom_out", "zoom out (held)", nullptr},
    {Action::SpeedUp, "speed_up", "faster (held)", nullptr},
    {Action::ToggleMouseLook, "mouse_look", "mouse look", nullptr},
    {Action::ToggleCameraMode, "camera_mode", "fly / orbit", nullptr},
    {Action::ToggleOverlay, "overlay", "overlay", nullptr},
    {Action::ToggleFullscreen, "fullscreen", "fullscreen", nullptr},
    {Action::NextScene, "next_scene", "next scene", nullptr},
    {Action::PreviousScene, "previous_scene", "previous scene", nullptr},
    {Action::ToggleBrowser, "browser", "scene browser", nullptr},
    {Action::Screenshot, "screenshot", "screenshot", nullptr},
    {Action::AddKeyframe, "add_keyframe", "add keyframe", nullptr},
    {Action::PlayPath, "play_path", "play / stop path", nullptr},
    {Action::Quit, "quit", "quit", nullptr},
};
constexpr std::span<const EnumName<Action>> enum_names(Action) {
  return kActionNames;
}

inline const char* action_name(Action action) {
  return enum_name(action);
}
inline std::optional<Action> action_from_name(const std::string& name) {
  return enum_from_name<Action>(name);
}
// Held actions last while their key is down; the others trigger once per press.
constexpr bool action_is_held(Action a) {
  return a <= Action::SpeedUp;
}

// Key name -> action. Several keys may share an action.
struct KeyBindings {
  std::map<std::string, Action> keys;
  // The explorer's default keys: the one list of them (the settings file's comment, the README's
  // table (checked by tests/explorer_core_test.cpp) and the overlay's labels come from here).
  static KeyBindings defaults();
  // The defaults with `extra` (key name -> action name, [controls.keys]) added; unknown action
  // names are skipped (the settings loader has reported them).
  static KeyBindings with_extra(const std::map<std::string, std::string>& extra);
  // The keys bound to `action`, in key-name order.
  std::vector<std::string> keys_for(Action action) const;
  // The keys bound to `action` for a label: "F12", "E/Space"; "unbound" when none.
  std::string label(Action action) const;
};

}  // namespace fr
