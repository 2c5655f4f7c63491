#include "cli/commands.hpp"
#include "cli/scene_setup.hpp"
#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace fr {

int command_bench(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto specs = scene_option_specs();
  specs.push_back({"frames", "N", false, "timed frames after one warm-up frame (default 20)"});
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("bench", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis bench [--scene ID] [--size WxH] [--frames N] [options]\n\n"
           "Renders N frames (update, render, tonemap, read back) after one untimed warm-up\n"
           "frame that builds the kernel, and prints the median, min and max frame time.\n\n"
        << format_options(specs)
        << "\nexample:\n  fractalis bench --scene mandelbulb --size 640x360 --lanes 16\n";
    return 0;
  }
  const int frames =
      static_cast<int>(parse_integer("--frames", options.get("frames").value_or("20"), 1, 100000));
  PreparedScene p = prepare_scene(options, err);
  ClRuntime runtime(p.device);
  Renderer renderer(runtime);
  std::string error;

  std::vector<double> frame_ms;
  double mean_steps = 0, hit_fraction = 0;
  for (int i = -1; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    // Fixed 60 Hz scene time, so every run renders the same frames.
    if (!p.instance->update(p.state, std::max(i, 0) / 60.0, &error)) {
      err << "fractalis: error: " << error << "\n";
      return 1;
    }
    // The warm-up frame also reads back the step and depth buffers for the statistics.
    FrameImage image = renderer.render(p.scene->info, p.state, p.render, i < 0);
    if (i < 0) {
      for (size_t k = 0; k < image.steps.size(); ++k) {
        mean_steps += image.steps[k];
        hit_fraction += std::isfinite(image.depth[k]) ? 1 : 0;
      }
      mean_steps /= static_cast<double>(image.steps.size());
      hit_fraction /= static_cast<double>(image.steps.size());
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (i >= 0) frame_ms.push_back(ms);
  }
  std::sort(frame_ms.begin(), frame_ms.end());
  const size_t n = frame_ms.size();
  const double median = n % 2 ? frame_ms[n / 2] : 0.5 * (frame_ms[n / 2 - 1] + frame_ms[n / 2]);
  char line[256];
  std::snprintf(line, sizeof line, "median %.2f ms, min %.2f ms, max %.2f ms over %zu frames\n",
                median, frame_ms.front(), frame_ms.back(), n);
  out << "scene " << p.scene->info.id << ", " << p.render.width_px << "x" << p.render.height_px
      << ", " << (p.render.precision == Precision::Double ? "double" : "float") << ", lanes "
      << renderer.lanes_for(p.render) << "\n"
      << "device " << p.device.name << " (" << p.device.platform_name << ", " << p.device.version
      << ")\n"
      << line;
  std::snprintf(line, sizeof line,
                "primary ray: %.1f DE steps per pixel on average, %.1f%% of pixels hit\n",
                mean_steps, 100 * hit_fraction);
  out << line;
  return 0;
}

}  // namespace fr
