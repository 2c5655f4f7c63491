#include "ui/window.hpp"

#include "render/renderer.hpp"

#include <SDL.h>
#include <backends/imgui_impl_sdl.h>
#include <backends/imgui_impl_sdlrenderer.h>
#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace fr {

Window::Window(const std::string& title, int w, int h, bool fullscreen) {
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0)
    throw std::runtime_error(std::string("cannot start SDL video: ") + SDL_GetError());
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w, h,
                             SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (!window_) {
    std::string why = SDL_GetError();
    SDL_Quit();
    throw std::runtime_error("cannot open a window: " + why);
  }
  renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED);
  if (!renderer_) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  if (!renderer_) {
    std::string why = SDL_GetError();
    SDL_DestroyWindow(window_);
    SDL_Quit();
    throw std::runtime_error("cannot create a renderer for the window: " + why);
  }
  SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "linear");
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename =
      nullptr;  // the explorer's settings live in config.toml, not imgui.ini
  ImGui::StyleColorsDark();
  ImGui_ImplSDL2_InitForSDLRenderer(window_);
  ImGui_ImplSDLRenderer_Init(renderer_);
  imgui_ready_ = true;
  if (fullscreen) set_fullscreen(true);
}

Window::~Window() {
  if (imgui_ready_) {
    ImGui_ImplSDLRenderer_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
  }
  if (texture_) SDL_DestroyTexture(texture_);
  for (auto& [key, picture] : pictures_) SDL_DestroyTexture(picture);
  if (renderer_) SDL_DestroyRenderer(renderer_);
  if (window_) SDL_DestroyWindow(window_);
  SDL_Quit();
}

int Window::width_px() const {
  int w = 0, h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  return w;
}

int Window::height_px() const {
  int w = 0, h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  return h;
}

void* Window::picture_texture(const std::string& key, int width_px, int height_px,
                              const uint8_t* rgba8) {
  if (const auto it = pictures_.find(key); it != pictures_.end()) return it->second;
  SDL_Texture* picture = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ABGR8888,
                                           SDL_TEXTUREACCESS_STATIC, width_px, height_px);
  if (!picture) return nullptr;
  SDL_UpdateTexture(picture, nullptr, rgba8, width_px * 4);
  pictures_[key] = picture;
  return picture;
}

bool Window::image_pixel(int x, int y, int* px, int* py) const {
  int points_w = 0, points_h = 0;
  SDL_GetWindowSize(window_, &points_w, &points_h);
  if (points_w <= 0 || points_h <= 0) return false;
  *px = static_cast<int>(static_cast<long long>(x) * width_px() / points_w);
  *py = static_cast<int>(static_cast<long long>(y) * height_px() / points_h);
  return true;
}

