#include "render/scene_vetting.hpp"

#include "io/cache_dirs.hpp"
#include "io/child_process.hpp"
#include "io/fnv1a.hpp"
#include "plugin/plugin_files.hpp"
#include "plugin/scan_cache.hpp"
#include "platform/user_folders.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

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
  return FRACTALIS_EXECUTABLE_BUILD_PATH;
}

VetResult vet_scene(const std::filesystem::path& file, const RenderSettings& settings,
                    const std::string& device, const PluginPolicy& policy) {
  const double timeout_s = policy.vet_timeout_s;
  VetResult result;
  const std::string exe = fractalis_executable().string();
  std::vector<std::string> args = {exe,           "vet-scene",
                                   "--file",      file.string(),
                                   "--size",      "8x8",
                                   "--lanes",     std::to_string(settings.lanes),
                                   "--precision", precision_name(settings.precision)};
  if (!device.empty()) args.insert(args.end(), {"--device", device});
  if (settings.lanes == 0) args.erase(args.begin() + 6, args.begin() + 8);
  const auto set = [&](const char* key, double value) {
    std::ostringstream text;
    text << key << "=" << value;
    args.insert(args.end(), {"--set", text.str()});
  };
  set("plugins.build_timeout_s", policy.build_timeout_s);
  set("plugins.worker_memory_mib", policy.worker_memory_mib);
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    result.error = std::string("cannot start the test render: ") + std::strerror(errno);
    return result;
  }
  std::string error;
  const pid_t pid = start_child_process(args, {}, pipe_fds[1], &error);
  if (pid < 0) {
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    result.error = "cannot start the test render: " + error;
    return result;
  }
  close(pipe_fds[1]);
  // Collect what it says (bounded) until it closes stderr or the time is up.
  std::string said;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(timeout_s));
  bool timed_out = false;
  for (;;) {
    const double left_ms =
        std::chrono::duration<double, std::milli>(deadline - std::chrono::steady_clock::now())
            .count();
    if (left_ms <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{pipe_fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::ceil(left_ms)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buffer[1024];
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (said.size() < 4096) said.append(buffer, static_cast<size_t>(n));
  }
  close(pipe_fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) {
    result.timed_out = true;
    std::ostringstream why;
    why << "a test render at 8x8 did not finish within " << timeout_s
        << " s (plugins.vet_timeout_s): its DE may never return";
    result.error = why.str();
    return result;
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    result.ok = true;
    return result;
  }
  // The child's last line is its error ("fractalis: error: ...").
  while (!said.empty() && said.back() == '\n') said.pop_back();
  const size_t line = said.rfind('\n');
  std::string last = line == std::string::npos ? said : said.substr(line + 1);
  if (last.rfind("fractalis: error: ", 0) == 0) last = last.substr(18);
  // The caller names the scene and its file; the child's error may name them too.
  if (last.rfind("scene '", 0) == 0)
    if (const size_t named = last.find("): "); named != std::string::npos)
      last = last.substr(named + 3);
  if (WIFSIGNALED(status))
    result.error = "the test render " + describe_child_exit(status);
  else
    result.error = "the test render failed: " + (last.empty() ? "no reason given" : last);
  return result;
}

uint64_t VettedScenes::content_hash(const std::filesystem::path& file) {
  std::string error;
  const int fd = open_plugin_file(file, true, &error);  // never blocks, regular files only
  if (fd < 0) return 0;
  uint64_t h = kFnv1aOffset;
  char buffer[1 << 16];
  ssize_t n;
  while ((n = read(fd, buffer, sizeof buffer)) > 0)
    h = fnv1a(std::string_view(buffer, static_cast<size_t>(n)), h);
  close(fd);
  return n < 0 ? 0 : h;
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
  const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd >= 0) close(fd);
}

VetResult vet_scene_once(const std::filesystem::path& file, const RenderSettings& settings,
                         const std::string& device, const PluginPolicy& policy) {
  VettedScenes vetted;
  const uint64_t hash = VettedScenes::content_hash(file);
  if (vetted.contains(hash, settings)) return {true, false, ""};
  VetResult vet = vet_scene(file, settings, device, policy);
  if (vet.ok) vetted.insert(hash, settings);
  return vet;
}

}  // namespace fr
