// window.hpp — the explorer's window: SDL2 window and renderer, a streaming texture that shows
// the latest image scaled to the window, SDL events translated to InputEvents, and Dear ImGui
// (SDL2 + SDL_Renderer backends) for the overlay. Owns all of SDL; nothing else includes it.
#pragma once

#include "app/input.hpp"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct SDL_Window;
struct SDL_Renderer;
struct SDL_Texture;

namespace fr {

struct FrameView;

class Window {
 public:
  // Opens a resizable window; throws std::runtime_error (with SDL's reason) when there is no
  // display or SDL cannot start.
  Window(const std::string& title, int width_px, int height_px, bool fullscreen);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Folds pending SDL events into `input` (key repeats ignored; keys typed into the overlay go to
  // the overlay). With `keys_to_overlay` every key press goes to the overlay alone (a modal
  // panel such as the scene browser: Escape closes it rather than quitting).
  void poll(const KeyBindings& bindings, InputState& input, bool keys_to_overlay = false);

  // Uploads a new image (null: keep showing the last one), draws it over the whole window, then
  // the overlay that `draw_overlay` builds with ImGui calls, and presents.
  void present(const FrameView* image, const std::function<void()>& draw_overlay);

  void set_fullscreen(bool on);
  bool fullscreen() const { return fullscreen_; }
  void set_mouse_capture(bool on);
  int width_px() const;
  int height_px() const;

  // Asks the next present() to keep a copy of what it draws (image and overlay), RGBA8, rows top
  // to bottom, returned by captured().
  void capture_next_frame() { capture_ = true; }
  // A texture of an RGBA picture for the overlay's ImGui::Image (an SDL_Texture*), made the
  // first time `key` is asked for and kept until the window closes; null if SDL cannot make it.
  void* picture_texture(const std::string& key, int width_px, int height_px,
                        const uint8_t* rgba8);
  // Where the overlay sees the pointer in the next frames, in window pixels, whatever the system
  // says, until cleared with std::nullopt. For tests under a virtual X server, which moves the
  // pointer in its own time and, now and then under load, never into a newly shown window.
  void place_overlay_pointer(std::optional<std::array<float, 2>> at_px) {
    overlay_pointer_px_ = at_px;
  }
  const std::vector<uint8_t>& captured(int* width_px, int* height_px) const {
    *width_px = captured_w_;
    *height_px = captured_h_;
    return captured_;
  }

 private:
  // The image pixel under window point (x, y) (the window's points may differ from its pixels on
  // a high-density display); false when the window has no size.
  bool image_pixel(int x, int y, int* px, int* py) const;

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  std::map<std::string, SDL_Texture*> pictures_;  // picture_texture's, by key
  int texture_w_ = 0, texture_h_ = 0;
  bool fullscreen_ = false;
  bool imgui_ready_ = false;
  bool capture_ = false;
  std::optional<std::array<float, 2>> overlay_pointer_px_;
  float ui_scale_ = 0;  // the overlay scale the ImGui style and font have now
  std::vector<uint8_t> captured_;
  int captured_w_ = 0, captured_h_ = 0;
};

// The overlay's scale (text, spacing, widgets) for a window `height_px` tall on a display of
// `dpi` dots per inch (0: unknown): 1 at 720 pixels and 96 dpi, growing with either, so that the
// panel is as tall a share of a 4K window as of a 720p one and as large physically on a dense
// display; 1 to 4.
float overlay_scale(int height_px, float dpi);

}  // namespace fr
