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

TEST(DepthIterations, FootprintNeedsLogOfTheRatio) {
  const SceneInfo info = counted_scene(2, 100);
  std::vector<fr_value> params = make_default_state(info).params;
  // R / f = 8 / 2^-60 = 2^63: 63 iterations, raised to the next step of 8, 64.
  auto raised = raise_iterations_for_footprint(info, 8, std::ldexp(1.0, -60), params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].key, "iterations");
  EXPECT_EQ(raised[0].set, 14);
  EXPECT_EQ(raised[0].needed, 63);
  EXPECT_EQ(raised[0].used, 64);
  EXPECT_EQ(params[1].v[0], 64);
  EXPECT_EQ(params[0].v[0], 2) << "a parameter without a ratio is left alone";

  // A shallow view needs fewer than set: nothing changes (never lowered).
  params = make_default_state(info).params;
  EXPECT_TRUE(raise_iterations_for_footprint(info, 8, 0.01, params).empty());
  EXPECT_EQ(params[1].v[0], 14);

  // The Menger sponge's 3: R / f = 3^50 needs 50, rendered 56.
  const SceneInfo sponge = counted_scene(3, 70);
  params = make_default_state(sponge).params;
  raised = raise_iterations_for_footprint(sponge, 8, 8 / std::pow(3.0, 50), params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].needed, 50);
  EXPECT_EQ(raised[0].used, 56);

  // Past the max: the max, and what the view needed, said.
  const SceneInfo capped = counted_scene(2, 40);
  params = make_default_state(capped).params;
  raised = raise_iterations_for_footprint(capped, 8, std::ldexp(1.0, -60), params);
  ASSERT_EQ(raised.size(), 1u);
  EXPECT_EQ(raised[0].used, 40);
  EXPECT_EQ(raised[0].needed, 63);
  EXPECT_NE(describe_raised(raised).find("needs 63 but that is its max"), std::string::npos)
      << describe_raised(raised);

  // Nothing to go on: no change.
  params = make_default_state(info).params;
  for (double f : {0.0, -1.0, double(NAN), double(INFINITY), 100.0})
    EXPECT_TRUE(raise_iterations_for_footprint(info, 8, f, params).empty()) << f;
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
  const double footprint = static_cast<double>(static_cast<float>(distance)) * rays.pixel_angle_rad;
  const int needed = static_cast<int>(std::ceil(std::log2(8 / footprint)));
  EXPECT_EQ(raised[0].needed, needed);
  EXPECT_EQ(raised[0].used, (needed + 7) / 8 * 8);
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
}

}  // namespace
}  // namespace fr
