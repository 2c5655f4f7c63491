// `fractalis gallery --out DIR`: every scene and every preset rendered into DIR at one size, and
// an index.html contact sheet beside them that opens in a browser without a server (names,
// families, descriptions, credits; what failed, with why).
#include "cli/commands.hpp"
#include "cli/prepared_scene.hpp"
#include "cli/progress.hpp"
#include "cli/scene_options.hpp"
#include "image/png_write.hpp"
#include "io/atomic_file.hpp"
#include "io/echo.hpp"

#include <algorithm>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace fr {
namespace {

struct GalleryItem {
  std::string scene_id, preset_id;  // preset_id empty: the scene's defaults
  std::string title, family, description, credit;
  std::string file;   // the picture's name in DIR
  std::string error;  // why it has no picture, or ""
};

// A contact sheet: the pictures in rows of `columns`, in order, on a dark ground with a 4-pixel
// gap (a failed picture's cell stays empty).
struct Sheet {
  int columns = 0, cell_w = 0, cell_h = 0, width = 0, height = 0;
  std::vector<uint8_t> rgba8;
  Sheet(int count, int columns_, int w, int h)
      : columns(columns_), cell_w(w), cell_h(h), width(columns_ * (w + 4) + 4),
        height(((count + columns_ - 1) / columns_) * (h + 4) + 4),
        rgba8(static_cast<size_t>(width) * static_cast<size_t>(height) * 4, 28) {
    for (size_t i = 3; i < rgba8.size(); i += 4) rgba8[i] = 255;
  }
  void place(int index, const FrameImage& image) {
    const int x0 = 4 + (index % columns) * (cell_w + 4), y0 = 4 + (index / columns) * (cell_h + 4);
    for (int y = 0; y < std::min(cell_h, image.height_px); ++y)
      std::copy_n(&image.rgba8[static_cast<size_t>(y) * static_cast<size_t>(image.width_px) * 4],
                  static_cast<size_t>(std::min(cell_w, image.width_px)) * 4,
                  &rgba8[(static_cast<size_t>(y0 + y) * static_cast<size_t>(width) +
                          static_cast<size_t>(x0)) * 4]);
  }
};

std::string html(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string index_html(const std::vector<GalleryItem>& items, const std::string& size) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
         "<title>Fractalis gallery</title>\n<style>\n"
         "body{font-family:sans-serif;background:#1c1c1e;color:#ddd;margin:1.5em}\n"
         "main{display:grid;grid-template-columns:repeat(auto-fill,minmax(300px,1fr));gap:1em}\n"
         "figure{margin:0;background:#2a2a2e;border-radius:6px;overflow:hidden}\n"
         "img{width:100%;display:block}figcaption{padding:.5em .7em;font-size:.85em}\n"
         "small{color:#999}.failed{color:#f88}code{color:#9cf}\n</style></head><body>\n"
      << "<h1>Fractalis gallery</h1>\n<p>" << items.size() << " pictures at " << html(size)
      << ", each the scene's default view or a preset's. Open one with <code>fractalis explore "
         "--scene ID</code> or <code>--preset NAME</code>.</p>\n<main>\n";
  for (const GalleryItem& item : items) {
    out << "<figure>";
    if (item.error.empty())
      out << "<img src=\"" << html(item.file) << "\" alt=\"" << html(item.title)
          << "\" loading=\"lazy\">";
    out << "<figcaption><b>" << html(item.title) << "</b> <small>" << html(item.family)
        << "</small><br><code>"
        << html(item.preset_id.empty() ? "--scene " + item.scene_id : "--preset " + item.preset_id)
        << "</code><br>" << html(item.description);
    if (!item.credit.empty()) out << "<br><small>" << html(item.credit) << "</small>";
    if (!item.error.empty()) out << "<br><span class=\"failed\">failed: " << html(item.error) << "</span>";
    out << "</figcaption></figure>\n";
  }
  out << "</main></body></html>\n";
  return out.str();
}

}  // namespace

