#include "app/input.hpp"

#include <algorithm>

namespace fr {
KeyBindings KeyBindings::defaults() {
  KeyBindings b;
  b.keys = {
      {"W", Action::MoveForward},
      {"S", Action::MoveBack},
      {"A", Action::MoveLeft},
      {"D", Action::MoveRight},
      {"E", Action::MoveUp},
      {"Space", Action::MoveUp},
      {"Q", Action::MoveDown},
      {"Left Ctrl", Action::MoveDown},
      {"Left Shift", Action::SpeedUp},
      {"M", Action::ToggleMouseLook},
      {"O", Action::ToggleCameraMode},
      {"F1", Action::ToggleOverlay},
      {"F11", Action::ToggleFullscreen},
      {"Tab", Action::NextScene},
      {"Backspace", Action::PreviousScene},
      {"F12", Action::Screenshot},
      {"K", Action::AddKeyframe},
      {"P", Action::PlayPath},
      {"Escape", Action::Quit},
  };
  return b;
}

std::vector<std::string> KeyBindings::keys_for(Action action) const {
  std::vector<std::string> out;
  for (const auto& [key, a] : keys)
    if (a == action) out.push_back(key);
  return out;
}

bool InputState::was_triggered(Action a) const {
  return std::find(triggered.begin(), triggered.end(), a) != triggered.end();
}

void InputState::end_frame() {
  triggered.clear();
  look_dx = look_dy = wheel = 0;
  resized.reset();
}

void apply_input_event(const KeyBindings& bindings, const InputEvent& e, InputState& s) {
  switch (e.type) {
    case InputEvent::Type::Quit:
      s.quit = true;
      return;
    case InputEvent::Type::MouseMotion:
      s.look_dx += e.dx;
      s.look_dy += e.dy;
      return;
    case InputEvent::Type::MouseWheel:
      s.wheel += e.dy;
      return;
    case InputEvent::Type::WindowResized:
      s.resized = std::make_pair(e.width, e.height);
      return;
    case InputEvent::Type::KeyDown:
    case InputEvent::Type::KeyUp: {
      auto it = bindings.keys.find(e.key);
      if (it == bindings.keys.end()) return;
      const bool down = e.type == InputEvent::Type::KeyDown;
      if (action_is_held(it->second)) {
        if (down)
          s.held.insert(it->second);
        else
          s.held.erase(it->second);
      } else if (down) {
        s.triggered.push_back(it->second);
        if (it->second == Action::Quit) s.quit = true;
      }
      return;
    }
  }
}

}  // namespace fr
