// render_settings.hpp — how a frame is rendered: size, kernel shape and shading constants.
// Plain data with defaults; the CLI and settings files fill it in.
#pragma once

#include <fractalis/scene.h>

#include <array>

namespace fr {

enum class Precision { Float, Double };

struct RenderSettings {
  int width_px = 1280;
  int height_px = 720;
  int lanes = 0;  // 1, 4, 8 or 16; 0 picks the device's preferred width
  Precision precision = Precision::Float;
  fr_features disabled_stages = 0;  // stages the user switched off

  int max_steps = 160;
  int shadow_max_steps = 64;
  float hit_threshold_k = 0.5f;  // epsilon = k * t * pixel angle
  float max_distance = 100.0f;
  float step_scale = 1.0f;
  float ao_strength = 2.5f;
  float shadow_softness = 12.0f;
  float specular_strength = 0.35f;
  float specular_power = 48.0f;
  float exposure = 1.0f;
  std::array<float, 3> albedo{0.72f, 0.52f, 0.36f};
  std::array<float, 3> ambient{0.16f, 0.19f, 0.25f};
  std::array<float, 3> sky_zenith{0.22f, 0.36f, 0.62f};
  std::array<float, 3> sky_horizon{0.72f, 0.78f, 0.86f};
};

}  // namespace fr
