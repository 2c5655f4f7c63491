// input.hpp — from device events to actions. The window layer translates SDL events into
// InputEvents (so tests can inject them), and key bindings map key names to actions.
#pragma once

#include "io/enum_names.hpp"

#include <map>
#include <optional>
#include <set>
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
  SpeedUp,           // held: faster
  ToggleMouseLook,   // capture or release the pointer
  ToggleCameraMode,  // fly <-> orbit
  ToggleOverlay,
  ToggleFullscreen,
  NextScene,
  PreviousScene,
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
    {Action::SpeedUp, "speed_up", "faster (held)", nullptr},
    {Action::ToggleMouseLook, "mouse_look", "mouse look", nullptr},
    {Action::ToggleCameraMode, "camera_mode", "fly / orbit", nullptr},
    {Action::ToggleOverlay, "overlay", "overlay", nullptr},
    {Action::ToggleFullscreen, "fullscreen", "fullscreen", nullptr},
    {Action::NextScene, "next_scene", "next scene", nullptr},
    {Action::PreviousScene, "previous_scene", "previous scene", nullptr},
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

struct InputEvent {
  enum class Type { KeyDown, KeyUp, MouseMotion, MouseWheel, WindowResized, Quit };
  Type type = Type::KeyDown;
  std::string key;            // SDL key name ("W", "Left Shift", "Escape") for key events
  double dx = 0, dy = 0;      // pixels (motion) or notches (wheel)
  int width = 0, height = 0;  // for WindowResized
};

// Key name -> action. Several keys may share an action.
struct KeyBindings {
  std::map<std::string, Action> keys;
  static KeyBindings defaults();
  // The keys bound to `action`, for help texts.
  std::vector<std::string> keys_for(Action action) const;
};

// What the user is doing this frame, from the events so far.
struct InputState {
  std::set<Action> held;            // movement keys currently down
  std::vector<Action> triggered;    // one-shot actions pressed since the last frame
  double look_dx = 0, look_dy = 0;  // mouse movement since the last frame, pixels
  double wheel = 0;                 // wheel notches since the last frame
  bool quit = false;
  std::optional<std::pair<int, int>> resized;

  bool is_held(Action a) const { return held.count(a) != 0; }
  bool was_triggered(Action a) const;
  // Clears what lasts one frame (triggers, mouse deltas), keeps what is held.
  void end_frame();
};

// Folds one event into the state. Held actions are the movement ones; the rest trigger once per
// key press (auto-repeat presses are ignored by the window layer).
void apply_input_event(const KeyBindings& bindings, const InputEvent& event, InputState& state);

}  // namespace fr
