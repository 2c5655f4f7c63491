// sweep_plan.hpp — the quality knobs a sweep turns, and the configurations it renders: the
// defaults, then each knob through its values one at a time (the others at their defaults).
#pragma once

#include "render/render_settings.hpp"
#include "scene/scene_data.hpp"

#include <string>
#include <vector>

namespace fr {

struct SweepConfig {
  std::string knob;   // "default" for the row of the current defaults
  std::string value;  // as `--set` would spell it
  RenderSettings settings;
};

// Every knob's name, in the order a sweep takes them.
const std::vector<std::string>& all_knob_names();

// The knobs that apply to this scene at these base settings: effect knobs (ao, shadow_steps) only
// when the scene uses that effect, the path tracer's (path_max_bounces) only when the base
// integrator is path, and not what its kernel leaves out (ao, the mirrors' shadow budget).
std::vector<std::string> knob_names(const SceneInfo& info, const RenderSettings& base);

// The configurations for `knobs` (each must be one of all_knob_names(); an unknown one throws
// std::invalid_argument naming it and the known ones). A value equal to the default is the
// default row, not a row of its own.
std::vector<SweepConfig> plan_sweep(const SceneInfo& info, const RenderSettings& defaults,
                                    const std::vector<std::string>& knobs);

}  // namespace fr
