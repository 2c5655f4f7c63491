#include "plugin/scene_host_process.hpp"

#include "io/build_paths.hpp"
#include "io/helper_executable.hpp"
#include "io/printable.hpp"
#include "plugin/scan_cache.hpp"
#include "plugin/scene_checks.hpp"
#include "plugin/wire_io.hpp"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

namespace fr {
namespace {

constexpr int kWireMismatchStatus = 126;

std::string describe_exit(const ChildProcess& process) {
  if (process.exit_status() == kWireMismatchStatus)
    return "is from another build of fractalis (message format differs)";
  return process.how_it_ended();
}

std::string seconds(double s) {
  std::ostringstream out;
  out << s << " s";
  return out.str();
}

// Messages in a reply: ok flag, error, plugin messages.
struct Reply {
  bool ok = false;
  std::string error;
  std::vector<PluginMessage> messages;
};
bool read_reply_head(WireReader& r, Reply* reply) {
  reply->ok = r.u32() != 0;
  reply->error = r.str(kMaxMessageBytes);
  return read_messages(r, &reply->messages) && !r.failed();
}

// Calls forwarded to a scene-host process, started on the first call that needs one.
class IsolatedCode final : public SceneCode {
 public:
  IsolatedCode(std::filesystem::path file, FileIdentity identity, std::string descriptor,
               uint32_t callbacks, const SceneInfo& info, PluginPolicy policy)
      : file_(std::move(file)),
        identity_(identity),
        descriptor_(std::move(descriptor)),
        callbacks_(callbacks),
        param_count_(info.params.size()),
        light_count_(info.lights.size()),
        policy_(policy) {}

  CallOutcome create(uint64_t* instance) override {
    if (callbacks_ == 0) {  // nothing to run: no process needed
      *instance = next_local_++;
      return {true, "", {}};
    }
    std::string reply;
    CallOutcome out = call(WireKind::Create, "", &reply);
    if (out.ok) {
      WireReader r(reply);
      *instance = r.u64();
      if (r.failed()) out = fail_process("sent a malformed reply to create");
    }
    return out;
  }

  CallOutcome update(uint64_t instance, SceneState& state) override {
    if (callbacks_ == 0) return {true, "", {}};
    WireWriter w;
    w.u64(instance);
    write_scene_state(w, state);
    std::string reply;
    CallOutcome out = call(WireKind::Update, w.bytes(), &reply);
    if (out.ok) {
      WireReader r(reply);
      SceneState updated;
      if (!read_scene_state(r, param_count_, light_count_, &updated))
        return fail_process("sent a malformed reply to update");
      // The host's counters stay the host's; the rest is what the plugin set.
      updated.time_s = state.time_s;
      updated.dt_s = state.dt_s;
      updated.frame_index = state.frame_index;
      state = std::move(updated);
    }
    return out;
  }

  std::optional<HostStats> host_stats(bool unload, std::string* error) override {
    std::string reply;
    const CallOutcome out = call(unload ? WireKind::Unload : WireKind::Stats, "", &reply);
    if (!out.ok) {
      *error = out.error;
      return std::nullopt;
    }
    WireReader r(reply);
    HostStats s;
    s.heap_bytes = r.u64();
    s.threads = r.u32();
    s.plugin_mappings = r.u32();
    if (r.failed()) {
      *error = fail_process("sent a malformed reply to stats").error;
      return std::nullopt;
    }
    return s;
  }

  void destroy(uint64_t instance) override {
    if (callbacks_ == 0 || !process_ || !process_->alive()) return;
    WireWriter w;
    w.u64(instance);
    std::string reply;
    call(WireKind::Destroy, w.bytes(), &reply);
  }

 private:
  CallOutcome fail_process(const std::string& why) {
    failure_ = "the scene host for " + printable(file_.string()) + " " + why;
    process_.reset();
    return {false, failure_, {}};
  }

  bool ensure_started(std::string* error) {
    if (process_) return true;
    const ReadableFile opened = open_plugin_file(file_, policy_.allow_writable, error);
    if (!opened.valid()) return false;
    if (!(opened.identity() == identity_)) {
      *error = printable(file_.string()) +
               " changed since it was loaded (it is reloaded once the "
               "change settles)";
      return false;
    }
    process_ = SceneHostProcess::start(opened, file_, error);
    if (!process_) return false;
    std::string loaded;
    if (!process_->receive_loaded(policy_.load_timeout_s, policy_.load_timeout_s, &loaded, error)) {
      process_.reset();
      *error = "while loading " + printable(file_.string()) + ", its scene host " + *error;
      return false;
    }
    if (loaded != descriptor_) {
      process_.reset();
      *error = printable(file_.string()) + " described itself differently when loaded again";
      return false;
    }
    return true;
  }