int command_gallery(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  auto specs = plugin_option_specs();
  const std::vector<OptionSpec> more = {
      {"out", "DIR", false, "folder for the pictures and index.html (made if missing)"},
      {"size", "WxH", false, "picture size in pixels (default 480x270)"},
      {"tag", "TAG", true, "only scenes with this tag (and their presets)"},
      {"no-presets", nullptr, false, "scenes at their defaults only"},
      {"sheet", "FILE.png", false, "also one PNG of every picture in a grid (README's gallery)"},
      {"columns", "N", false, "pictures per row of the sheet (default 8)"},
      {"samples", "N", false, "jittered samples per pixel (anti-aliasing; default 1)"},
      {"set", "KEY=VALUE", true, "any setting, as in config/default.toml (repeatable)"},
      {"device", "SEL", false, "OpenCL device: gpu, cpu, P:D or part of its name"},
      {"help", nullptr, false, "show this help"},
  };
  specs.insert(specs.end(), more.begin(), more.end());
  auto options = parse_options("gallery", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis gallery --out DIR [--size WxH] [--tag TAG] [--no-presets] "
           "[--sheet FILE.png]\n\n"
           "Renders every scene at its default view and every preset into DIR (ID.png,\n"
           "ID--PRESET.png), then writes DIR/index.html, a contact sheet with each picture's\n"
           "name, family, description and credit that opens in a browser without a server.\n"
           "A scene that fails is listed with why; the exit status is then 1.\n\n"
        << format_options(specs);
    return 0;
  }
  const auto dir_option = options.get("out");
  if (!dir_option || dir_option->empty()) throw UsageError("--out DIR is required");
  const std::filesystem::path dir = *dir_option;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir, ec))
    throw UsageError("--out " + echo(dir.string()) + ": cannot make that folder");
  if (!options.has("size")) options.values["size"] = {"480x270"};
  const auto sheet_file = options.get("sheet");
  if (sheet_file) check_output_file("--sheet", *sheet_file);
  const int columns =
      static_cast<int>(parse_integer("--columns", options.get("columns").value_or("8"), 1, 64));
  const std::string size = *options.get("size");
  const std::vector<std::string> tags =
      options.values.count("tag") ? options.values.at("tag") : std::vector<std::string>{};

  const Settings settings = load_settings(options);
  const auto folders = plugin_folders(settings, options);
  if (folders.empty())
    throw std::runtime_error("no plugin folder found (build the plugins, or pass --plugins DIR)");
  std::vector<PresetProblem> preset_problems;
  const std::vector<Preset> presets = load_presets(folders, &preset_problems);
  std::vector<GalleryItem> items;
  for (const auto& o : load_plugins(folders, settings.plugins)) {
    if (!o.scene) continue;
    const SceneInfo& s = o.scene->info;
    const std::vector<std::string> own = scene_tags(s);
    bool wanted = true;
    for (const std::string& t : tags) wanted = wanted && std::count(own.begin(), own.end(), t);
    if (!wanted) continue;
    const std::string family = own.empty() ? "" : own.front();
    items.push_back({s.id, "", s.name, family, s.description, s.credit, s.id + ".png", ""});
    if (options.has("no-presets")) continue;
    for (const Preset& p : presets)
      if (p.scene_id == s.id)
        items.push_back({s.id, p.id, s.name + ": " + p.name, family, p.description, s.credit,
                         s.id + "--" + p.id + ".png", ""});
  }
  // By family, then as found (the loader sorts by file name).
  std::stable_sort(items.begin(), items.end(),
                   [](const GalleryItem& a, const GalleryItem& b) { return a.family < b.family; });

  const auto wh = parse_size("--size", size, kMaxImageSide);
  std::optional<Sheet> sheet;
  if (sheet_file) sheet.emplace(static_cast<int>(items.size()), columns, wh[0], wh[1]);
  Progress progress(err, "picture", static_cast<int>(items.size()));
  bool any_failed = false;
  for (size_t i = 0; i < items.size(); ++i) {
    GalleryItem& item = items[i];
    ParsedOptions one = options;
    for (const char* own_option : {"out", "tag", "no-presets", "sheet", "columns"})
      one.values.erase(own_option);
    one.values["scene"] = {item.scene_id};
    if (!item.preset_id.empty()) one.values["preset"] = {item.preset_id};
    try {
      PreparedScene p = prepare_scene(one);
      update_scene(p, 0);
      p.worker->prepare(p.scene->info, p.state, p.render);
      const FrameImage image = p.worker->render(p.scene->info, p.state, p.render, true);
      std::string error;
      if (!write_png_atomic(dir / item.file, image.width_px, image.height_px, image.rgba8, &error))
        throw std::runtime_error(error);
      if (sheet) sheet->place(static_cast<int>(i), image);
    } catch (const std::exception& e) {
      item.error = e.what();
      any_failed = true;
    }
    progress.update(static_cast<int>(i + 1), item.preset_id.empty() ? item.scene_id : item.preset_id);
  }
  progress.finish();
  std::string error;
  if (!write_file_atomic(dir / "index.html", index_html(items, size), &error))
    throw std::runtime_error(error);
  if (sheet &&
      !write_png_atomic(*sheet_file, sheet->width, sheet->height, sheet->rgba8, &error))
    throw std::runtime_error(error);
  size_t failed = 0;
  for (const GalleryItem& item : items) failed += !item.error.empty();
  out << "wrote " << items.size() - failed << " pictures and " << (dir / "index.html").string();
  if (failed) out << "; " << failed << " failed (listed there)";
  out << "\n";
  return any_failed ? 1 : 0;
}

}  // namespace fr
