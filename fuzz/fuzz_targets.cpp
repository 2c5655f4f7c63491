#include "fuzz_targets.hpp"

#include "cli/cli.hpp"
#include "cli/options.hpp"
#include "plugin/scene_checks.hpp"
#include "plugin/scene_wire.hpp"
#include "settings/settings.hpp"

#include <sstream>
#include <string>
#include <vector>

namespace fr {

int fuzz_settings_file(const uint8_t* data, size_t size) {
  Settings settings;
  const auto problems =
      load_settings_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz", settings);
  for (const auto& p : problems) (void)p.to_string();
  return 0;
}

int fuzz_set_override(const uint8_t* data, size_t size) {
  Settings settings;
  const auto problems =
      apply_setting_override(std::string(reinterpret_cast<const char*>(data), size), settings);
  for (const auto& p : problems) (void)p.to_string();
  return 0;
}

int fuzz_command_line(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  // The public commands; "--help" is added last, so each stops after checking its options and
  // never renders, opens a window or writes a file.
  static const char* const kCommands[] = {"render",  "bench", "sweep", "list",
                                          "devices", "check", "cache", "explore"};
  std::vector<std::string> args = {kCommands[data[0] % std::size(kCommands)]};
  std::string current;
  for (size_t i = 1; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  args.push_back(current);
  for (std::string& a : args) {
    // --log-file opens its file before the command runs: keep the fuzzer from writing files.
    if (a.rfind("--log-file", 0) == 0) a = "--log-fil";
    // Each argument through the value parsers too.
    try {
      parse_size("--size", a);
    } catch (const UsageError&) {
    }
    try {
      parse_vec3("--eye", a);
    } catch (const UsageError&) {
    }
    try {
      parse_integer("--frames", a, 1, 1000000);
    } catch (const UsageError&) {
    }
  }
  args.push_back("--help");
  std::ostringstream out, err;
  run_cli(args, out, err);
  return 0;
}

int fuzz_scene_descriptor(const uint8_t* data, size_t size) {
  WireReader reader(std::string_view(reinterpret_cast<const char*>(data), size));
  SceneInfo info;
  if (read_scene_info(reader, &info)) {
    (void)check_scene_info(info);
    for (size_t i = 0; i < info.params.size(); ++i) (void)check_param_info(info.params[i], i);
  }
  return 0;
}

}  // namespace fr
