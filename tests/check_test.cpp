// `fractalis check` as an author runs it: every in-tree scene passes (exit 0), and each broken
// fixture fails exactly the check that names its fault (exit 1), with JSON that says the same.
#include "in_tree_scenes.hpp"
#include "test_support.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace fr {
namespace {

const bool kWindows = std::filesystem::path::preferred_separator == '\\';

struct CheckRun {
  int exit_code = -1;
  std::string out;
  std::string json;
};

CheckRun run_check(const std::filesystem::path& plugin,
                   const std::vector<std::string>& extra = {}) {
  const auto dir = test::fresh_dir("check_" + plugin.stem().string());
  const auto json = dir / "check.json";
  std::vector<std::string> args = {"check", plugin.string(), "--json", json.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::ProgramRun run = test::run_fractalis(args);
  CheckRun r;
  r.exit_code = run.exit_code;
  r.out = run.output;
  r.json = test::read_file(json);
  return r;
}

// The status the table gives a check ("PASS", "WARN", "FAIL"), or "" when it is not there.
std::string status_of(const std::string& table, const std::string& check) {
  std::istringstream in(table);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string name, status;
    if (words >> name >> status && name == check) return status;
  }
  return "";
}

TEST(Check, EnoughInTreeScenes) {
  const std::vector<std::string> scenes = test::scene_ids_for_this_platform();
  ASSERT_GE(scenes.size(), 12u);
  if (!std::getenv("FRACTALIS_TEST_SCENES") && !kWindows) {
    ASSERT_GE(scenes.size(), 40u);
  }
}

// Every in-tree scene passes every check. One test per scene, so that CTest's shards of this
// program (tests/CMakeLists.txt) run them side by side: each check is mostly one process
// compiling kernels on one core.
// The over-estimate checks WARN at any measurable share, and some in-tree DEs are estimates that
// run long at a few points (the Mandelbulb's near thin features, the Kleinian's): those may
// WARN, never FAIL. A DE that is a true lower bound by construction (the Menger sponge's exact
// distance; folding IFS, whose folds and scalings cannot lengthen a distance) passes them.
class EveryInTreeScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryInTreeScene, PassesEveryCheck) {
  const std::string scene = GetParam();
  const CheckRun r = run_check(std::filesystem::path(SCENE_PLUGIN_DIR) / (scene + PLUGIN_SUFFIX));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  for (const char* check : {"descriptor", "de-compiles", "de-returns", "de-finite", "de-lipschitz",
                            "de-bounded", "wide-lanes", "lanes-agree", "update", "create-destroy",
                            "render", "unload"})
    EXPECT_EQ(status_of(r.out, check), "PASS") << check << "\n" << r.out;
  const bool lower_bound = scene == "menger" || scene == "sierpinski" ||
                           scene.rfind("kifs_", 0) == 0;
  for (const char* check : {"de-overestimate", "de-near-surface", "render-careful"}) {
    const std::string status = status_of(r.out, check);
    if (lower_bound)
      EXPECT_EQ(status, "PASS") << check << "\n" << r.out;
    else
      EXPECT_TRUE(status == "PASS" || status == "WARN") << check << "\n" << r.out;
  }
  const auto json = nlohmann::json::parse(r.json);
  EXPECT_EQ(json["result"], "pass") << r.json;
  EXPECT_EQ(json["scene"], scene);
}

