// Iteration counts that follow a deep zoom (render/depth_iterations.hpp): the count a footprint
// needs against log(R / f) / log(ratio) worked out by hand, the steps, the max, and the second
// probe at the max that sees past an estimate too coarse to see the eye's depth (a fake probe with
// a known distance and resolution stands in for a scene).
#include "render/depth_iterations.hpp"

#include "plugin/scene_instance.hpp"
#include "scene/scene_data.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fr {
namespace {

SceneInfo counted_scene(double ratio, double max_count) {
  SceneInfo info;
  info.id = "counted";
  ParamInfo scale;
  scale.key = "scale";
  scale.type = FR_PARAM_FLOAT;
  scale.default_value.v[0] = 2;
  scale.max_value.v[0] = 3;
  info.params.push_back(scale);
  ParamInfo count;
  count.key = "iterations";
  count.type = FR_PARAM_INT;
  count.default_value.v[0] = 14;
  count.min_value.v[0] = 1;
  count.max_value.v[0] = max_count;
  count.detail_ratio = ratio;
  info.params.push_back(count);
  info.camera = fr_camera{sizeof(fr_camera), 0, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 60};
  info.bounding_radius = 8;
  return info;
}

// R = 8, pixels of 2^-10 rad: an eye d from the surface adds log_g(R / d) iterations to the count
// set (in steps of 4, rounded down), up to what the footprint d 2^-10 needs, log_g(R / f) (rounded
// up to a step), never below the count set or past the max.
TEST(DepthIterations, AddsTheZoomUpToWhatThePixelsNeed) {
  const SceneInfo info = counted_scene(2, 100);
  const double pixel = std::ldexp(1.0, -10);
  std::vector<fr_value> params = make_default_state(info).params;
  // d = 2^-57: the zoom adds log2(8 / 2^-57) = 60, 14 + 60 = 74; the pixels need 70, stepped 72.
  auto raised = raise_iterations_for_depth(info, 8, std::ldexp(1.0, -57), pixel, params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].key, "iterations");
  EXPECT_EQ(raised[0].set, 14);
  EXPECT_EQ(raised[0].needed, 70);
  EXPECT_EQ(raised[0].used, 72);
  EXPECT_FALSE(raised[0].capped);
  EXPECT_EQ(params[1].v[0], 72);
  EXPECT_EQ(params[0].v[0], 2) << "a parameter without a ratio is left alone";

  // d = 2^-7: the zoom adds 10, stepped down to 8: 22; the footprint 2^-17 needs 20: 20.
  params = make_default_state(info).params;
  raised = raise_iterations_for_depth(info, 8, std::ldexp(1.0, -7), pixel, params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].used, 20);

  // The scene seen whole (d >= R) or barely closer (zoom under a step): the count set.
  params = make_default_state(info).params;
  EXPECT_TRUE(raise_iterations_for_depth(info, 8, 9, pixel, params).empty());
  EXPECT_TRUE(raise_iterations_for_depth(info, 8, 1.5, pixel, params).empty());
  EXPECT_EQ(params[1].v[0], 14);

  // A deliberately coarse count keeps its coarseness relative to the view: 2 at d = 8 / 2^5
  // becomes 2 + 4 = 6, though the pixels could use 15.
  params[1].v[0] = 2;
  raised = raise_iterations_for_depth(info, 8, 8 * std::ldexp(1.0, -5), pixel, params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].used, 6);
  EXPECT_EQ(raised[0].needed, 15);

  // An explicit count above what the pixels need stays: 90 at d = 2^-57 (they need 70).
  params = make_default_state(info).params;
  params[1].v[0] = 90;
  EXPECT_TRUE(raise_iterations_for_depth(info, 8, std::ldexp(1.0, -57), pixel, params).empty());
  EXPECT_EQ(params[1].v[0], 90);

  // The Menger sponge's 3: d = 8 / 3^40 adds 40 (stepped 40), the pixels need 40 + 6.3, 47,
  // stepped 48: 4 + 40 = 44.
  const SceneInfo sponge = counted_scene(3, 70);
  params = make_default_state(sponge).params;
  params[1].v[0] = 4;
  raised = raise_iterations_for_depth(sponge, 8, 8 / std::pow(3.0, 40), pixel, params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].needed, 47);
  EXPECT_EQ(raised[0].used, 44);

  // Past the max: the max, and what the view asked for, said.
  const SceneInfo capped = counted_scene(2, 40);
  params = make_default_state(capped).params;
  raised = raise_iterations_for_depth(capped, 8, std::ldexp(1.0, -57), pixel, params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].used, 40);
  EXPECT_TRUE(raised[0].capped);
  EXPECT_NE(describe_raised(raised).find("its max (the view asks for more: 70)"),
            std::string::npos)
      << describe_raised(raised);

  // Nothing to go on: no change.
  params = make_default_state(info).params;
  for (double d : {0.0, -1.0, double(NAN), double(INFINITY), 100.0})
    EXPECT_TRUE(raise_iterations_for_depth(info, 8, d, pixel, params).empty()) << d;
}

