// plugin_policy.hpp — how the host treats scene plugins: where their code runs (their C code in
// scene-host processes, their OpenCL code in the render worker), how long each of their calls may
// take, and which files it agrees to load. From the [plugins] settings.
#pragma once

#include "io/enum_names.hpp"

namespace fr {

enum class PluginIsolation {
  Process,  // default: plugin code runs only in scene-host processes (scene_host_process.hpp),
            // its kernels in the render worker (worker/render_worker.hpp)
  None,     // both in the host itself: for debugging a plugin under gdb; a crash ends the host
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
  // That test's render alone, its kernel build not counted (build_timeout_s has that): a DE that
  // never returns is said in seconds, not at vet_timeout_s.
  double vet_render_timeout_s = 10;
  // The render worker (worker/render_worker.hpp), which compiles and runs scene kernels:
  // One kernel build: the in-tree scenes' take under 1 s here, cold; a preprocessor bomb ends here.
  double build_timeout_s = 20;
  double worker_memory_mib = 4096;  // its resident memory
  // The explorer's first sample of a scene; later samples may take 20 times the slowest time per
  // pixel the scene has needed so far, and at least 5 s (worker/frame_limit.hpp).
  double frame_limit_s = 30;
};

}  // namespace fr
