// game_loop.hpp — the frame loop in its fixed order: poll input, update the scene,
// render. The steps are functions, so tests drive the loop with injected events and a fake clock
// and check the order; the explorer passes its window and renderer.
#pragma once

#include "app/input.hpp"

#include <cstdint>
#include <functional>

namespace fr {

struct LoopSteps {
  std::function<void(InputState&)> poll;  // fold pending events into the state
  std::function<void(const InputState&, double dt_s)> update;
  // Renders and presents; returns whether the window showed a frame of the scene (or of what
  // stands in for it: the browser, a scene's error, a parked view's last picture), as against a
  // notice that the scene is still being prepared. Only those count as frames.
  std::function<bool()> render;
  std::function<double()> now_s;  // a monotonic clock, seconds
};

// Runs until the input asks to quit (or once max_frames frames were shown, when max_frames >= 0).
// Returns the number of frames shown.
int64_t run_game_loop(const LoopSteps& steps, int64_t max_frames = -1);

}  // namespace fr
