// mb2_scene_fixture.hpp — the mandelbulber scene (what imports open into) with its default
// values, and setters by key, for the tests that run its kernels on the device: the formula steps
// (mb2_import_test) and the colouring pass (mb2_colour_test).
#pragma once

#include "plugin/scene_instance.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <vector>

namespace fr::test {

class Mb2SceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    scene = load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulber" PLUGIN_SUFFIX);
    ASSERT_TRUE(scene);
    values = make_default_state(scene->info).params;
  }
  void set(const char* key, double v) {
    const int i = scene->info.find_param(key);
    ASSERT_GE(i, 0) << key;
    values[i].v[0] = v;
  }
  void set3(const char* key, double x, double y, double z) {
    const int i = scene->info.find_param(key);
    ASSERT_GE(i, 0) << key;
    values[i].v[0] = x;
    values[i].v[1] = y;
    values[i].v[2] = z;
  }
  void choose(const char* key, const char* name) {
    const int i = scene->info.find_param(key);
    ASSERT_GE(i, 0) << key;
    values[i].v[0] = scene->info.params[i].choice_index(name);
  }
  std::shared_ptr<const LoadedScene> scene;
  std::vector<fr_value> values;
};

}  // namespace fr::test
