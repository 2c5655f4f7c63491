// Plugin loading against one deliberately broken fixture per failure mode: the result code and
// the message (what was wrong, what was expected) for each, and the good plugins still load.
#include "plugin/plugin_loader.hpp"
#include "plugin/plugin_library.hpp"
#include "plugin/scene_checks.hpp"
#include "plugin/scene_code.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <dlfcn.h>
#include <cmath>
#include <cstring>
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

// Readable address ranges /proc/self/maps shows for files whose name contains `name_part`.
std::vector<std::pair<uintptr_t, uintptr_t>> mapped_ranges(const std::string& name_part) {
  std::vector<std::pair<uintptr_t, uintptr_t>> ranges;
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    if (line.find(name_part) == std::string::npos) continue;
    const size_t dash = line.find('-'), space = line.find(' ');
    if (line[space + 1] != 'r') continue;
    ranges.emplace_back(std::stoull(line.substr(0, dash), nullptr, 16),
                        std::stoull(line.substr(dash + 1, space - dash - 1), nullptr, 16));
  }
  return ranges;
}

PluginPolicy in_process() {
  PluginPolicy p;
  p.isolation = PluginIsolation::None;
  return p;
}

// In-process mode (plugins.isolation = "none"), where the plugin is mapped into this process:
// the descriptor's strings are copied into host memory. No string of the SceneInfo lies inside
// the plugin's mapped image (its private copy, a memfd named fractalis-plugin), and the copied
// values survive the library being unmapped. The plugin's own literal of its id is found inside
// that image, so the range test itself is shown to be able to fail.
TEST(PluginLoader, ValidFixtureLoadsAndCopiesStrings) {
  LoadOutcome o = load_scene_plugin(fixture_plugin("valid_scene"), in_process());
  ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
  auto scene = std::move(o.scene);
  EXPECT_EQ(scene->info.id, "fixture_valid");
  EXPECT_EQ(scene->info.de_source_name, "fixture.cl");
  EXPECT_EQ(scene->info.bounding_radius, 2.0);
  EXPECT_EQ(scene->info.credit, "the Fractalis tests");  // ABI 1.2's fields
  EXPECT_EQ(scene_tags(scene->info), (std::vector<std::string>{"ifs", "test-fixture"}));

  const auto ranges = mapped_ranges("fractalis-plugin");
  ASSERT_FALSE(ranges.empty());
  auto in_library = [&](const void* p) {
    const auto a = reinterpret_cast<uintptr_t>(p);
    for (const auto& [lo, hi] : ranges)
      if (a >= lo && a < hi) return true;
    return false;
  };
  bool literal_inside = false;
  for (const auto& [lo, hi] : ranges)
    literal_inside |=
        memmem(reinterpret_cast<const void*>(lo), hi - lo, "fixture_valid", 14) != nullptr;
  EXPECT_TRUE(literal_inside);
  const SceneInfo& info = scene->info;
  std::vector<const std::string*> strings = {
      &info.id,      &info.name,        &info.version,   &info.author,
      &info.license, &info.description, &info.de_source, &info.de_source_name,
      &info.tags,    &info.credit};
  for (const ParamInfo& p : info.params)
    for (const std::string* s : {&p.key, &p.name, &p.group, &p.description}) strings.push_back(s);
  for (const std::string* s : strings)
    EXPECT_FALSE(in_library(s->data())) << "'" << *s << "' points into the plugin's image";

  const SceneInfo kept = scene->info;
  const std::string de_source = kept.de_source;
  scene.reset();
  EXPECT_TRUE(mapped_ranges("fractalis-plugin").empty()) << "still mapped";
  EXPECT_EQ(kept.id, "fixture_valid");
  EXPECT_EQ(kept.de_source, de_source);
  EXPECT_NE(kept.de_source.find("scene_de"), std::string::npos);
}

