#include "sweep/sweep_plan.hpp"

#include <functional>
#include <sstream>
#include <stdexcept>

namespace fr {
namespace {

struct KnobValue {
  std::string value;
  std::function<void(RenderSettings&)> apply;
};

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// "sampled-5": sampled AO with that many samples.
std::string sampled_ao_label(int samples) {
  std::string label = enum_name(AoMethod::Sampled);
  label += '-';
  label += number(samples);
  return label;
}

// Each knob's values, and how the default spells its value (to recognise the default row).
std::vector<KnobValue> knob_values(const std::string& knob, const RenderSettings& d,
                                   std::string* default_value) {
  std::vector<KnobValue> v;
  if (knob == "precision") {
    *default_value = precision_name(d.precision);
    for (Precision p : {Precision::Float, Precision::Double})
      v.push_back({precision_name(p), [p](RenderSettings& s) { s.precision = p; }});
  } else if (knob == "hit_threshold_k") {
    *default_value = number(d.hit_threshold_k);
    for (float k : {2.0f, 1.0f, 0.5f, 0.25f, 0.125f})
      v.push_back({number(k), [k](RenderSettings& s) { s.hit_threshold_k = k; }});
  } else if (knob == "max_steps") {
    *default_value = number(d.max_steps);
    for (int n : {40, 80, 160, 320, 640})
      v.push_back({number(n), [n](RenderSettings& s) { s.max_steps = n; }});
  } else if (knob == "refine_steps") {
    *default_value = number(d.refine_steps);
    for (int n : {0, 1, 2, 4})
      v.push_back({number(n), [n](RenderSettings& s) { s.refine_steps = n; }});
  } else if (knob == "relaxation") {
    *default_value = number(d.relaxation);
    for (float w : {1.0f, 1.3f, 1.6f, 1.9f})
      v.push_back({number(w), [w](RenderSettings& s) { s.relaxation = w; }});
  } else if (knob == "adaptive_relaxation") {
    *default_value = d.adaptive_relaxation ? "on" : "off";
    for (bool on : {false, true})
      v.push_back({on ? "on" : "off", [on](RenderSettings& s) { s.adaptive_relaxation = on; }});
  } else if (knob == "cone_prepass") {
    *default_value = d.cone_prepass ? "on" : "off";
    for (bool on : {false, true})
      v.push_back({on ? "on" : "off", [on](RenderSettings& s) { s.cone_prepass = on; }});
  } else if (knob == "normals") {
    *default_value = enum_name(d.normals);
    for (NormalMethod m : {NormalMethod::Tetrahedron, NormalMethod::CentralDifferences})
      v.push_back({enum_name(m), [m](RenderSettings& s) { s.normals = m; }});
  } else if (knob == "samples") {
    *default_value = number(d.samples);
    // Path tracing converges by samples alone: a longer range, for error against time.
    const std::vector<int> counts = d.integrator == Integrator::Path
                                        ? std::vector<int>{1, 4, 16, 64, 256}
                                        : std::vector<int>{1, 2, 4, 8, 16};
    for (int n : counts) v.push_back({number(n), [n](RenderSettings& s) { s.samples = n; }});
  } else if (knob == "integrator") {
    // Against the base integrator's reference: with --integrator path, the fast integrator's
    // row is how far its light model is from the path-traced one, which the samples rows reach
    // at some cost (where path tracing starts to pay).
    *default_value = enum_name(d.integrator);
    for (Integrator i : {Integrator::Fast, Integrator::Path})
      v.push_back({enum_name(i), [i](RenderSettings& s) { s.integrator = i; }});
  } else if (knob == "path_max_bounces") {
    *default_value = number(d.path_max_bounces);
    for (int n : {1, 2, 4, 8, 16})
      v.push_back({number(n), [n](RenderSettings& s) { s.path_max_bounces = n; }});
  } else if (knob == "lanes") {
    *default_value = number(d.lanes);
    for (int n : {1, 16}) v.push_back({number(n), [n](RenderSettings& s) { s.lanes = n; }});
  } else if (knob == "ao") {
    *default_value = d.ao_method == AoMethod::StepCount
                         ? std::string(enum_name(AoMethod::StepCount))
                         : sampled_ao_label(d.ao_samples);
    v.push_back({enum_name(AoMethod::StepCount),
                 [](RenderSettings& s) { s.ao_method = AoMethod::StepCount; }});
    for (int n : {3, 5, 8})
      v.push_back({sampled_ao_label(n), [n](RenderSettings& s) {
                     s.ao_method = AoMethod::Sampled;
                     s.ao_samples = n;
                   }});
  } else if (knob == "shadow_steps") {
    *default_value = number(d.shadow_max_steps);
    for (int n : {16, 32, 64, 128})
      v.push_back({number(n), [n](RenderSettings& s) { s.shadow_max_steps = n; }});
  } else if (knob == "bounce_steps") {
    *default_value = number(d.bounce_max_steps);
    for (int n : {32, 64, 160})
      v.push_back({number(n), [n](RenderSettings& s) { s.bounce_max_steps = n; }});
  } else if (knob == "bounce_shadow_steps") {
    *default_value = number(d.bounce_shadow_max_steps);
    for (int n : {0, 8, 16, 32})
      v.push_back({number(n), [n](RenderSettings& s) { s.bounce_shadow_max_steps = n; }});
  } else {
    std::string known;
    for (const auto& k : all_knob_names()) known += (known.empty() ? "" : ", ") + k;
    throw std::invalid_argument("unknown knob '" + knob + "' (known: " + known + ")");
  }
  return v;
}

}  // namespace

const std::vector<std::string>& all_knob_names() {
  static const std::vector<std::string> names = {"precision",    "hit_threshold_k",
                                                 "max_steps",    "refine_steps",
                                                 "relaxation",   "adaptive_relaxation",
                                                 "cone_prepass", "normals",
                                                 "samples",      "lanes",
                                                 "ao",           "shadow_steps",
                                                 "bounce_steps", "bounce_shadow_steps",
                                                 "integrator",   "path_max_bounces"};
  return names;
}

std::vector<std::string> knob_names(const SceneInfo& info, const RenderSettings& base) {
  const bool path = base.integrator == Integrator::Path;
  std::vector<std::string> names;
  for (const auto& k : all_knob_names()) {
    if (k == "path_max_bounces" && !path) continue;
    if (path && (k == "ao" || k == "bounce_shadow_steps")) continue;
    if (k == "ao" && !(info.features & FR_FEATURE_AO)) continue;
    if (k == "shadow_steps" && !(info.features & FR_FEATURE_SHADOWS)) continue;
    if (k == "bounce_steps" && !(info.features & FR_FEATURE_REFLECTIONS)) continue;
    if (k == "bounce_shadow_steps" &&
        (info.features & (FR_FEATURE_REFLECTIONS | FR_FEATURE_SHADOWS)) !=
            (FR_FEATURE_REFLECTIONS | FR_FEATURE_SHADOWS))
      continue;
    names.push_back(k);
  }
  return names;
}

std::vector<SweepConfig> plan_sweep(const SceneInfo& info, const RenderSettings& defaults,
                                    const std::vector<std::string>& knobs) {
  (void)info;
  std::vector<SweepConfig> configs = {{"default", "", defaults}};
  for (const auto& knob : knobs) {
    std::string default_value;
    for (const KnobValue& kv : knob_values(knob, defaults, &default_value)) {
      if (kv.value == default_value) continue;
      SweepConfig c{knob, kv.value, defaults};
      kv.apply(c.settings);
      configs.push_back(std::move(c));
    }
  }
  return configs;
}

}  // namespace fr
