// scene_host_process.hpp — plugin code in a process of its own.
//
// `dlopen` runs a library's constructors before anything can check it, and a scene's callbacks
// are native code, so the host never runs either itself (unless plugins.isolation = "none"). A
// scene-host process (the fractalis-scene-host executable) loads one plugin from a descriptor
// the host opened, sends back a checked copy of its descriptor, then serves create, update and
// destroy calls over a socket. Every wait has a time limit; a process that crashes, hangs or sends
// garbage is killed and reaped, and the calls it owed fail with the reason.
//
// Processes are started only from the main thread (the one that runs the game loop or the
// command): the scene host asks the kernel to kill it when that thread ends.
#pragma once

#include "platform/channel.hpp"
#include "platform/child_process.hpp"
#include "plugin/plugin_files.hpp"
#include "plugin/plugin_loader.hpp"
#include "plugin/plugin_policy.hpp"
#include "plugin/scene_code.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace fr {

// The scene-host executable: $FRACTALIS_SCENE_HOST, else beside the running executable (or in
// ../libexec/fractalis/ from it), else the build tree's. Empty when none exists.
std::filesystem::path scene_host_executable();

class SceneHostProcess {
 public:
  // Starts a scene host on the plugin `plugin` (open_plugin_file; the host hands it a handle of
  // its own); `file` names it in messages. Returns null and sets *error when no process could be
  // started.
  static std::unique_ptr<SceneHostProcess> start(const ReadableFile& plugin,
                                                 const std::filesystem::path& file,
                                                 std::string* error);
  ~SceneHostProcess();  // asks it to quit, kills it if it does not, and reaps it
  SceneHostProcess(const SceneHostProcess&) = delete;
  SceneHostProcess& operator=(const SceneHostProcess&) = delete;

  // Sends one request and waits at most `timeout_s` for the answer. On failure the process is
  // gone (killed and reaped) and *error says why ("crashed (SIGSEGV)", "did not answer within
  // 2 s"); every later call fails the same way.
  bool call(WireKind kind, const std::string& request, double timeout_s, std::string* reply,
            std::string* error);
  // Waits at most `timeout_s` for the first message, the load outcome; `limit_s` is the limit
  // the message names (the time the process has had in all).
  bool receive_loaded(double timeout_s, double limit_s, std::string* payload, std::string* error);

  int64_t pid() const { return process_->id(); }
  bool alive() const { return !gone_; }

 private:
  SceneHostProcess(std::unique_ptr<ChildProcess> process, Channel channel)
      : process_(std::move(process)), channel_(std::move(channel)) {}
  bool receive(double timeout_s, double limit_s, WireKind expected, std::string* payload,
               std::string* error);
  std::string stop(bool kill_now);  // ends and reaps the process; returns how it ended

  std::unique_ptr<ChildProcess> process_;
  Channel channel_;
  bool gone_ = false;
  std::string failure_;
};

// Loads each file in a scene-host process of its own, several at once, each within
// policy.load_timeout_s. The scenes' callbacks later run in processes of their own (started on
// first use).
std::vector<LoadOutcome> load_isolated(const std::vector<std::filesystem::path>& files,
                                       const PluginPolicy& policy);

// The scene-host side: what fractalis-scene-host runs. Loads the plugin `plugin` (the
// handle fractalis handed over; closed once its bytes are read), answers on `channel` until told to
// quit or the host goes away. Returns the exit status.
int run_scene_host(Channel& channel, ReadableFile plugin, const std::string& file);

}  // namespace fr