// Tags are words [a-z0-9][a-z0-9-]* separated by spaces, at most 16, none twice; anything else
// is refused with the word that broke the rule.
TEST(PluginLoader, TagRules) {
  LoadOutcome o = load_scene_plugin(fixture_plugin("valid_scene"), in_process());
  ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
  SceneInfo info = o.scene->info;
  for (const std::string ok : {"", "box", "  box   julia-set 3d ", "a b c d e f g h i j k l m n o p"}) {
    info.tags = ok;
    EXPECT_EQ(check_scene_info(info), std::nullopt) << "'" << ok << "'";
  }
  for (const auto& [bad, says] : std::vector<std::pair<std::string, std::string>>{
           {"Box", "tag 'Box' must match"},
           {"box,julia", "tag 'box,julia'"},
           {"-box", "tag '-box'"},
           {"box box", "tag 'box' appears twice"},
           {"a b c d e f g h i j k l m n o p q", "more than 16 tags"},
           {"box\tjulia", "tags is not clean text"}}) {
    info.tags = bad;
    const auto problem = check_scene_info(info);
    ASSERT_TRUE(problem.has_value()) << bad;
    EXPECT_NE(problem->find(says), std::string::npos) << *problem;
  }
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
  expect_failure("too_new_minor", LoadResult::AbiTooNew, "plugin needs ABI 1.99, host has 1.4");
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
  std::ofstream(dir / "truncated" PLUGIN_SUFFIX, std::ios::binary).write(head.data(), in.gcount());
  const LoadOutcome o = load_scene_plugin(dir / "truncated" PLUGIN_SUFFIX);
  EXPECT_EQ(o.result, LoadResult::NotLoadable);
  EXPECT_NE(o.message.find("truncated: 2000 bytes"), std::string::npos) << o.message;
}

TEST(PluginLoader, DuplicateIdNamesTheFirstFile) {
  const auto dir = test::fresh_dir("duplicate");
  std::filesystem::copy_file(fixture_plugin("valid_scene"), dir / "a" PLUGIN_SUFFIX);
  std::filesystem::copy_file(fixture_plugin("valid_scene"), dir / "b" PLUGIN_SUFFIX);
  const auto outcomes = load_scene_folder({dir});
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_EQ(outcomes[0].result, LoadResult::Loaded);
  EXPECT_EQ(outcomes[1].result, LoadResult::DuplicateId);
  EXPECT_NE(outcomes[1].message.find("duplicate scene id 'fixture_valid' (already provided by " +
                                     (dir / "a" PLUGIN_SUFFIX).string()),
            std::string::npos)
      << outcomes[1].message;
}

// A whole folder of fixtures: each bad one is reported and skipped, the good ones load.
TEST(PluginLoader, FolderSkipsBadPluginsAndKeepsGoodOnes) {
  const auto outcomes = load_scene_folder({FIXTURE_PLUGIN_DIR});
  std::map<std::string, LoadResult> by_file;
  for (const auto& o : outcomes) by_file.emplace(o.file.filename().string(), o.result);
  // Every fixture, each with its result: a missing file fails here rather than reading a default.
  const std::map<std::string, LoadResult> expected = {
      {"fixture_valid_scene" PLUGIN_SUFFIX, LoadResult::Loaded},
      {"fixture_bad_de" PLUGIN_SUFFIX, LoadResult::Loaded},  // a DE is only compiled when rendered
      {"fixture_update_error" PLUGIN_SUFFIX, LoadResult::Loaded},
      {"fixture_not_elf" PLUGIN_SUFFIX, LoadResult::NotLoadable},
      {"fixture_no_entry" PLUGIN_SUFFIX, LoadResult::NoEntrySymbol},
      {"fixture_wrong_major" PLUGIN_SUFFIX, LoadResult::WrongAbiMajor},
      {"fixture_too_new_minor" PLUGIN_SUFFIX, LoadResult::AbiTooNew},
      {"fixture_small_struct" PLUGIN_SUFFIX, LoadResult::StructTooSmall},
      {"fixture_null_id" PLUGIN_SUFFIX, LoadResult::InvalidScene},
      {"fixture_null_de" PLUGIN_SUFFIX, LoadResult::InvalidScene},
  };
  EXPECT_EQ(outcomes.size(), expected.size());
  for (const auto& [file, result] : expected) {
    const auto it = by_file.find(file);
    ASSERT_NE(it, by_file.end()) << file << " was not reported";
    EXPECT_EQ(it->second, result) << file << ": " << load_result_name(it->second);
  }
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
  EXPECT_EQ(error,
            "scene 'fixture_update_error': update failed: fixture refuses to update (its updates "
            "stop until the scene is reloaded)");
}

