#include "settings/settings.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cstdlib>
#include <functional>

namespace fr {
namespace {

const char* const kKnownKeys[] = {
    "plugins.folders",        "device.select",          "render.lanes",    "render.precision",
    "render.max_steps",       "render.hit_threshold_k", "render.exposure", "render.ao_strength",
    "render.effects.shadows", "render.effects.ao",
};

size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

struct Reader {
  std::string file;
  std::vector<SettingsProblem> problems;

  void problem(const toml::node& node, const std::string& key, const std::string& message) {
    problems.push_back({file, static_cast<int>(node.source().begin.line), key, message});
  }

  // Walks every leaf, reporting keys that are not known.
  void check_keys(const toml::table& table, const std::string& prefix) {
    for (const auto& [k, node] : table) {
      const std::string key =
          prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
      if (const auto* sub = node.as_table()) {
        const bool is_prefix = std::any_of(
            std::begin(kKnownKeys), std::end(kKnownKeys),
            [&](const char* known) { return std::string(known).rfind(key + ".", 0) == 0; });
        if (is_prefix) {
          check_keys(*sub, key);
          continue;
        }
      }
      if (std::find(std::begin(kKnownKeys), std::end(kKnownKeys), key) == std::end(kKnownKeys))
        problem(node, key, "unknown key (did you mean '" + nearest_known_key(key) + "'?)");
    }
  }
};

}  // namespace

std::string SettingsProblem::to_string() const {
  return file + ":" + std::to_string(line) + ": " + (key.empty() ? "" : "key '" + key + "': ") +
         message;
}

std::string nearest_known_key(const std::string& key) {
  std::string best;
  size_t best_d = ~size_t{0};
  for (const char* known : kKnownKeys) {
    size_t d = edit_distance(key, known);
    if (d < best_d) best_d = d, best = known;
  }
  return best;
}

std::optional<std::filesystem::path> user_settings_file() {
  std::filesystem::path base;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    base = xdg;
  else if (const char* home = std::getenv("HOME"); home && *home)
    base = std::filesystem::path(home) / ".config";
  else
    return std::nullopt;
  auto file = base / "fractalis" / "config.toml";
  std::error_code ec;
  if (std::filesystem::is_regular_file(file, ec)) return file;
  return std::nullopt;
}

std::vector<SettingsProblem> load_settings_file(const std::filesystem::path& file, Settings& s) {
  Reader r{file.string(), {}};
  toml::table root;
  try {
    root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    r.problems.push_back({file.string(), static_cast<int>(e.source().begin.line), "",
                          "not valid TOML: " + std::string(e.description())});
    return r.problems;
  }
  r.check_keys(root, "");

  auto with = [&](const char* key, auto&& apply) {
    const toml::node* node = root.at_path(key).node();
    if (node) apply(*node);
  };
  with("plugins.folders", [&](const toml::node& n) {
    const auto* arr = n.as_array();
    if (!arr) return r.problem(n, "plugins.folders", "expected an array of folder paths");
    std::vector<std::filesystem::path> folders;
    for (const auto& item : *arr) {
      if (!item.is_string())
        return r.problem(item, "plugins.folders", "expected a string (a folder path)");
      folders.emplace_back(item.as_string()->get());
    }
    s.plugin_folders = folders;
  });
  with("device.select", [&](const toml::node& n) {
    if (!n.is_string())
      return r.problem(n, "device.select",
                       "expected a string: \"\", \"gpu\", \"cpu\", \"P:D\" or part of a name");
    s.device = n.as_string()->get();
  });
  with("render.lanes", [&](const toml::node& n) {
    auto v = n.value<int64_t>();
    if (!n.is_integer() || !v || (*v != 0 && *v != 1 && *v != 4 && *v != 8 && *v != 16))
      return r.problem(n, "render.lanes", "expected one of 0 (device's choice), 1, 4, 8, 16");
    s.render.lanes = static_cast<int>(*v);
  });
  with("render.precision", [&](const toml::node& n) {
    auto v = n.value<std::string>();
    if (!n.is_string() || (*v != "float" && *v != "double"))
      return r.problem(n, "render.precision", "expected \"float\" or \"double\"");
    s.render.precision = *v == "double" ? Precision::Double : Precision::Float;
  });
  with("render.max_steps", [&](const toml::node& n) {
    auto v = n.value<int64_t>();
    if (!n.is_integer() || *v < 1 || *v > 10000)
      return r.problem(n, "render.max_steps", "expected an integer in [1, 10000]");
    s.render.max_steps = static_cast<int>(*v);
  });
  auto positive_float = [&](const char* key, float& out, double hi) {
    with(key, [&](const toml::node& n) {
      auto v = n.value<double>();
      if (!(n.is_number()) || !v || !(*v > 0 && *v <= hi))
        return r.problem(n, key, "expected a number in (0, " + std::to_string(hi) + "]");
      out = static_cast<float>(*v);
    });
  };
  positive_float("render.hit_threshold_k", s.render.hit_threshold_k, 100);
  positive_float("render.exposure", s.render.exposure, 100);
  positive_float("render.ao_strength", s.render.ao_strength, 100);
  auto effect = [&](const char* key, fr_features feature) {
    with(key, [&](const toml::node& n) {
      if (!n.is_boolean()) return r.problem(n, key, "expected true or false");
      if (*n.value<bool>())
        s.render.disabled_stages &= ~feature;
      else
        s.render.disabled_stages |= feature;
    });
  };
  effect("render.effects.shadows", FR_FEATURE_SHADOWS);
  effect("render.effects.ao", FR_FEATURE_AO);
  std::stable_sort(
      r.problems.begin(), r.problems.end(),
      [](const SettingsProblem& a, const SettingsProblem& b) { return a.line < b.line; });
  return r.problems;
}

}  // namespace fr
