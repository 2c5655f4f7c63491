#include "settings/key_bindings.hpp"

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
      {"Z", Action::ZoomIn},
      {"X", Action::ZoomOut},
      {"Left Shift", Action::SpeedUp},
      {"M", Action::ToggleMouseLook},
      {"O", Action::ToggleCameraMode},
      {"F1", Action::ToggleOverlay},
      {"F11", Action::ToggleFullscreen},
      {"Tab", Action::NextScene},
      {"Backspace", Action::PreviousScene},
      {"B", Action::ToggleBrowser},
      {"F12", Action::Screenshot},
      {"K", Action::AddKeyframe},
      {"P", Action::PlayPath},
      {"Escape", Action::Quit},
  };
  return b;
}

KeyBindings KeyBindings::with_extra(const std::map<std::string, std::string>& extra) {
  KeyBindings b = defaults();
  for (const auto& [key, action_name] : extra)
    if (auto action = action_from_name(action_name)) b.keys[key] = *action;
  return b;
}

std::vector<std::string> KeyBindings::keys_for(Action action) const {
  std::vector<std::string> out;
  for (const auto& [key, a] : keys)
    if (a == action) out.push_back(key);
  return out;
}

std::string KeyBindings::label(Action action) const {
  std::string out;
  for (const auto& key : keys_for(action)) out += (out.empty() ? "" : "/") + key;
  return out.empty() ? "unbound" : out;
}

}  // namespace fr
