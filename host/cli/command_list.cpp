#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "io/log.hpp"
#include "io/echo.hpp"
#include "io/printable.hpp"
#include "plugin/scene_instance.hpp"
#include "render/kernel_assembly.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <ostream>
#include <set>
#include <stdexcept>

namespace fr {
namespace {

std::string format_value(const ParamInfo& p, const fr_value& v) {
  auto num = [](double x) {
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  if (p.type == FR_PARAM_BOOL) return v.v[0] != 0 ? "true" : "false";
  if (p.type == FR_PARAM_CHOICE) return p.choice_name(v);
  if (p.component_count() == 1) return num(v.v[0]);
  return num(v.v[0]) + "," + num(v.v[1]) + "," + num(v.v[2]);
}

// What the scene's kernel contains with the current settings: the stages compiled in and left
// out, the DE library files it includes, and the parameters baked in as constants. This is
// "each scene's kernel contains only what it needs", made visible.
void describe_kernel(const SceneInfo& info, const RenderSettings& settings, std::ostream& out) {
  const int lanes = resolve_lanes(settings.lanes, nullptr, settings.precision);
  const KernelConfig config = make_kernel_config(info, settings, lanes);
  const AssembledKernel k = assemble_render_kernel(info, make_default_state(info).params, config);
  const fr_features all = all_optional_stages();
  out << "  kernel (lanes " << lanes << ", " << precision_name(config.precision) << "): stages "
      << stage_names(config.stages) << "; left out: " << stage_names(all & ~config.stages) << "\n";
  std::set<std::string> library;
  for (size_t at = k.source.find("#line 1 \"fr/"); at != std::string::npos;
       at = k.source.find("#line 1 \"fr/", at + 1)) {
    const size_t start = at + 9, end = k.source.find('"', start);
    library.insert(k.source.substr(start, end - start));
  }
  out << "  DE library files:";
  for (const auto& f : library) out << " " << f;
  out << (library.empty() ? " none\n" : "\n");
  out << "  baked in as constants:";
  bool any = false;
  for (const auto& p : info.params)
    if (p.specialized()) {
      out << " " << p.key << "=" << format_value(p, p.default_value);
      any = true;
    }
  out << (any ? "" : " none") << "; " << std::count(k.source.begin(), k.source.end(), '\n')
      << " lines of OpenCL C\n";
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text + ' ') {
    if (!std::isspace(static_cast<unsigned char>(c))) {
      word += c;
    } else if (!word.empty()) {
      words.push_back(lower(word));
      word.clear();
    }
  }
  return words;
}

// Whether a scene is one the filters ask for: it has every --tag, and every word of --search
// appears (case-insensitive, anywhere) in its id, name, description, tags, credit or author.
bool matches(const SceneInfo& s, const std::vector<std::string>& tags,
             const std::vector<std::string>& search_words) {
  const std::vector<std::string> own = scene_tags(s);
  for (const std::string& t : tags)
    if (std::find(own.begin(), own.end(), lower(t)) == own.end()) return false;
  const std::string haystack = lower(s.id + " " + s.name + " " + s.description + " " + s.tags +
                                     " " + s.credit + " " + s.author);
  for (const std::string& w : search_words)
    if (haystack.find(w) == std::string::npos) return false;
  return true;
}

nlohmann::json value_json(const ParamInfo& p, const fr_value& v) {
  if (p.type == FR_PARAM_BOOL) return v.v[0] != 0;
  if (p.type == FR_PARAM_CHOICE) return p.choice_name(v);
  if (p.type == FR_PARAM_INT) return static_cast<long long>(v.v[0]);
  if (p.component_count() == 1) return v.v[0];
  return nlohmann::json::array({v.v[0], v.v[1], v.v[2]});
}

// The effects a scene asks the renderer for, by name.
std::vector<std::string> effects_of(fr_features features) {
  std::vector<std::string> names;
  const std::pair<fr_features, const char*> known[] = {{FR_FEATURE_AO, "ao"},
                                                       {FR_FEATURE_SHADOWS, "shadows"},
                                                       {FR_FEATURE_GLOW, "glow"},
                                                       {FR_FEATURE_FOG, "fog"},
                                                       {FR_FEATURE_REFLECTIONS, "reflections"}};
  for (const auto& [bit, name] : known)
    if (features & bit) names.push_back(name);
  return names;
}

nlohmann::json scene_json(const SceneInfo& s, const std::filesystem::path& file) {
  nlohmann::json params = nlohmann::json::array();
  for (const ParamInfo& p : s.params) {
    params.push_back({{"key", p.key},
                      {"name", p.name},
                      {"group", p.group},
                      {"description", p.description},
                      {"type", param_type_name(p.type)},
                      {"default", value_json(p, p.default_value)},
                      {"min", value_json(p, p.min_value)},
                      {"max", value_json(p, p.max_value)},
                      {"compiled_in", p.specialized()},
                      {"animatable", (p.flags & FR_PARAM_ANIMATABLE) != 0}});
    if (p.type == FR_PARAM_CHOICE) params.back()["choices"] = p.choices;
  }
  const fr_camera& c = s.camera;
  return {{"id", s.id},
          {"name", s.name},
          {"version", s.version},
          {"file", file.string()},
          {"description", s.description},
          {"tags", scene_tags(s)},
          {"family", scene_tags(s).empty() ? "" : scene_tags(s).front()},
          {"credit", s.credit},
          {"author", s.author},
          {"license", s.license},
          {"bounding_radius", s.bounding_radius},
          {"effects", effects_of(s.features)},
          {"camera",
           {{"eye", {c.eye[0], c.eye[1], c.eye[2]}},
            {"target", {c.target[0], c.target[1], c.target[2]}},
            {"up", {c.up[0], c.up[1], c.up[2]}},
            {"fov_deg", c.fov_deg}}},
          {"params", params}};
}

}  // namespace

int command_list(const std::vector<std::string>& args, std::ostream& out,
                 std::ostream& /*err: messages go to spdlog*/) {
  auto specs = plugin_option_specs();
  specs.push_back({"tag", "TAG", true, "only scenes with this tag (a family: bulb, box, kifs, ...)"});
  specs.push_back({"search", "WORDS", false,
                   "only scenes whose id, name, description, tags or credit hold every word"});
  specs.push_back({"json", nullptr, false,
                   "print one JSON document: every scene with its parameters, tags and credit"});
  specs.push_back({"help", nullptr, false, "show this help"});
  auto options = parse_options("list", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis list [--tag TAG] [--search WORDS] [--json] [--plugins DIR] "
           "[--verbose]\n\nLists every scene plugin found: id, family and tags, credit, "
           "parameters with their ranges, presets, or why\nit failed to load. Exits 1 when a plugin "
           "or a preset failed to load. With --verbose (-v), also what each\nscene's kernel compiles in: "
           "stages, DE library files, parameters baked in as constants.\n\n"
        << format_options(specs);
    return 0;
  }
  const std::vector<std::string> tags =
      options.values.count("tag") ? options.values.at("tag") : std::vector<std::string>{};
  const std::vector<std::string> search_words = words_of(options.get("search").value_or(""));
  const bool json = options.has("json");
  const Settings settings = load_settings(options);
  const auto folders = plugin_folders(settings, options);
  if (folders.empty()) {
    throw std::runtime_error("no plugin folder found (build the plugins, or pass --plugins DIR)");
  }
  if (!json)
    for (const auto& f : folders) out << "plugin folder: " << f.string() << "\n";
  bool any_failed = false;
  size_t shown = 0;
  nlohmann::json doc = {{"scenes", nlohmann::json::array()},
                        {"failed", nlohmann::json::array()},
                        {"failed_presets", nlohmann::json::array()}};
  // Presets: each checked against its scene's table; one that does not fit (or whose scene is
  // missing) is reported as a failure, like a plugin that does not load.
  std::vector<PresetProblem> preset_problems;
  const std::vector<Preset> presets = load_presets(folders, &preset_problems);
  std::set<std::string> scene_ids;
  const auto outcomes = load_scene_folder(folders, settings.plugins);
  for (const auto& o : outcomes)
    if (o.scene) scene_ids.insert(o.scene->info.id);
  for (const Preset& preset : presets)
    if (!scene_ids.count(preset.scene_id))
      preset_problems.push_back({preset.file, preset.file.string() + ": preset '" + preset.id +
                                                  "' is for scene '" + echo(preset.scene_id) +
                                                  "', which is not there"});
  for (const auto& o : outcomes) {
    if (!o.scene) continue;
    for (const Preset& preset : presets) {
      if (preset.scene_id != o.scene->info.id) continue;
      SceneState state = make_default_state(o.scene->info);
      for (const std::string& problem : apply_preset(preset, o.scene->info, state))
        preset_problems.push_back({preset.file, problem});
    }
  }
  for (const auto& o : outcomes) {
    if (!o.scene) {
      any_failed = true;
      if (json) {
        doc["failed"].push_back({{"file", o.file.string()},
                                 {"result", load_result_name(o.result)},
                                 {"message", o.message}});
        continue;
      }
      out << "\n"
          << printable(o.file.filename().string()) << ": FAILED (" << load_result_name(o.result)
          << "): " << o.message << "\n";
      continue;
    }
    const SceneInfo& s = o.scene->info;
    if (!matches(s, tags, search_words)) continue;
    ++shown;
    nlohmann::json scene_presets = nlohmann::json::array();
    for (const Preset& preset : presets)
      if (preset.scene_id == s.id)
        scene_presets.push_back({{"id", preset.id},
                                 {"name", preset.name},
                                 {"description", preset.description},
                                 {"file", preset.file.string()}});
    if (json) {
      doc["scenes"].push_back(scene_json(s, o.file));
      doc["scenes"].back()["presets"] = scene_presets;
      continue;
    }
    out << "\n"
        << s.id << " " << s.version << " — " << s.name << "  (" << o.file.filename().string()
        << ")\n";
    if (!s.description.empty()) out << "  " << s.description << "\n";
    if (!s.tags.empty()) out << "  tags: " << s.tags << "\n";
    if (!s.credit.empty()) out << "  credit: " << s.credit << "\n";
    if (!s.author.empty() || !s.license.empty())
      out << "  by " << s.author << ", " << s.license << "\n";
    for (const auto& p : s.params) {
      std::string range = " in [";
      range += format_value(p, p.min_value);
      range += ", ";
      range += format_value(p, p.max_value);
      range += "]";
      if (p.type == FR_PARAM_CHOICE) {
        range = " of ";
        for (size_t c = 0; c < p.choices.size(); ++c) {
          if (c) range += "|";
          range += p.choices[c];
        }
      }
      out << "  --param " << p.key << "=" << format_value(p, p.default_value) << "  "
          << param_type_name(p.type) << range
          << (p.flags & FR_PARAM_SPECIALIZE ? ", compiled in" : "")
          << (p.flags & FR_PARAM_ANIMATABLE ? ", animatable" : "") << "  " << p.description << "\n";
    }
    for (const auto& preset : scene_presets)
      out << "  --preset " << preset["id"].get<std::string>() << "  "
          << preset["name"].get<std::string>()
          << (preset["description"].get<std::string>().empty() ? "" : ": ")
          << preset["description"].get<std::string>() << "\n";
    if (log_verbosity() == LogVerbosity::Verbose) describe_kernel(s, settings.render, out);
  }
  for (const PresetProblem& problem : preset_problems) {
    any_failed = true;
    if (json)
      doc["failed_presets"].push_back({{"file", problem.file.string()}, {"message", problem.message}});
    else
      out << "\npreset FAILED: " << printable(problem.message) << "\n";
  }
  if (json) {
    out << doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else if (shown == 0 && (!tags.empty() || !search_words.empty())) {
    out << "\nno scene matches";
    for (const std::string& t : tags) out << " --tag " << t;
    if (!search_words.empty()) out << " --search '" << options.get("search").value_or("") << "'";
    out << "\n";
  }
  // A plugin that did not load is a failure a script should see (the listing still shows the
  // rest).
  return any_failed ? 1 : 0;
}

}  // namespace fr
