// scene_browser_view.hpp — drawing the scene browser (app/scene_browser.hpp) with Dear ImGui: a
// search field that has the keyboard, a grid of pictures with name, family and description (a
// failed file or picture in red with why), the selection framed. Typing searches; the arrows
// move the selection (up and down by a row); Enter or a click opens; Escape closes. Call between
// ImGui::NewFrame and ImGui::Render (Window::present does).
#pragma once

#include "app/scene_browser.hpp"
#include "ui/overlay.hpp"
#include "ui/window.hpp"

#include <array>
#include <string>
#include <vector>

namespace fr {

struct BrowserViewState {
  std::array<char, 256> query{};
  int scrolled_to = -1;  // the selection the view last scrolled to
  // What the last draw laid out, for the tests: each shown entry's cell (named by its scene id,
  // "--" and its preset id for a preset), and the columns of the grid.
  std::vector<DrawnControl> cells;
  int columns = 1;
  std::string message;  // why the last open failed, shown until the next one
};

// Draws the browser over the window when it is visible; opens what the user picks.
void draw_scene_browser(SceneBrowser& browser, Explorer& explorer, Window& window,
                        BrowserViewState& view);

}  // namespace fr
