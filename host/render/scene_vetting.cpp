#include "render/scene_vetting.hpp"

#include "io/build_paths.hpp"
#include "io/cache_dirs.hpp"
#include "io/fnv1a.hpp"
#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "platform/files.hpp"
#include "platform/user_folders.hpp"
#include "plugin/plugin_files.hpp"
#include "plugin/scan_cache.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <vector>

namespace fr {

std::filesystem::path fractalis_executable() {
  const std::filesystem::path self = executable_path();
  if (self.filename() == "fractalis" || self.filename() == "fractalis.exe") return self;
  return build_paths::fractalis;
}

VetResult vet_scene(const std::filesystem::path& file, const RenderSettings& settings,
                    const std::string& device, const PluginPolicy& policy,
                    const std::atomic<bool>* cancel) {
  const double timeout_s = policy.vet_timeout_s;
  VetResult result;
  std::vector<std::string> args = {"vet-scene",
                                   "--file",
                                   file.string(),
                                   "--size",
                                   "8x8",
                                   "--lanes",
                                   std::to_string(settings.lanes),
                                   "--precision",
                                   precision_name(settings.precision)};
  if (!device.empty()) args.insert(args.end(), {"--device", device});
  if (settings.lanes == 0) args.erase(args.begin() + 5, args.begin() + 7);
  const auto set = [&](const char* key, double value) {
    std::ostringstream text;
    text << key << "=" << value;
    args.insert(args.end(), {"--set", text.str()});
  };
  set("plugins.build_timeout_s", policy.build_timeout_s);
  set("plugins.vet_render_timeout_s", policy.vet_render_timeout_s);
  set("plugins.worker_memory_mib", policy.worker_memory_mib);
  ChannelPair said_pipe;
  std::string error;
  if (!make_pipe(&said_pipe, &error)) {
    result.error = "cannot start the test render: " + error;
    return result;
  }
  ChildSpec spec;
  spec.program = fractalis_executable();
  spec.arguments = args;
  spec.stderr_to = said_pipe.theirs.handle();
  const std::unique_ptr<ChildProcess> child = ChildProcess::start(spec, &error);
  said_pipe.theirs.close();
  if (!child) {
    result.error = "cannot start the test render: " + error;
    return result;
  }
  // Collect what it says (bounded) until it closes stderr or the time is up.
  std::string said;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(timeout_s));
  bool timed_out = false;
  bool cancelled = false;
  // (Waits of at most 100 ms, so that a cancel is seen.)
  constexpr double kCancelCheckMs = 100;
  for (;;) {
    if (cancel && cancel->load()) {
      cancelled = true;
      break;
    }
    const double left_ms =
        std::chrono::duration<double, std::milli>(deadline - std::chrono::steady_clock::now())
            .count();
    if (left_ms <= 0) {
      timed_out = true;
      break;
    }
    char buffer[1024];
    size_t got = 0;
    const ChannelStatus s =
        said_pipe.ours.read_some(buffer, sizeof buffer,
                                 static_cast<int>(std::ceil(std::min(left_ms, kCancelCheckMs))),
                                 &got);
    if (s == ChannelStatus::TimedOut) continue;
    if (s != ChannelStatus::Ok) break;
    if (said.size() < 4096) said.append(buffer, got);
  }
  said_pipe.ours.close();
  if (timed_out || cancelled)
    child->kill();
  else
    child->wait(-1);
  if (cancelled) {
    result.cancelled = true;
    result.error = "the test render was cancelled";
    return result;
  }
  if (timed_out) {
    result.timed_out = true;
    std::ostringstream why;
    why << "a test render at 8x8 did not finish within " << timeout_s
        << " s (plugins.vet_timeout_s): its DE may never return";
    result.error = why.str();
    return result;
  }
  if (child->exit_status() == 0) {
    result.ok = true;
    return result;
  }
  // The render outlasted plugins.vet_render_timeout_s in the child (the watchdog's status).
  // (3: cli/watchdog.hpp's kWatchdogExitStatus, the status of every time limit; cli/ is a floor
  // above this one.)
  result.timed_out = child->exit_status() == 3;
  // The child's last line is its error ("fractalis: error: ...").
  while (!said.empty() && said.back() == '\n') said.pop_back();
  const size_t line = said.rfind('\n');
  std::string last = line == std::string::npos ? said : said.substr(line + 1);
  if (last.rfind("fractalis: error: ", 0) == 0) last = last.substr(18);
  // The caller names the scene and its file; the child's error may name them too.
  if (last.rfind("scene '", 0) == 0)
    if (const size_t named = last.find("): "); named != std::string::npos)
      last = last.substr(named + 3);
  if (child->exit_status() < 0)
    result.error = "the test render " + child->how_it_ended();
  else
    result.error = "the test render failed: " + (last.empty() ? "no reason given" : last);
  return result;
}

uint64_t VettedScenes::content_hash(const std::filesystem::path& file) {
  std::string error;
  const ReadableFile opened = open_plugin_file(file, true, &error);  // regular files only
  std::string bytes;
  if (!opened.valid() || !opened.read_all(kMaxPluginFileBytes, &bytes, &error)) return 0;
  return fnv1a(bytes, kFnv1aOffset);
}

namespace {
std::filesystem::path marker(uint64_t hash, const RenderSettings& s) {
  const auto base = fractalis_cache_dir();
  if (base.empty()) return {};
  char name[96];
  std::snprintf(name, sizeof name, "%016llx-lanes%d-%s", static_cast<unsigned long long>(hash),
                s.lanes, precision_name(s.precision));
  return base / "vetted" / name;
}
}  // namespace

bool VettedScenes::contains(uint64_t hash, const RenderSettings& s) const {
  if (hash == 0) return false;
  if (vetted_.count({hash, s.lanes, static_cast<int>(s.precision)}) > 0) return true;
  const auto file = marker(hash, s);
  std::error_code ec;
  return !file.empty() && std::filesystem::is_regular_file(file, ec);
}

void VettedScenes::insert(uint64_t hash, const RenderSettings& s) {
  if (hash == 0) return;
  vetted_.insert({hash, s.lanes, static_cast<int>(s.precision)});
  const auto file = marker(hash, s);
  if (file.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  std::filesystem::permissions(file.parent_path(), std::filesystem::perms::owner_all, ec);
  // An empty marker, created new (never through a link someone put there); one that is there
  // already says the same.
  bool exists = false;
  std::string error;
  WritableFile::create_new(file, &exists, &error);
}

VetResult vet_scene_once(const std::filesystem::path& file, const RenderSettings& settings,
                         const std::string& device, const PluginPolicy& policy) {
  VettedScenes vetted;
  const uint64_t hash = VettedScenes::content_hash(file);
  if (vetted.contains(hash, settings)) {
    VetResult known;
    known.ok = true;
    return known;
  }
  VetResult vet = vet_scene(file, settings, device, policy);
  if (vet.ok) vetted.insert(hash, settings);
  return vet;
}

}  // namespace fr
