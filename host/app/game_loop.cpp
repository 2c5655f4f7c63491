#include "app/game_loop.hpp"

namespace fr {

int64_t run_game_loop(const LoopSteps& steps, int64_t max_frames) {
  InputState input;
  double last = steps.now_s();
  int64_t frames = 0;
  while (max_frames < 0 || frames < max_frames) {
    steps.poll(input);
    if (input.quit) break;
    const double now = steps.now_s();
    steps.update(input, now - last);
    last = now;
    const bool shown = steps.render();
    input.end_frame();
    frames += shown;
  }
  return frames;
}

}  // namespace fr
