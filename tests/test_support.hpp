// test_support.hpp — what several tests share: fixture paths and one OpenCL device per process.
#pragma once

#include "plugin/plugin_loader.hpp"
#include "render/cl_runtime.hpp"
#include "render/device.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

namespace fr::test {

inline std::filesystem::path fixture_plugin(const std::string& name) {
  return std::filesystem::path(FIXTURE_PLUGIN_DIR) / ("fixture_" + name + ".so");
}

// A scene that must load: the test fails loudly otherwise.
inline std::shared_ptr<const LoadedScene> load_or_fail(const std::filesystem::path& file) {
  LoadOutcome o = load_scene_plugin(file);
  EXPECT_EQ(o.result, LoadResult::Loaded) << file << ": " << o.message;
  return o.scene;
}

inline std::shared_ptr<const LoadedScene> mandelbulb() {
  return load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / "mandelbulb.so");
}
inline std::shared_ptr<const LoadedScene> unit_ball() {
  return load_or_fail(std::filesystem::path(TEST_SCENE_DIR) / "unit_ball.so");
}

// The default device (PoCL's CPU device on the development machines), opened once.
inline ClRuntime& runtime() {
  static std::unique_ptr<ClRuntime> rt = [] {
    std::string error;
    auto device = select_device(list_devices(), "", &error);
    if (!device) throw std::runtime_error(error);
    return std::make_unique<ClRuntime>(*device);
  }();
  return *rt;
}

// A fresh, empty folder under the build tree's test output.
inline std::filesystem::path fresh_dir(const std::string& name) {
  auto dir = std::filesystem::path(TEST_OUTPUT_DIR) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace fr::test
