// scene_vetting.hpp — a tiny test render of a new or rebuilt scene, in a child process.
//
// A DE that never returns hangs the OpenCL device, and nothing can cancel a running kernel. The
// explorer must not find that out by freezing, so before it first uses a scene (found at start
// or arriving by hot reload), `fractalis vet-scene` renders it at 8x8 in a child process with a
// time limit (plugins.vet_timeout_s). The child's kernel build also warms the OpenCL compiler's
// cache for the explorer's own build of the same kernel.
#pragma once

#include "plugin/plugin_policy.hpp"
#include "render/render_settings.hpp"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <tuple>

namespace fr {

struct VetResult {
  bool ok = false;
  bool timed_out = false;  // the test render did not finish within the limit
  bool cancelled = false;  // *cancel was set: the child was ended, nothing is known
  std::string error;       // why not: the child's error, "crashed (SIGSEGV)", or the time limit
};

// Renders `file`'s scene at 8x8 with `settings`' lanes and precision on the device `device`
// (a selector as for --device; "" for the default) in a `fractalis vet-scene` process, within
// policy.vet_timeout_s; the kernel compiles and runs in that process's render worker, under
// policy's build and memory limits. Setting *cancel (when given) from another thread ends the
// child within about 0.1 s (a result with `cancelled`), so a program that quits does not wait
// for test renders it no longer needs.
VetResult vet_scene(const std::filesystem::path& file, const RenderSettings& settings,
                    const std::string& device, const PluginPolicy& policy,
                    const std::atomic<bool>* cancel = nullptr);

// Scenes already vetted, by the content of their file and the kernel shape: a file that comes
// back with the same bytes (an undo, a rebuild that changed nothing, the next start of the
// explorer) is not vetted again. Kept in memory and, as empty marker files, in
// $XDG_CACHE_HOME/fractalis/vetted/.
class VettedScenes {
 public:
  // The key of `file` as it is now; 0 when it cannot be read.
  static uint64_t content_hash(const std::filesystem::path& file);
  bool contains(uint64_t hash, const RenderSettings& s) const;
  void insert(uint64_t hash, const RenderSettings& s);

 private:
  std::set<std::tuple<uint64_t, int, int>> vetted_;
};

// vet_scene for a command that renders one scene (`render`, `bench`, `animate`, `sweep`): once
// per file content and kernel shape, remembered in the same markers as the explorer's, so a DE
// that never returns fails in plugins.vet_timeout_s instead of after render.watchdog_s.
VetResult vet_scene_once(const std::filesystem::path& file, const RenderSettings& settings,
                         const std::string& device, const PluginPolicy& policy);

// The fractalis executable: this process when it is fractalis, else the build tree's.
std::filesystem::path fractalis_executable();

}  // namespace fr
