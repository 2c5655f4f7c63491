#include "plugin/scene_instance.hpp"

#include "io/printable.hpp"
#include "plugin/scene_checks.hpp"
#include "plugin/scene_code.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace fr {
namespace {

// Passes on what a plugin logged to the one log channel (io/log.hpp) at the level it gave, with its
// scene id and with control characters escaped.
void forward_messages(const std::string& id, const std::vector<PluginMessage>& messages) {
  for (const PluginMessage& m : messages) {
    const std::string text = printable(m.text);
    switch (m.level) {
      case FR_LOG_DEBUG:
        spdlog::debug("[{}] {}", id, text);
        break;
      case FR_LOG_INFO:
        spdlog::info("[{}] {}", id, text);
        break;
      case FR_LOG_WARNING:
        spdlog::warn("[{}] {}", id, text);
        break;
      default:  // errors keep their level, and also become the failing call's reason
        spdlog::error("[{}] {}", id, text);
        break;
    }
  }
}

// Why the state an update left cannot be rendered, or "".
std::string check_updated_state(const SceneState& s) {
  if (auto problem = check_camera(s.camera, s.camera_lo))
    return "update left an invalid camera: " + *problem;
  for (size_t i = 0; i < s.lights.size(); ++i)
    if (auto problem = check_light(s.lights[i]))
      return "update left light " + std::to_string(i) + " invalid: it " + *problem;
  if (!(std::isfinite(s.bounding_radius) && s.bounding_radius > 0))
    return "update set bounding_radius to " + std::to_string(s.bounding_radius) +
           " (expected a finite value > 0)";
  return "";
}

}  // namespace

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
      if (p.whole()) v = std::round(v);
      values[i].v[c] = std::clamp(v, p.min_value.v[c], p.max_value.v[c]);
    }
  }
}

std::unique_ptr<SceneInstance> SceneInstance::create(std::shared_ptr<const LoadedScene> scene,
                                                     std::string* error) {
  std::unique_ptr<SceneInstance> self(new SceneInstance(std::move(scene)));
  const std::string& id = self->scene_->info.id;
  if (!self->scene_->code) {
    *error = "scene '" + id + "': has no code to run its callbacks";
    return nullptr;
  }
  CallOutcome out = self->scene_->code->create(&self->handle_);
  forward_messages(id, out.messages);
  if (!out.ok) {
    *error = "scene '" + id + "': " + out.error;
    return nullptr;
  }
  self->created_ = true;
  return self;
}

SceneInstance::~SceneInstance() {
  if (created_) scene_->code->destroy(handle_);
}

bool SceneInstance::update(SceneState& state, double time_s, std::string* error) {
  const SceneInfo& info = scene_->info;
  if (!failure_.empty()) {
    *error = failure_;
    return false;
  }
  SceneState next = state;
  next.dt_s = next.frame_index == 0 ? 0.0 : time_s - next.time_s;
  next.time_s = time_s;
  clamp_params(info, next.params);  // the plugin only ever sees values within their limits
  CallOutcome out = scene_->code->update(handle_, next);
  forward_messages(info.id, out.messages);
  std::string problem = out.ok ? check_updated_state(next) : out.error;
  if (!problem.empty()) {
    failure_ =
        "scene '" + info.id + "': " + problem + " (its updates stop until the scene is reloaded)";
    *error = failure_;
    return false;
  }
  clamp_params(info, next.params);
  ++next.frame_index;
  state = std::move(next);
  return true;
}

}  // namespace fr
