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
  std::function<void()> render;
  std::function<double()> now_s;  // a monotonic clock, seconds
};

// Runs until the input asks to quit (or after max_frames when that is >= 0). Returns the number
// of frames run.
int64_t run_game_loop(const LoopSteps& steps, int64_t max_frames = -1);

}  // namespace fr