  CallOutcome call(WireKind kind, const std::string& request, std::string* payload) {
    if (!failure_.empty()) return {false, failure_, {}};
    std::string error;
    if (!ensure_started(&error)) {
      failure_ = error;
      return {false, failure_, {}};
    }
    std::string reply_bytes;
    if (!process_->call(kind, request, policy_.call_timeout_s, &reply_bytes, &error)) {
      failure_ = error;
      process_.reset();
      return {false, failure_, {}};
    }
    WireReader r(reply_bytes);
    Reply head;
    if (!read_reply_head(r, &head)) return fail_process("sent a malformed reply");
    payload->assign(r.rest());
    return {head.ok, head.error, std::move(head.messages)};
  }

  std::filesystem::path file_;
  FileIdentity identity_;
  std::string descriptor_;  // the Loaded message from the scan: a restarted host must match it
  uint32_t callbacks_;
  size_t param_count_, light_count_;
  PluginPolicy policy_;
  std::unique_ptr<SceneHostProcess> process_;
  std::string failure_;  // once set, every call fails with it (until the scene is reloaded)
  uint64_t next_local_ = 1;
};

// Reads a Loaded message: the outcome, and for a loaded scene its checked descriptor.
LoadOutcome parse_loaded(const std::filesystem::path& file, const std::string& payload,
                         uint32_t* callbacks) {
  LoadOutcome out;
  out.file = file;
  WireReader r(payload);
  const uint32_t result = r.u32();
  std::string message = r.str(kMaxMessageBytes);
  if (r.failed() || result > static_cast<uint32_t>(LoadResult::Crashed)) {
    out.result = LoadResult::Crashed;
    out.message = "its scene host sent a malformed description";
    return out;
  }
  out.result = static_cast<LoadResult>(result);
  out.message = printable(message);
  if (out.result != LoadResult::Loaded) return out;
  auto scene = std::make_shared<LoadedScene>();
  *callbacks = r.u32();
  if (!read_scene_info(r, &scene->info) || !r.at_end()) {
    out.result = LoadResult::Crashed;
    out.message = "its scene host sent a malformed description";
    return out;
  }
  // The scene host ran plugin code, so its copy is checked again here.
  if (auto problem = check_scene_info(scene->info)) {
    out.result = LoadResult::InvalidScene;
    out.message = *problem;
    return out;
  }
  scene->file = file;
  out.scene = std::move(scene);
  return out;
}

// A loaded scene's callbacks run in a scene-host process of their own, started on first use.
void attach_code(LoadOutcome& outcome, const FileIdentity& identity, const std::string& loaded,
                 uint32_t callbacks, const PluginPolicy& policy) {
  if (!outcome.scene) return;
  auto scene = std::const_pointer_cast<LoadedScene>(outcome.scene);
  scene->code = std::make_shared<IsolatedCode>(outcome.file, identity, loaded, callbacks,
                                               scene->info, policy);
}

}  // namespace

std::filesystem::path scene_host_executable() {
  return helper_executable("fractalis-scene-host", "FRACTALIS_SCENE_HOST",
                           build_paths::scene_host);
}

std::unique_ptr<SceneHostProcess> SceneHostProcess::start(const ReadableFile& plugin,
                                                          const std::filesystem::path& file,
                                                          std::string* error) {
  const std::filesystem::path exe = scene_host_executable();
  if (exe.empty()) {
    *error =
        "the scene-host executable fractalis-scene-host was not found (beside fractalis, in "
        "../libexec/fractalis, or $FRACTALIS_SCENE_HOST)";
    return nullptr;
  }
  ChannelPair channel;
  if (!make_channel_pair(&channel, error)) {
    *error = "cannot connect to the scene host: " + *error;
    return nullptr;
  }
  const bool keep_stderr = std::getenv("FRACTALIS_SCENE_HOST_STDERR") != nullptr;
  ChildSpec spec;
  spec.program = exe;
  spec.handles = {channel.theirs.handle(), plugin.handle()};
  spec.arguments = {"--wire",    std::to_string(kSceneWireVersion),
                    "--channel", handle_in_child(0, spec.handles[0]),
                    "--plugin",  handle_in_child(1, spec.handles[1]),
                    "--file",    file.string()};
  spec.stderr_to = keep_stderr ? own_stderr() : kNoHandle;
  std::unique_ptr<ChildProcess> process = ChildProcess::start(spec, error);
  if (!process) {
    *error = "cannot start the scene host: " + *error;
    return nullptr;
  }
  return std::unique_ptr<SceneHostProcess>(
      new SceneHostProcess(std::move(process), std::move(channel.ours)));
}

SceneHostProcess::~SceneHostProcess() {
  if (!gone_) {
    write_frame(channel_, WireKind::Quit, "");
    stop(false);
  }
}

std::string SceneHostProcess::stop(bool kill_now) {
  if (gone_) return failure_;
  channel_.close();
  gone_ = true;
  // A moment to exit by itself (after Quit, or when it crashed and its channel closed), so that
  // its status says how it ended; then it is killed.
  if (!kill_now && process_->wait(100)) return describe_exit(*process_);
  process_->kill();
  return "";
}

bool SceneHostProcess::receive(double timeout_s, double limit_s, WireKind expected,
                               std::string* payload, std::string* error) {
  if (gone_) {
    *error = failure_;
    return false;
  }
  WireKind kind{};
  const ReadStatus s = read_frame(channel_, timeout_s, &kind, payload);
  if (s == ReadStatus::Ok && kind == expected) return true;
  if (s == ReadStatus::TimedOut) {
    stop(true);
    failure_ = "did not answer within " + seconds(limit_s) + "; it was stopped";
  } else if (s == ReadStatus::Closed) {
    const std::string how = stop(false);
    failure_ = how.empty() ? "closed its connection" : how;
  } else {
    stop(true);
    failure_ = "sent a malformed message; it was stopped";
  }
  *error = failure_;
  return false;
}

bool SceneHostProcess::receive_loaded(double timeout_s, double limit_s, std::string* payload,
                                      std::string* error) {
  return receive(timeout_s, limit_s, WireKind::Loaded, payload, error);
}

bool SceneHostProcess::call(WireKind kind, const std::string& request, double timeout_s,
                            std::string* reply, std::string* error) {
  if (!gone_ && !write_frame(channel_, kind, request)) {
    const std::string how = stop(false);
    failure_ = how.empty() ? "closed its connection" : how;
  }
  if (receive(timeout_s, timeout_s, WireKind::Reply, reply, error)) return true;
  const char* what = kind == WireKind::Create    ? "create"
                     : kind == WireKind::Update  ? "update"
                     : kind == WireKind::Destroy ? "destroy"
                     : kind == WireKind::Unload  ? "unload"
                                                 : "a status request";
  *error = std::string("its scene host ") + *error + " during " + what;
  return false;
}

std::vector<LoadOutcome> load_isolated(const std::vector<std::filesystem::path>& files,
                                       const PluginPolicy& policy) {
  struct Pending {
    LoadOutcome outcome;
    FileIdentity identity;
    std::unique_ptr<SceneHostProcess> process;
    std::chrono::steady_clock::time_point started;
  };
  std::vector<LoadOutcome> outcomes;
  constexpr size_t kInFlight = 8;  // scans at once: they wait on the dynamic loader and the disk
  for (size_t first = 0; first < files.size(); first += kInFlight) {
    std::vector<Pending> batch;
    for (size_t i = first; i < std::min(files.size(), first + kInFlight); ++i) {
      Pending p;
      p.outcome.file = files[i];
      std::string error;
      const ReadableFile opened = open_plugin_file(files[i], policy.allow_writable, &error);
      p.identity = opened.identity();
      std::optional<std::string> kept;
      if (opened.valid() && (kept = find_scan(p.identity))) {
        uint32_t callbacks = 0;
        LoadOutcome cached = parse_loaded(files[i], *kept, &callbacks);
        // A damaged entry is scanned again, as is a load the system refused (kept by an
        // earlier version, which kept those).
        if (cached.result != LoadResult::Crashed && cached.result != LoadResult::NotLoadable) {
          attach_code(cached, p.identity, *kept, callbacks, policy);
          p.outcome = std::move(cached);
          batch.push_back(std::move(p));
          continue;
        }
      }
      if (!opened.valid()) {
        p.outcome.result = LoadResult::Refused;
        p.outcome.message = error;
      } else {
        p.process = SceneHostProcess::start(opened, files[i], &error);
        if (!p.process) {
          p.outcome.result = LoadResult::Crashed;
          p.outcome.message = error;
        }
      }
      p.started = std::chrono::steady_clock::now();
      batch.push_back(std::move(p));
    }
    for (Pending& p : batch) {
      if (p.process) {
        const double waited_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - p.started).count();
        std::string payload, error;
        if (!p.process->receive_loaded(std::max(0.0, policy.load_timeout_s - waited_s),
                                       policy.load_timeout_s, &payload, &error)) {
          p.outcome.result = LoadResult::Crashed;
          p.outcome.message = "while loading, its scene host " + error;
        } else {
          uint32_t callbacks = 0;
          p.outcome = parse_loaded(p.outcome.file, payload, &callbacks);
          attach_code(p.outcome, p.identity, payload, callbacks, policy);
          // Not kept: a crash or time-out, nor a library the system could not load (what it
          // lacked, a DLL or shared object it needs, may be installed before the next scan).
          if (p.outcome.result != LoadResult::Crashed &&
              p.outcome.result != LoadResult::NotLoadable)
            keep_scan(p.identity, payload);
        }
      }
      outcomes.push_back(std::move(p.outcome));
    }
  }
  return outcomes;
}

}  // namespace fr
