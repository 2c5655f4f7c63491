#include "app/input.hpp"

#include <algorithm>

namespace fr {
bool InputState::was_triggered(Action a) const {
  return std::find(triggered.begin(), triggered.end(), a) != triggered.end();
}

void InputState::end_frame() {
  triggered.clear();
  look_dx = look_dy = wheel = 0;
  resized.reset();
  clicked.reset();
}

void apply_input_event(const KeyBindings& bindings, const InputEvent& e, InputState& s) {
  switch (e.type) {
    case InputEvent::Type::Quit:
      s.quit = true;
      return;
    case InputEvent::Type::MouseMotion:
      s.look_dx += e.dx;
      s.look_dy += e.dy;
      if (e.pointer) s.pointer = std::make_pair(e.x, e.y);
      return;
    case InputEvent::Type::MouseWheel:
      s.wheel += e.dy;
      if (e.pointer) s.pointer = std::make_pair(e.x, e.y);
      return;
    case InputEvent::Type::MouseClick:
      s.clicked = std::make_pair(e.x, e.y);
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
