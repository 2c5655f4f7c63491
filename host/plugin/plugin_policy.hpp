// plugin_policy.hpp — how the host treats scene plugins: where their code runs, how long each of
// their calls may take, and which files it agrees to load. From the [plugins] settings.
#pragma once

#include "io/enum_names.hpp"

namespace fr {

enum class PluginIsolation {
  Process,  // default: plugin code runs only in scene-host processes (scene_host_process.hpp)
  None,     // dlopen in the host itself: for debugging a plugin under gdb; a crash ends the host
};
inline constexpr EnumName<PluginIsolation> kPluginIsolationNames[] = {
    {PluginIsolation::Process, "process", "own process", nullptr},
    {PluginIsolation::None, "none", "none (in fractalis)", nullptr},
};
constexpr std::span<const EnumName<PluginIsolation>> enum_names(PluginIsolation) {
  return kPluginIsolationNames;
}

struct PluginPolicy {
  PluginIsolation isolation = PluginIsolation::Process;
  double load_timeout_s = 10;   // loading the library (its constructors) and copying its descriptor
  double call_timeout_s = 2;    // one create, update or destroy call
  bool allow_writable = false;  // load from folders and files that other users can write to
  double vet_timeout_s = 60;    // the explorer's test render of a new or rebuilt scene
};

}  // namespace fr