void Window::set_fullscreen(bool on) {
  SDL_SetWindowFullscreen(window_, on ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
  fullscreen_ = on;
}

void Window::set_mouse_capture(bool on) {
  SDL_SetRelativeMouseMode(on ? SDL_TRUE : SDL_FALSE);
}

void Window::poll(const KeyBindings& bindings, InputState& input, bool keys_to_overlay) {
  SDL_Event e;
  while (SDL_PollEvent(&e)) {
    ImGui_ImplSDL2_ProcessEvent(&e);
    const bool overlay_keys = keys_to_overlay || ImGui::GetIO().WantCaptureKeyboard;
    const bool overlay_mouse = ImGui::GetIO().WantCaptureMouse && !SDL_GetRelativeMouseMode();
    InputEvent ev;
    switch (e.type) {
      case SDL_QUIT:
        ev.type = InputEvent::Type::Quit;
        break;
      case SDL_WINDOWEVENT:
        if (e.window.event == SDL_WINDOWEVENT_CLOSE)
          ev.type = InputEvent::Type::Quit;
        else if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
          ev.type = InputEvent::Type::WindowResized;
          ev.width = e.window.data1;
          ev.height = e.window.data2;
        } else
          continue;
        break;
      case SDL_KEYDOWN:
      case SDL_KEYUP:
        if (e.key.repeat || (overlay_keys && e.type == SDL_KEYDOWN)) continue;
        ev.type = e.type == SDL_KEYDOWN ? InputEvent::Type::KeyDown : InputEvent::Type::KeyUp;
        ev.key = SDL_GetKeyName(e.key.keysym.sym);
        break;
      case SDL_MOUSEMOTION:
        if (overlay_mouse) continue;
        ev.type = InputEvent::Type::MouseMotion;
        ev.dx = e.motion.xrel;
        ev.dy = e.motion.yrel;
        ev.pointer = image_pixel(e.motion.x, e.motion.y, &ev.x, &ev.y);
        break;
      case SDL_MOUSEWHEEL: {
        if (overlay_mouse) continue;
        ev.type = InputEvent::Type::MouseWheel;
        ev.dy = e.wheel.y;
        int x = 0, y = 0;
        SDL_GetMouseState(&x, &y);
        ev.pointer = image_pixel(x, y, &ev.x, &ev.y);
        break;
      }
      case SDL_MOUSEBUTTONDOWN: {
        // A left click on the picture (not the overlay's, not while the mouse looks around):
        // the pixel under it, in the image's pixels (the window's points may differ on a
        // high-density display).
        if (overlay_mouse || SDL_GetRelativeMouseMode() || e.button.button != SDL_BUTTON_LEFT)
          continue;
        ev.type = InputEvent::Type::MouseClick;
        if (!image_pixel(e.button.x, e.button.y, &ev.x, &ev.y)) continue;
        break;
      }
      default:
        continue;
    }
    apply_input_event(bindings, ev, input);
  }
}

void Window::present(const FrameView* image, const std::function<void()>& draw_overlay) {
  if (image && image->rgba8 && image->pixel_count() > 0) {
    if (!texture_ || texture_w_ != image->width_px || texture_h_ != image->height_px) {
      if (texture_) SDL_DestroyTexture(texture_);
      texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_STREAMING,
                                   image->width_px, image->height_px);
      texture_w_ = image->width_px;
      texture_h_ = image->height_px;
    }
    SDL_UpdateTexture(texture_, nullptr, image->rgba8, image->width_px * 4);
  }
  // The overlay follows the window's size and the display's density.
  float dpi = 0;
  if (SDL_GetDisplayDPI(SDL_GetWindowDisplayIndex(window_), &dpi, nullptr, nullptr) != 0) dpi = 0;
  const float scale = overlay_scale(height_px(), dpi);
  if (scale != ui_scale_) {
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    style.ScaleAllSizes(scale);
    ImGui::GetStyle() = style;
    ImGui::GetIO().FontGlobalScale = scale;
    ui_scale_ = scale;
  }
  ImGui_ImplSDLRenderer_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  if (overlay_pointer_px_)
    ImGui::GetIO().MousePos = ImVec2((*overlay_pointer_px_)[0], (*overlay_pointer_px_)[1]);
  ImGui::NewFrame();
  if (draw_overlay) draw_overlay();
  ImGui::Render();
  SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
  SDL_RenderClear(renderer_);
  if (texture_) SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
  ImGui_ImplSDLRenderer_RenderDrawData(ImGui::GetDrawData());
  if (capture_) {
    captured_w_ = width_px();
    captured_h_ = height_px();
    captured_.resize(static_cast<size_t>(captured_w_) * captured_h_ * 4);
    SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_ABGR8888, captured_.data(),
                         captured_w_ * 4);
    capture_ = false;
  }
  SDL_RenderPresent(renderer_);
}

float overlay_scale(int height_px, float dpi) {
  const float by_size = static_cast<float>(height_px) / 720.0f;
  const float by_density = dpi > 0 ? dpi / 96.0f : 1.0f;
  return std::clamp(std::max(by_size, by_density), 1.0f, 4.0f);
}

}  // namespace fr
