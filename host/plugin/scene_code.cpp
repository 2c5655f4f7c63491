#include "plugin/scene_code.hpp"

#include "plugin/plugin_library.hpp"

#include <exception>

namespace fr {
namespace {

// Collects what the plugin logs during one call; fr_host.host_data points at it.
struct CallLog {
  std::vector<PluginMessage> messages;
  std::string last_error;  // the last FR_LOG_ERROR message: the reason for an FR_ERROR

  static void log(void* host_data, fr_log_level level, const char* message) {
    auto* self = static_cast<CallLog*>(host_data);
    std::string text = message ? message : "(null message)";
    if (text.size() > kMaxMessageBytes) text.resize(kMaxMessageBytes);
    if (level >= FR_LOG_ERROR) self->last_error = text;
    if (self->messages.size() < kMaxMessagesPerCall) self->messages.push_back({level, text});
  }
  fr_host host() {
    fr_host h{};
    h.struct_size = sizeof h;
    h.host_data = this;
    h.log = &CallLog::log;
    return h;
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
  out.messages = std::move(log.messages);
  return out;
}

}  // namespace

InProcessCode::~InProcessCode() { destroy_all(); }

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