// A scene whose surface is `distance` from the eye and whose estimate with n iterations cannot
// tell distances below 8 x 2^-n (it reads the eye as that far off), as an escape-time estimate
// does. With the 14 set, the first probe reads 2^-11; the counts at their max see the true
// distance, and the view gets what that needs.
TEST(DepthIterations, ProbesAgainAtTheMaxWhereTheSetCountsCannotSee) {
  const SceneInfo info = counted_scene(2, 100);
  SceneState state = make_default_state(info);
  const double distance = 1e-15;
  int probes = 0;
  const DeProbe probe = [&](const std::vector<fr_value>& params,
                            const std::vector<std::array<float, 3>>& points, Precision,
                            const PairOrigin*) {
    ++probes;
    const double n = params[1].v[0];
    return std::vector<float>(points.size(),
                              static_cast<float>(std::max(distance, 8 * std::ldexp(1.0, -int(n)))));
  };
  std::vector<fr_value> params;
  const auto raised = raise_iterations_for_view(probe, info, state, 64, 48, false, params);
  ASSERT_EQ(raised.size(), 1u);
  const CameraRays rays = make_camera_rays(state.camera, 64, 48);
  const double seen = static_cast<double>(static_cast<float>(distance));
  const int needed = static_cast<int>(std::ceil(std::log2(8 / (seen * rays.pixel_angle_rad))));
  const int zoom = static_cast<int>(std::log2(8 / seen)) / 4 * 4;
  EXPECT_EQ(raised[0].needed, needed);
  EXPECT_EQ(raised[0].used, std::min(14 + zoom, (needed + 3) / 4 * 4));
  EXPECT_EQ(params[1].v[0], raised[0].used);
  EXPECT_EQ(probes, 2) << "the set counts, then the max";

  // A shallow view: one probe, nothing raised.
  probes = 0;
  const DeProbe shallow = [&](const std::vector<fr_value>&,
                              const std::vector<std::array<float, 3>>& points, Precision,
                              const PairOrigin*) {
    ++probes;
    return std::vector<float>(points.size(), 3.0f);
  };
  EXPECT_TRUE(raise_iterations_for_view(shallow, info, state, 64, 48, false, params).empty());
  EXPECT_EQ(probes, 1);
  EXPECT_EQ(params[1].v[0], 14);

  // An eye 12 outside the bounding sphere (R 8) cannot be closer than 12 to the surface: no
  // count could gain a step, and nothing is probed.
  probes = 0;
  state.camera.eye[2] = 20;
  EXPECT_TRUE(raise_iterations_for_view(probe, info, state, 64, 48, false, params).empty());
  EXPECT_EQ(probes, 0);
}

}  // namespace
}  // namespace fr
