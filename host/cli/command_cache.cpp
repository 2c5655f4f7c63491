#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/scene_options.hpp"
#include "io/cache_dirs.hpp"
#include "render/kernel_cache.hpp"
#include "render/memory_budget.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <ostream>
#include <stdexcept>

namespace fr {

int command_cache(const std::vector<std::string>& args, std::ostream& out,
                  std::ostream& /*err: messages go to spdlog*/) {
  std::vector<OptionSpec> specs = {
      {"clear", nullptr, false, "remove everything in fractalis's cache folders"},
      {"config", "FILE", false, "settings file (for cache.kernel_cache_mib)"},
      {"set", "KEY=VALUE", true, "any setting, as in config/default.toml (repeatable)"},
      {"help", nullptr, false, "show this help"},
  };
  auto options = parse_options("cache", args, specs);
  if (options.has("help")) {
    out << "usage: fractalis cache [--clear]\n\nLists fractalis's cache folders with their sizes "
           "(compiled kernels, plugin scans, vetted\nscenes, sweep references); --clear empties "
           "them. Everything there is rebuilt when needed.\n\n"
        << format_options(specs);
    return 0;
  }
  const Settings settings = load_settings(options);
  const auto base = fractalis_cache_dir();
  if (base.empty()) {
    throw std::runtime_error(
        "no cache folder: the system names none (XDG_CACHE_HOME and HOME unset; on Windows "
        "LOCALAPPDATA)");
  }
  const char* pocl = std::getenv("POCL_CACHE_DIR");
  // main() set POCL_CACHE_DIR to ours unless the user had set it: then the kernels are theirs.
  const bool kernels_are_ours = kernel_cache_is_ours();
  out << "cache folder: " << base.string() << "\n";
  int failures = 0;
  for (const CacheFolder& folder : cache_folders()) {
    const auto dir = base / folder.name;
    const bool theirs = std::string(folder.name) == "kernels" && !kernels_are_ours;
    if (options.has("clear") && !theirs) {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
      if (ec) {
        spdlog::error("cannot clear {}: {}", dir.string(), ec.message());
        ++failures;
      }
    }
    out << "  " << folder.name << "  " << format_bytes(folder_bytes(dir)) << "  "
        << folder.description;
    if (std::string(folder.name) == "kernels")
      out << " (at most " << settings.cache.kernel_cache_mib << " MiB)";
    out << "\n";
  }
  if (!kernels_are_ours)
    out << "compiled kernels are in POCL_CACHE_DIR=" << (pocl ? pocl : "")
        << ", which you set: not fractalis's to clear or bound\n";
  if (options.has("clear") && failures == 0) out << "cleared\n";
  return failures == 0 ? 0 : 1;
}

}  // namespace fr
