// input.hpp — from device events to actions. The window layer translates SDL events into
// InputEvents (so tests can inject them), and key bindings (settings/key_bindings.hpp) map key
// names to actions.
#pragma once

#include "settings/key_bindings.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fr {

struct InputEvent {
  enum class Type { KeyDown, KeyUp, MouseMotion, MouseWheel, MouseClick, WindowResized, Quit };
  Type type = Type::KeyDown;
  std::string key;            // SDL key name ("W", "Left Shift", "Escape") for key events
  double dx = 0, dy = 0;      // pixels (motion) or notches (wheel)
  int x = 0, y = 0;           // MouseClick: the image pixel under the pointer (0, 0: top left)
  bool pointer = false;       // MouseWheel, MouseMotion: x and y are the pointer's pixel
  int width = 0, height = 0;  // for WindowResized
};

// What the user is doing this frame, from the events so far.
struct InputState {
  std::set<Action> held;            // movement keys currently down
  std::vector<Action> triggered;    // one-shot actions pressed since the last frame
  double look_dx = 0, look_dy = 0;  // mouse movement since the last frame, pixels
  double wheel = 0;                 // wheel notches since the last frame
  bool quit = false;
  std::optional<std::pair<int, int>> resized;
  std::optional<std::pair<int, int>> clicked;  // the image pixel clicked since the last frame
  std::optional<std::pair<int, int>> pointer;  // the image pixel under the pointer, when known

  bool is_held(Action a) const { return held.count(a) != 0; }
  bool was_triggered(Action a) const;
  // Clears what lasts one frame (triggers, mouse deltas), keeps what is held.
  void end_frame();
};

// Folds one event into the state. Held actions are the movement ones; the rest trigger once per
// key press (auto-repeat presses are ignored by the window layer).
void apply_input_event(const KeyBindings& bindings, const InputEvent& event, InputState& state);

}  // namespace fr
