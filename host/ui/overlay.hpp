// overlay.hpp — the explorer's Dear ImGui panel, generated from the scene's parameter table:
// scene list, parameters (sliders with the declared ranges, log scale where flagged, colour
// pickers, checkboxes, vec3 fields, grouped), effects and shading model, camera and bookmarks,
// camera path (keyframes, playback, save and load), statistics, screenshot. Call between
// ImGui::NewFrame and ImGui::Render (Window::present does).
#pragma once

#include "app/explorer.hpp"

#include <array>
#include <string>
#include <vector>

namespace fr {

// Where a control was drawn: its frame (the label beside it excluded), window pixels.
struct DrawnControl {
  std::string name;
  float x_px = 0, y_px = 0, width_px = 0, height_px = 0;
};

// What the last draw_overlay laid out: the tests check from it that the panel is readable at
// every window size (text height, and no label cut by the panel's edge), and find the scene's
// parameter controls to drive them with the mouse as a user does.
struct OverlayLayout {
  float font_px = 0;  // height of a line of text, pixels
  float panel_width_px = 0, panel_height_px = 0;
  float content_width_px = 0;                // the widest row laid out (widget and label)
  float visible_width_px = 0;                // the panel's content area
  std::vector<DrawnControl> param_controls;  // the current scene's, named by parameter key
};

struct OverlayState {
  bool visible = true;
  bool expand_all = false;  // every section open (the tests' view of every label)
  OverlayLayout layout;
  std::vector<fr_camera> bookmarks;
  std::array<int, 2> screenshot_size{1920, 1080};
  // The screenshot's file: a PNG, or an OpenEXR file with its passes when named *.exr.
  std::array<char, 1024> screenshot_file{"fractalis-screenshot.png"};
  bool screenshot_requested = false;
  bool screenshot_at_window_size = true;
  std::array<char, 1024> path_file{"fractalis-path.toml"};  // the camera path's Save / Load file
  std::filesystem::path settings_file;  // where "Save settings" writes (the user's config.toml)
  KeyBindings keys = KeyBindings::defaults();  // in force: the labels name these keys
  // Edit mode (app/scene_edit.hpp): what the last saved change did, shown at the top; red when
  // it failed. Empty outside edit mode.
  std::string edit_status;
  bool edit_failed = false;
};

// Builds the panel; changes go straight into the explorer's scene state and settings (and mark
// the view changed).
void draw_overlay(Explorer& explorer, OverlayState& overlay);

}  // namespace fr
