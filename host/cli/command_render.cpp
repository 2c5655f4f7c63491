#include "cli/commands.hpp"
#include "cli/scene_setup.hpp"
#include "image/png_write.hpp"
#include "render/renderer.hpp"

#include <chrono>
#include <filesystem>
#include <ostream>

namespace fr {

int command_render(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto specs = scene_option_specs();
  specs.push_back({"out", "FILE", false, "PNG file to write (default fractalis.png)"});
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("render", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis render [--scene ID] [--size WxH] [--out FILE] [options]\n\n"
           "Renders one frame of a scene and writes it as a PNG (atomically: a temporary file,\n"
           "then a rename).\n\n"
        << format_options(specs) << "\nexample:\n"
        << "  fractalis render --scene mandelbulb --size 1280x720 --param power=6 --out bulb.png\n";
    return 0;
  }
  const std::string out_file = options.get("out").value_or("fractalis.png");
  if (out_file.empty()) throw UsageError("--out: empty file name");
  // Checked before rendering, so a typo in the folder costs nothing.
  const std::filesystem::path out_dir = std::filesystem::path(out_file).parent_path();
  std::error_code ec;
  if (!out_dir.empty() && !std::filesystem::is_directory(out_dir, ec))
    throw UsageError("--out: folder '" + out_dir.string() + "' does not exist");
  PreparedScene p = prepare_scene(options, err);

  std::string error;
  if (!p.instance->update(p.state, p.state.time_s, &error)) {
    err << "fractalis: error: " << error << "\n";
    return 1;
  }
  ClRuntime runtime(p.device);
  Renderer renderer(runtime);
  const auto start = std::chrono::steady_clock::now();
  FrameImage image = renderer.render(p.scene->info, p.state, p.render);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!write_png_atomic(out_file, image.width_px, image.height_px, image.rgba8, &error)) {
    err << "fractalis: error: " << error << "\n";
    return 1;
  }
  out << "rendered " << p.scene->info.id << " " << image.width_px << "x" << image.height_px
      << " on " << p.device.name << " (lanes " << image.lanes << ", "
      << (p.render.precision == Precision::Double ? "double" : "float") << ") in "
      << static_cast<int>(ms) << " ms including kernel build; wrote " << out_file << "\n";
  return 0;
}

}  // namespace fr