// In-process mode loads from a private in-memory copy: the original can go away, nothing of
// the file's name is mapped, and after the last reference is dropped the copy is unmapped.
TEST(PluginLoader, PrivateCopyAndUnmap) {
  const auto dir = test::fresh_dir("private_copy");
  std::filesystem::copy_file(fixture_plugin("valid_scene"), dir / "private_probe" PLUGIN_SUFFIX);
  LoadOutcome o = load_scene_plugin(dir / "private_probe" PLUGIN_SUFFIX, in_process());
  auto scene = std::move(o.scene);
  ASSERT_TRUE(scene) << o.message;
  std::filesystem::remove(dir / "private_probe" PLUGIN_SUFFIX);
  EXPECT_EQ(scene->info.id, "fixture_valid");
  EXPECT_TRUE(mapped_ranges("private_probe" PLUGIN_SUFFIX).empty())
      << "the user's file itself is mapped";
  auto mapped = [] { return !mapped_ranges("fractalis-plugin").empty(); };
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

// ABI compatibility. A scene built against the frozen 1.0 headers (tests/abi_1_0/) loads, updates
// (reading its light as 1.0 lays it out) and renders on this 1.1 host.
TEST(AbiCompatibility, SceneBuiltAgainst10HeadersRuns) {
  const auto file = std::filesystem::path(COMPAT_PLUGIN_DIR) / "abi10_scene" PLUGIN_SUFFIX;
  for (PluginIsolation mode : {PluginIsolation::Process, PluginIsolation::None}) {
    PluginPolicy policy;
    policy.isolation = mode;
    const LoadOutcome o = load_scene_plugin(file, policy);
    ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
    std::string error;
    auto instance = SceneInstance::create(o.scene, &error);
    ASSERT_TRUE(instance) << error;
    SceneState state = make_default_state(o.scene->info);
    ASSERT_TRUE(instance->update(state, 2.0, &error)) << error;
    EXPECT_NEAR(state.camera.eye[0], 3.5 * std::sin(0.4), 1e-12);
    Renderer renderer(test::runtime());
    RenderSettings settings;
    settings.width_px = settings.height_px = 16;
    const FrameImage image = renderer.render(o.scene->info, state, settings, true);
    EXPECT_GT(count_rays(image).hit, 0u);
  }
}

// A plugin built with this (1.1) SDK that uses nothing new declares minor 0, so a 1.0 host —
// which accepts minor <= 0 and any struct at least 1.0's size — loads it; one that uses 1.1's
// entry fields declares minor 1.
TEST(AbiCompatibility, MinorIsWhatThePluginNeedsNotTheSdks) {
  auto entry_of = [](const std::filesystem::path& file) {
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    EXPECT_TRUE(handle) << dlerror();
    const auto* entry = static_cast<const fr_scene_entry*>(dlsym(handle, FR_SCENE_ENTRY_SYMBOL));
    const fr_scene_entry copy = *entry;
    return std::make_pair(copy, handle);
  };
  auto [plain, plain_handle] = entry_of(fixture_plugin("valid_scene"));
  EXPECT_EQ(plain.abi_minor, 0u);
  EXPECT_GE(plain.struct_size, 24u);
  EXPECT_GE(plain.scene->struct_size, 160u);
  auto [v11, v11_handle] =
      entry_of(std::filesystem::path(COMPAT_PLUGIN_DIR) / "abi11_features" PLUGIN_SUFFIX);
  EXPECT_EQ(v11.abi_minor, 1u);
  // The plugin's side of the extension mechanism: an id it knows, and NULL for one it does not.
  ASSERT_TRUE(v11.get_extension);
  EXPECT_EQ(*static_cast<const int*>(v11.get_extension("fixture.answer/1")), 42);
  EXPECT_EQ(v11.get_extension("fixture.unknown/1"), nullptr);
  dlclose(plain_handle);
  dlclose(v11_handle);
}

// ABI 1.1's host side: init gets the plugin's path as the user named it and the host's name and
// version, the host's extension lookup gives the thread-safe log (and NULL for an unknown id),
// a message logged from another thread arrives with the update's answer, and lights are found
// through FR_FRAME_LIGHT.
TEST(AbiCompatibility, Abi11InitExtensionsAndThreadLog) {
  const auto file = std::filesystem::path(COMPAT_PLUGIN_DIR) / "abi11_features" PLUGIN_SUFFIX;
  for (PluginIsolation mode : {PluginIsolation::Process, PluginIsolation::None}) {
    PluginPolicy policy;
    policy.isolation = mode;
    const LoadOutcome o = load_scene_plugin(file, policy);
    ASSERT_EQ(o.result, LoadResult::Loaded) << o.message;
    uint64_t handle = 0;
    ASSERT_TRUE(o.scene->code->create(&handle).ok);
    SceneState state = make_default_state(o.scene->info);
    const CallOutcome out = o.scene->code->update(handle, state);
    ASSERT_TRUE(out.ok) << out.error;
    bool found = false;
    for (const PluginMessage& m : out.messages)
      found |= m.text == "init by fractalis " FRACTALIS_VERSION " for " + file.string();
    EXPECT_TRUE(found) << "the worker thread's message did not arrive";
    o.scene->code->destroy(handle);
  }
}

}  // namespace
}  // namespace fr