INSTANTIATE_TEST_SUITE_P(Check, EveryInTreeScene,
                         ::testing::ValuesIn(test::scene_ids_for_this_platform()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

// The in-tree Menger sponge, whose DE is the exact distance outside the sponge, with that DE
// multiplied by 1.25, 1.5 and 3 (tests/CMakeLists.txt generates them from plugins/menger):
// de-overestimate fails each, and the worst over-estimate it reports is the factor (at most the
// factor over the surface threshold's 99/100); render-careful, coarser, fails the 3x one.
TEST(Check, OverEstimatingDeFails) {
  for (const auto& [tag, factor] :
       std::vector<std::pair<std::string, double>>{{"1_25", 1.25}, {"1_5", 1.5}, {"3", 3.0}}) {
    SCOPED_TRACE(tag);
    const CheckRun r = run_check(std::filesystem::path(OVERESTIMATE_PLUGIN_DIR) /
                                 ("overestimate_menger_x" + tag + PLUGIN_SUFFIX));
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_EQ(status_of(r.out, "de-overestimate"), "FAIL") << r.out;
    EXPECT_EQ(status_of(r.out, "render"), "PASS") << "only the DE is wrong\n" << r.out;
    // The render comparison is coarse (grazing rays count): only three times too long fails it.
    if (factor == 3) {
      EXPECT_EQ(status_of(r.out, "render-careful"), "FAIL") << r.out;
    }
    const std::string tail = "x too far";
    const size_t at = r.out.find(tail);
    ASSERT_NE(at, std::string::npos) << r.out;
    const size_t start = r.out.rfind(' ', at) + 1;
    const double worst = std::stod(r.out.substr(start, at - start));
    EXPECT_GE(worst, 0.99 * factor) << r.out;
    EXPECT_LE(worst, factor * 100 / 99) << r.out;
    bool named = false;
    const auto json = nlohmann::json::parse(r.json);
    for (const auto& row : json["checks"])
      if (row["check"] == "de-overestimate")
        named = row["status"] == "fail" &&
                row["detail"].get<std::string>().find("over-estimates") != std::string::npos;
    EXPECT_TRUE(named) << r.json;
  }
}

// Cantor's dust and the icosahedral KIFS with their DE multiplied by 1.5 and 3, and the Mandelbox
// by 3 (tests/CMakeLists.txt generates them from the scenes' own sources), fail de-near-surface:
// near the surface each steps past it. Over the Mandelbox's bounding sphere its DE
// under-estimates several-fold, which is why a check that samples only there let 3x pass. The
// Mandelbox times 1.5 is a warning, not a failure: near its surface the Mandelbox's DE is at most
// 0.82 of the distance (typically a third), so 1.5x of it still stops short of the surface but
// at a fraction of a percent of the points. The unscaled scenes pass (EveryInTreeScene).
TEST(Check, DeThatOverestimatesNearTheSurfaceFails) {
  for (const auto& [scene, tag] :
       std::vector<std::pair<std::string, std::string>>{{"cantor_dust", "1_5"},
                                                        {"cantor_dust", "3"},
                                                        {"kifs_icosahedron", "1_5"},
                                                        {"kifs_icosahedron", "3"},
                                                        {"mandelbox", "3"}}) {
    SCOPED_TRACE(scene + " x" + tag);
    const CheckRun r = run_check(std::filesystem::path(OVERESTIMATE_PLUGIN_DIR) /
                                 ("overestimate_" + scene + "_x" + tag + PLUGIN_SUFFIX));
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_EQ(status_of(r.out, "de-near-surface"), "FAIL") << r.out;
    EXPECT_NE(r.out.find("(the DE steps past the surface)"), std::string::npos) << r.out;
  }
  // Times 1.5 the Mandelbox oversteps at a fraction of a percent of the points: a WARN naming
  // the share and the worst point, not a failure (exit 0).
  const CheckRun box = run_check(std::filesystem::path(OVERESTIMATE_PLUGIN_DIR) /
                                 ("overestimate_mandelbox_x1_5" PLUGIN_SUFFIX));
  EXPECT_EQ(box.exit_code, 0) << box.out;
  EXPECT_EQ(status_of(box.out, "de-near-surface"), "WARN") << box.out;
  EXPECT_NE(box.out.find("; worst: DE "), std::string::npos) << box.out;
}

// A material function is checked where the render saw surface: the material ball's defaults lie
// in the material's ranges; at a preset whose metalness is 1.5 (its parameter allows up to 2),
// the check fails naming the field, the value and a point on the ball.
TEST(Check, AMaterialOutsideItsRangesFails) {
  const auto dir = test::folder_of_one_scene("check_material", TEST_SCENE_DIR, "material_ball");
  std::filesystem::create_directories(dir / "presets");
  std::ofstream(dir / "presets" / "too_metal.toml")
      << "scene = \"material_ball\"\nname = \"Too metal\"\n[params]\nmetalness = 1.5\n";
  const auto plugin = dir / ("material_ball" PLUGIN_SUFFIX);
  const CheckRun fine = run_check(plugin);
  EXPECT_EQ(fine.exit_code, 0) << fine.out;
  EXPECT_EQ(status_of(fine.out, "material"), "PASS") << fine.out;
  const CheckRun bad = run_check(plugin, {"--preset", "too_metal"});
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  EXPECT_EQ(status_of(bad.out, "material"), "FAIL") << bad.out;
  EXPECT_NE(bad.out.find("scene_material returns metalness = 1.5 at ("), std::string::npos)
      << bad.out;
  EXPECT_EQ(status_of(bad.out, "render"), "PASS") << "only the material is wrong\n" << bad.out;
}

// The compatibility scene, built against the frozen ABI 1.0 headers, passes on this 1.1 host.
TEST(Check, SceneBuiltAgainstAbi10Passes) {
  const CheckRun r =
      run_check(std::filesystem::path(COMPAT_PLUGIN_DIR) / "abi10_scene" PLUGIN_SUFFIX);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(status_of(r.out, "render"), "PASS") << r.out;
}

// Every broken fixture (the loader's, the hostile ones and the check-only ones) fails the check
// named after its fault, and the checks before that one pass. Short time limits keep the hanging
// ones quick.
TEST(Check, EveryBrokenFixtureFailsItsCheck) {
  const std::filesystem::path check_dir = CHECK_PLUGIN_DIR, hostile_dir = HOSTILE_PLUGIN_DIR;
  auto hostile = [&](const char* name) {
    return hostile_dir / ("hostile_" + std::string(name) + PLUGIN_SUFFIX);
  };
  const char* const kCrashed = kWindows ? "crashed (access violation)" : "crashed (SIG";
  const std::map<std::filesystem::path, std::pair<std::string, std::string>> cases = {
      // fixtures/plugins, as the loader sees them
      {test::fixture_plugin("not_elf"),
       {"descriptor", kWindows ? "not a Windows DLL" : "not an ELF shared library"}},
      {test::fixture_plugin("no_entry"), {"descriptor", "no exported symbol"}},
      {test::fixture_plugin("wrong_major"), {"descriptor", "wrong ABI major: plugin 2, host 1"}},
      {test::fixture_plugin("too_new_minor"), {"descriptor", "plugin needs ABI 1.99"}},
      {test::fixture_plugin("small_struct"), {"descriptor", "struct_size 8"}},
      {test::fixture_plugin("null_id"), {"descriptor", "scene id is null"}},
      {test::fixture_plugin("null_de"), {"descriptor", "de_source is null"}},
      {test::fixture_plugin("bad_de"), {"de-compiles", "fixture.cl:3:"}},
      {test::fixture_plugin("update_error"), {"update", "fixture refuses to update"}},
      // hostile plugins (Windows: abort() exits with status 3, and the loader turns a fault in a
      // DLL's initialisation into a failed LoadLibrary)
      {hostile("ctor_abort"),
       {"descriptor", kWindows ? "exited with status 3" : "crashed (SIGABRT"}},
      {hostile("ctor_segv"),
       {"descriptor", kWindows ? "No access to memory location" : "crashed (SIG"}},
      {hostile("ctor_loop"), {"descriptor", "did not answer within 2 s"}},
      {hostile("ctor_exit"), {"descriptor", "exited with status 0"}},
      {hostile("absurd_counts"), {"descriptor", "param_count 2000000000 is more than 256"}},
      {hostile("too_many_lights"), {"descriptor", "light_count 9"}},
      {hostile("escape_name"), {"descriptor", "control character 0x1b"}},
      {hostile("invalid_utf8"), {"descriptor", "invalid UTF-8 at byte 3"}},
      {hostile("reserved_nonzero"), {"descriptor", "reserved is not zero"}},
      {hostile("missing_dep"), {"descriptor", "libfixture_missing_dep_lib" PLUGIN_SUFFIX}},
      {hostile("create_crash"), {"update", kCrashed}},
      {hostile("create_hang"), {"update", "did not answer within 0.5 s"}},
      {hostile("create_throw"), {"update", "create threw a C++ exception"}},
      {hostile("update_crash"), {"update", kCrashed}},
      {hostile("update_throw"), {"update", "update threw a C++ exception"}},
      {hostile("update_exit"), {"update", "exited with status 0"}},
      {hostile("update_hang_later"), {"update", "did not answer within 0.5 s"}},
      {hostile("update_bad_camera"), {"update", "invalid camera"}},
      {hostile("de_loop"), {"de-returns", "did not finish within 8 s"}},
      // faults only `check` looks for
      {check_dir / "check_de_nan" PLUGIN_SUFFIX, {"de-finite", "DE is nan"}},
      {check_dir / "check_de_overstep" PLUGIN_SUFFIX, {"de-lipschitz", "the DE oversteps"}},
      {check_dir / "check_de_pairs_in_double" PLUGIN_SUFFIX,
       {"de-pairs", "is it computed in pairs?"}},
      {check_dir / "check_surface_outside" PLUGIN_SUFFIX,
       {"de-bounded", "outside the bounding radius 0.8"}},
      {check_dir / "check_nondeterministic" PLUGIN_SUFFIX, {"update", "not deterministic"}},
      {check_dir / "check_create_leak" PLUGIN_SUFFIX,
       {"create-destroy", "bytes per create/destroy"}},
      {check_dir / "check_thread_leak" PLUGIN_SUFFIX,
       {"unload", "thread(s) of the plugin still run"}},
      {check_dir / "check_blank" PLUGIN_SUFFIX,
       {"render", "nothing visible from the default camera"}},
      {check_dir / "check_wrong_entry" PLUGIN_SUFFIX,
       {"de-compiles", "defines no `real_t scene_de("}},
  };
  const std::vector<std::string> limits = {"--set", "plugins.load_timeout_s=2",
                                           "--set", "plugins.call_timeout_s=0.5",
                                           "--set", "plugins.vet_timeout_s=8"};
  for (const auto& [plugin, expected] : cases) {
    SCOPED_TRACE(plugin.filename().string());
    const CheckRun r = run_check(plugin, limits);
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_EQ(status_of(r.out, expected.first), "FAIL") << r.out;
    EXPECT_NE(r.out.find(expected.second), std::string::npos) << r.out;
    EXPECT_EQ(nlohmann::json::parse(r.json)["result"], "fail") << r.json;
    if (expected.first != "descriptor") {
      EXPECT_EQ(status_of(r.out, "descriptor"), "PASS") << r.out;
    }
  }
  // A plugin that floods the log, but does nothing wrong, passes.
  const CheckRun flood = run_check(hostile("log_flood"), limits);
  EXPECT_EQ(flood.exit_code, 0) << flood.out;
}

// A DE that builds at 16 lanes but not at 64 (it calls a built-in wide_lanes.cl does not
// overload) is not a failure: the check warns, the other checks run at the widths that build, and
// the render falls back to 16-lane packets.
TEST(Check, SceneThatBuildsOnlyNarrowIsWarned) {
  const std::filesystem::path plugin =
      std::filesystem::path(CHECK_PLUGIN_DIR) / ("check_narrow_only" PLUGIN_SUFFIX);
  const CheckRun r = run_check(plugin);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(status_of(r.out, "wide-lanes"), "WARN") << r.out;
  EXPECT_NE(r.out.find("does not build at 64 lanes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ldexp"), std::string::npos) << r.out;
  for (const char* check : {"de-compiles", "lanes-agree", "render"})
    EXPECT_EQ(status_of(r.out, check), "PASS") << check << "\n" << r.out;
  EXPECT_NE(r.out.find("widths 1 and 16 agree"), std::string::npos) << r.out;
}

TEST(Check, UsageErrors) {
  EXPECT_EQ(test::run_fractalis({"check"}).exit_code, 2);
  const test::ProgramRun unknown =
      test::run_fractalis({"check", "x" PLUGIN_SUFFIX, "--frobnicate"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.output.find("--frobnicate"), std::string::npos) << unknown.output;
}

}  // namespace
}  // namespace fr
