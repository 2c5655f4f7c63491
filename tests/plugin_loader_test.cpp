// Plugin loading against one deliberately broken fixture per failure mode: the result code and
// the message (what was wrong, what was expected) for each, and the good plugins still load.
#include "plugin/plugin_loader.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <fstream>
#include <map>

namespace fr {
namespace {

using test::fixture_plugin;

void expect_failure(const std::string& fixture, LoadResult result,
                    const std::string& message_part) {
  const LoadOutcome o = load_scene_plugin(fixture_plugin(fixture));
  EXPECT_EQ(o.result, result) << fixture << ": " << load_result_name(o.result) << ": " << o.message;
  EXPECT_NE(o.message.find(message_part), std::string::npos) << fixture << " said: " << o.message;
  EXPECT_EQ(o.scene, nullptr);
  EXPECT_EQ(o.file, fixture_plugin(fixture));
}

TEST(PluginLoader, ValidFixtureLoadsAndCopiesStrings) {
  auto scene = test::load_or_fail(fixture_plugin("valid_scene"));
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->info.id, "fixture_valid");
  EXPECT_EQ(scene->info.de_source_name, "fixture.cl");
  EXPECT_EQ(scene->info.bounding_radius, 2.0);
  // Strings live in host memory, not in the library's.
  const void* lib_lo = scene->library.get();
  EXPECT_NE(static_cast<const void*>(scene->info.id.data()), lib_lo);
}

TEST(PluginLoader, NotElf) {
  expect_failure("not_elf", LoadResult::NotLoadable, "not an ELF shared library");
}
TEST(PluginLoader, NoEntrySymbol) {
  expect_failure("no_entry", LoadResult::NoEntrySymbol,
                 "no exported symbol 'fractalis_scene_entry'");
}
TEST(PluginLoader, WrongAbiMajor) {
  expect_failure("wrong_major", LoadResult::WrongAbiMajor, "wrong ABI major: plugin 2, host 1");
}
TEST(PluginLoader, AbiMinorTooNew) {
  expect_failure("too_new_minor", LoadResult::AbiTooNew, "plugin needs ABI 1.99, host has 1.0");
}
TEST(PluginLoader, StructTooSmall) {
  expect_failure("small_struct", LoadResult::StructTooSmall,
                 "fr_scene_entry struct_size 8 is smaller than ABI 1.0's 24");
}
TEST(PluginLoader, NullId) {
  expect_failure("null_id", LoadResult::InvalidScene, "scene id is null");
}
TEST(PluginLoader, NullDeSource) {
  expect_failure("null_de", LoadResult::InvalidScene, "scene 'fixture_null_de': de_source is null");
}

TEST(PluginLoader, Truncated) {
  const auto dir = test::fresh_dir("truncated");
  std::ifstream in(fixture_plugin("valid_scene"), std::ios::binary);
  std::vector<char> head(2000);
  in.read(head.data(), head.size());
  std::ofstream(dir / "truncated.so", std::ios::binary).write(head.data(), in.gcount());
  const LoadOutcome o = load_scene_plugin(dir / "truncated.so");
  EXPECT_EQ(o.result, LoadResult::NotLoadable);
  EXPECT_NE(o.message.find("truncated: 2000 bytes"), std::string::npos) << o.message;
}

TEST(PluginLoader, DuplicateIdNamesTheFirstFile) {
  const auto dir = test::fresh_dir("duplicate");
  std::filesystem::copy_file(fixture_plugin("valid_scene"), dir / "a.so");
  std::filesystem::copy_file(fixture_plugin("valid_scene"), dir / "b.so");
  const auto outcomes = load_scene_folder({dir});
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_EQ(outcomes[0].result, LoadResult::Loaded);
  EXPECT_EQ(outcomes[1].result, LoadResult::DuplicateId);
  EXPECT_NE(outcomes[1].message.find("duplicate scene id 'fixture_valid' (already provided by " +
                                     (dir / "a.so").string()),
            std::string::npos)
      << outcomes[1].message;
}

// A whole folder of fixtures: each bad one is reported and skipped, the good ones load.
TEST(PluginLoader, FolderSkipsBadPluginsAndKeepsGoodOnes) {
  const auto outcomes = load_scene_folder({FIXTURE_PLUGIN_DIR});
  std::map<std::string, LoadResult> by_file;
  for (const auto& o : outcomes) by_file[o.file.filename().string()] = o.result;
  EXPECT_EQ(by_file["fixture_valid_scene.so"], LoadResult::Loaded);
  EXPECT_EQ(by_file["fixture_bad_de.so"], LoadResult::Loaded)
      << "a DE is only compiled when rendered";
  EXPECT_EQ(by_file["fixture_update_error.so"], LoadResult::Loaded);
  EXPECT_EQ(by_file["fixture_not_elf.so"], LoadResult::NotLoadable);
  EXPECT_EQ(by_file["fixture_wrong_major.so"], LoadResult::WrongAbiMajor);
  EXPECT_EQ(by_file["fixture_null_id.so"], LoadResult::InvalidScene);
  EXPECT_EQ(outcomes.size(), 10u);
}

TEST(PluginLoader, DeThatDoesNotCompileNamesSceneAndLine) {
  auto scene = test::load_or_fail(fixture_plugin("bad_de"));
  ASSERT_TRUE(scene);
  Renderer renderer(test::runtime());
  RenderSettings settings;
  settings.width_px = 8;
  settings.height_px = 8;
  try {
    renderer.render(scene->info, make_default_state(scene->info), settings);
    FAIL() << "the broken DE compiled";
  } catch (const KernelBuildError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("scene 'fixture_bad_de'"), std::string::npos) << what;
    EXPECT_NE(what.find("fixture.cl:3:"), std::string::npos)
        << "line 3 of the scene's own source:\n"
        << what;
    EXPECT_NE(what.find("undeclared_radius"), std::string::npos) << what;
  }
}

TEST(PluginLoader, UpdateErrorCarriesPluginsReason) {
  auto scene = test::load_or_fail(fixture_plugin("update_error"));
  ASSERT_TRUE(scene);
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  ASSERT_TRUE(instance) << error;
  SceneState state = make_default_state(scene->info);
  EXPECT_FALSE(instance->update(state, 0.0, &error));
  EXPECT_EQ(error, "scene 'fixture_update_error': update failed: fixture refuses to update");
}

// The library is loaded from a private copy: the original can go away, and after the last
// reference is dropped the copy is no longer mapped.
TEST(PluginLoader, PrivateCopyAndUnmap) {
  const auto dir = test::fresh_dir("private_copy");
  std::filesystem::copy_file(fixture_plugin("valid_scene"), dir / "private_probe.so");
  auto scene = test::load_or_fail(dir / "private_probe.so");
  ASSERT_TRUE(scene);
  std::filesystem::remove(dir / "private_probe.so");
  EXPECT_EQ(scene->info.id, "fixture_valid");
  auto mapped = [] {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line))
      if (line.find("private_probe.so") != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(mapped());
  scene.reset();
  EXPECT_FALSE(mapped()) << "the library is still mapped after its last reference went";
}

TEST(SceneInstance, ClampsParamsAfterUpdate) {
  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  const int power = scene->info.find_param("power");
  ASSERT_GE(power, 0);
  state.params[power].v[0] = 1000;
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  ASSERT_TRUE(instance->update(state, 0.0, &error)) << error;
  EXPECT_EQ(state.params[power].v[0], 16.0);
}

}  // namespace
}  // namespace fr
