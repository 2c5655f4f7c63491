#include "plugin/scene_instance.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace fr {

SceneState make_default_state(const SceneInfo& info) {
  SceneState s;
  for (const auto& p : info.params) s.params.push_back(p.default_value);
  s.camera = info.camera;
  s.lights = info.lights;
  s.bounding_radius = info.bounding_radius;
  return s;
}

void clamp_params(const SceneInfo& info, std::vector<fr_value>& values) {
  values.resize(info.params.size());
  for (size_t i = 0; i < info.params.size(); ++i) {
    const ParamInfo& p = info.params[i];
    for (int c = 0; c < p.component_count(); ++c) {
      double v = values[i].v[c];
      if (!std::isfinite(v)) v = p.default_value.v[c];
      if (p.type == FR_PARAM_INT || p.type == FR_PARAM_BOOL) v = std::round(v);
      values[i].v[c] = std::clamp(v, p.min_value.v[c], p.max_value.v[c]);
    }
  }
}

void SceneInstance::log_from_plugin(void* host_data, fr_log_level level, const char* message) {
  auto* self = static_cast<SceneInstance*>(host_data);
  const std::string text = message ? message : "(null message)";
  const std::string& id = self->scene_->info.id;
  switch (level) {
    case FR_LOG_DEBUG:
      spdlog::debug("[{}] {}", id, text);
      break;
    case FR_LOG_INFO:
      spdlog::info("[{}] {}", id, text);
      break;
    case FR_LOG_WARNING:
      spdlog::warn("[{}] {}", id, text);
      break;
    default:
      self->last_error_ = text;
      spdlog::debug("[{}] error: {}", id, text);
      break;
  }
}

fr_host SceneInstance::host_api() {
  fr_host host{};
  host.struct_size = sizeof(fr_host);
  host.host_data = this;
  host.log = &SceneInstance::log_from_plugin;
  return host;
}

std::unique_ptr<SceneInstance> SceneInstance::create(std::shared_ptr<const LoadedScene> scene,
                                                     std::string* error) {
  std::unique_ptr<SceneInstance> self(new SceneInstance(std::move(scene)));
  if (self->scene_->create) {
    fr_host host = self->host_api();
    if (self->scene_->create(&host, &self->instance_) != FR_OK) {
      *error = "scene '" + self->scene_->info.id + "': create failed: " +
               (self->last_error_.empty() ? "no reason logged" : self->last_error_);
      return nullptr;
    }
  }
  self->created_ = true;
  return self;
}

SceneInstance::~SceneInstance() {
  if (created_ && scene_->destroy) scene_->destroy(instance_);
}

bool SceneInstance::update(SceneState& state, double time_s, std::string* error) {
  const SceneInfo& info = scene_->info;
  state.dt_s = state.frame_index == 0 ? 0.0 : time_s - state.time_s;
  state.time_s = time_s;
  clamp_params(info, state.params);  // the plugin only ever sees values within their limits
  if (scene_->update) {
    fr_frame_state fs{};
    fs.struct_size = sizeof(fr_frame_state);
    fs.param_count = static_cast<uint32_t>(state.params.size());
    fs.time_s = state.time_s;
    fs.dt_s = state.dt_s;
    fs.frame_index = state.frame_index;
    fs.params = state.params.data();
    fs.camera = &state.camera;
    fs.lights = state.lights.data();
    fs.light_count = static_cast<uint32_t>(state.lights.size());
    fs.bounding_radius = state.bounding_radius;
    fr_host host = host_api();
    last_error_.clear();
    if (scene_->update(instance_, &host, &fs) != FR_OK) {
      *error = "scene '" + info.id +
               "': update failed: " + (last_error_.empty() ? "no reason logged" : last_error_);
      return false;
    }
    state.camera.struct_size = sizeof(fr_camera);
    if (std::isfinite(fs.bounding_radius) && fs.bounding_radius > 0)
      state.bounding_radius = fs.bounding_radius;
    else {
      *error = "scene '" + info.id + "': update set bounding_radius to " +
               std::to_string(fs.bounding_radius) + " (expected a finite value > 0)";
      return false;
    }
  }
  clamp_params(info, state.params);
  ++state.frame_index;
  return true;
}

}  // namespace fr
