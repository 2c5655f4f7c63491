#include "plugin/scene_code.hpp"

#include "plugin/plugin_library.hpp"

#include <cstring>
#include <exception>
#include <mutex>

namespace fr {
namespace {

// FR_EXT_THREAD_LOG: messages from any plugin thread, at any time, passed on with the next
// call's answer (bounded like a call's own messages).
std::mutex g_thread_log_mutex;
std::vector<PluginMessage> g_thread_log;
size_t g_thread_log_dropped = 0;

// A plugin's message, at most kMaxMessageBytes of it: never reads further (a flood of huge
// messages costs the cap, not their length).
std::string bounded_text(const char* message) {
  if (!message) return "(null message)";
  return std::string(message, strnlen(message, kMaxMessageBytes));
}

void thread_log(fr_log_level level, const char* message) {
  std::string text = bounded_text(message);
  std::lock_guard lock(g_thread_log_mutex);
  if (g_thread_log.size() < kMaxMessagesPerCall)
    g_thread_log.push_back({level, std::move(text)});
  else
    ++g_thread_log_dropped;
}

const fr_thread_log kThreadLog = {sizeof(fr_thread_log), 0, &thread_log};

const void* host_extension(const fr_host* host, const char* id) {
  (void)host;
  if (id && std::strcmp(id, FR_EXT_THREAD_LOG) == 0) return &kThreadLog;
  return nullptr;
}

// Collects what the plugin logs during one call; fr_host.host_data points at it.
struct CallLog {
  std::vector<PluginMessage> messages;
  std::string last_error;  // the last FR_LOG_ERROR message: the reason for an FR_ERROR

  static void log(void* host_data, fr_log_level level, const char* message) {
    auto* self = static_cast<CallLog*>(host_data);
    const bool keep = self->messages.size() < kMaxMessagesPerCall;
    if (!keep && level < FR_LOG_ERROR) return;  // past the cap: not even copied
    std::string text = bounded_text(message);
    if (level >= FR_LOG_ERROR) self->last_error = text;
    if (keep) self->messages.push_back({level, std::move(text)});
  }
  fr_host host() {
    fr_host h{};
    h.struct_size = sizeof h;
    h.host_data = this;
    h.log = &CallLog::log;
    h.host_name = "fractalis";
    h.host_version = FRACTALIS_VERSION;
    h.get_extension = &host_extension;
    return h;
  }
  // What other threads logged meanwhile comes after the call's own messages.
  void take_thread_log() {
    std::lock_guard lock(g_thread_log_mutex);
    for (PluginMessage& m : g_thread_log)
      if (messages.size() < kMaxMessagesPerCall) messages.push_back(std::move(m));
    g_thread_log.clear();
    g_thread_log_dropped = 0;
  }
};

// Runs `call` and turns whatever it does (FR_ERROR, an exception) into an outcome.
template <typename Call>
CallOutcome guarded(const char* what, CallLog& log, Call&& call) {
  CallOutcome out;
  try {
    const fr_result r = call();
    out.ok = r == FR_OK;
    if (!out.ok)
      out.error = std::string(what) +
                  " failed: " + (log.last_error.empty() ? "no reason logged" : log.last_error) +
                  (r == FR_ERROR ? "" : " (returned " + std::to_string(r) + ")");
  } catch (const std::exception& e) {
    out.error = std::string(what) + " threw a C++ exception: " + e.what() +
                " (exceptions must not cross the C ABI)";
  } catch (...) {
    out.error = std::string(what) + " threw an exception (exceptions must not cross the C ABI)";
  }
  log.take_thread_log();
  out.messages = std::move(log.messages);
  return out;
}

}  // namespace

CallOutcome run_entry_init(const fr_scene_entry& entry, const std::string& plugin_path) {
  CallLog log;
  return guarded("init", log, [&] {
    if (!entry.init) return FR_OK;
    fr_host host = log.host();
    return entry.init(&host, plugin_path.c_str());
  });
}

InProcessCode::~InProcessCode() {
  destroy_all();
}

void InProcessCode::destroy_all() {
  while (!instances_.empty()) destroy(instances_.begin()->first);
}

CallOutcome InProcessCode::create(uint64_t* handle) {
  CallLog log;
  void* instance = nullptr;
  CallOutcome out = guarded("create", log, [&] {
    if (!create_) return FR_OK;
    fr_host host = log.host();
    return create_(&host, &instance);
  });
  if (out.ok) {
    *handle = next_handle_++;
    instances_[*handle] = instance;
  }
  return out;
}

CallOutcome InProcessCode::update(uint64_t handle, SceneState& state) {
  CallLog log;
  auto it = instances_.find(handle);
  if (it == instances_.end()) return {false, "update called on an unknown instance", {}};
  return guarded("update", log, [&] {
    if (!update_) return FR_OK;
    // The plugin works on copies it cannot resize: the counts are the host's.
    fr_frame_state fs{};
    fs.struct_size = sizeof fs;
    fs.param_count = static_cast<uint32_t>(state.params.size());
    fs.time_s = state.time_s;
    fs.dt_s = state.dt_s;
    fs.frame_index = state.frame_index;
    fs.params = state.params.data();
    fr_camera camera = state.camera;
    camera.struct_size = sizeof camera;
    camera.reserved = 0;
    fs.camera = &camera;
    fs.lights = state.lights.data();
    fs.light_count = static_cast<uint32_t>(state.lights.size());
    fs.bounding_radius = state.bounding_radius;
    fs.light_stride = sizeof(fr_light);
    fr_host host = log.host();
    const fr_result r = update_(it->second, &host, &fs);
    camera.struct_size = sizeof camera;
    camera.reserved = 0;
    state.camera = camera;
    state.bounding_radius = fs.bounding_radius;
    for (fr_light& l : state.lights) l.struct_size = sizeof l;
    return r;
  });
}

void InProcessCode::destroy(uint64_t handle) {
  auto it = instances_.find(handle);
  if (it == instances_.end()) return;
  void* instance = it->second;
  instances_.erase(it);
  if (!destroy_) return;
  try {
    destroy_(instance);
  } catch (...) {
    // Nothing to recover: the instance is gone either way.
  }
}

}  // namespace fr
