// Scene plugins loaded in their own process (plugin/plugin_loader with the default isolation):
// fractalis-scene-host is started with a channel and the plugin file's handle, loads a private
// copy of the library, runs its constructors and answers calls. Fixture plugins
// (tests/fixtures/plugins/) built as this system's libraries: a valid scene that loads and
// updates, one built for another ABI major, one whose constructor writes through a null pointer
// (the scene host crashes, or on Windows its loader refuses the library; the caller goes on) and
// one whose constructor never returns (stopped at the load limit). Linux CTest runs it;
// cross-built, Wine runs the Windows programs (scripts/test-windows.sh).
// (tests/plugin_isolation_test.cpp has the whole Linux table.)
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "test_paths.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

namespace fr {
namespace {

const bool kWindows = std::filesystem::path::preferred_separator == '\\';

std::filesystem::path fixture(const std::string& name) {
  return std::filesystem::path(PORTED_FIXTURE_DIR) / ("ported_fixture_" + name + PLUGIN_SUFFIX);
}

TEST(PortedPlugins, AValidSceneLoadsAndUpdatesInItsOwnProcess) {
  const LoadOutcome loaded = load_scene_plugin(fixture("valid_scene"));
  ASSERT_EQ(loaded.result, LoadResult::Loaded) << loaded.message;
  EXPECT_EQ(loaded.scene->info.id, "fixture_valid");
  EXPECT_NE(loaded.scene->info.de_source.find("scene_de"), std::string::npos);
  std::string error;
  auto instance = SceneInstance::create(loaded.scene, &error);
  ASSERT_TRUE(instance) << error;
  SceneState state = make_default_state(loaded.scene->info);
  EXPECT_TRUE(instance->update(state, 0.5, &error)) << error;
}

TEST(PortedPlugins, ABadPluginIsReportedAndTheCallerGoesOn) {
  const LoadOutcome wrong = load_scene_plugin(fixture("wrong_major"));
  EXPECT_EQ(wrong.result, LoadResult::WrongAbiMajor) << wrong.message;

  const LoadOutcome segv = load_scene_plugin(fixture("ctor_segv"));
  if (kWindows) {
    // Windows' loader runs a DLL's initialisation under its own exception handler: the fault
    // fails LoadLibrary (ERROR_NOACCESS) and the scene host lives on to say so.
    EXPECT_EQ(segv.result, LoadResult::NotLoadable) << segv.message;
    EXPECT_NE(segv.message.find("memory location"), std::string::npos) << segv.message;
  } else {
    EXPECT_EQ(segv.result, LoadResult::Crashed) << segv.message;
    EXPECT_NE(segv.message.find("crashed"), std::string::npos) << segv.message;
  }

  PluginPolicy quick;
  quick.load_timeout_s = 2;
  const auto started = std::chrono::steady_clock::now();
  const LoadOutcome loop = load_scene_plugin(fixture("ctor_loop"), quick);
  const double took_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(loop.result, LoadResult::Crashed) << loop.message;
  EXPECT_NE(loop.message.find("did not answer within 2 s"), std::string::npos) << loop.message;
  EXPECT_LT(took_s, 10) << "stopped at the limit, not waited for";
}

}  // namespace
}  // namespace fr
