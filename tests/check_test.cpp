// `fractalis check` as an author runs it: every in-tree scene passes (exit 0), and each broken
// fixture fails exactly the check that names its fault (exit 1), with JSON that says the same.
#include "test_support.hpp"

#include <sys/wait.h>

#include <fstream>
#include <map>
#include <sstream>

namespace fr {
namespace {

struct CheckRun {
  int exit_code = -1;
  std::string out;
  std::string json;
};

CheckRun run_check(const std::filesystem::path& plugin, const std::string& extra = "") {
  const auto dir = test::fresh_dir("check_" + plugin.stem().string());
  const auto out = dir / "out.txt", json = dir / "check.json";
  const std::string command = std::string(FRACTALIS_EXECUTABLE) + " check " + plugin.string() +
                              " --json " + json.string() + " " + extra + " > " + out.string() +
                              " 2>&1";
  const int status = std::system(command.c_str());
  CheckRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream o(out), j(json);
  std::stringstream os, js;
  os << o.rdbuf();
  js << j.rdbuf();
  r.out = os.str();
  r.json = js.str();
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

TEST(Check, EveryInTreeScenePasses) {
  for (const char* scene : {"mandelbulb", "menger", "sierpinski", "julia", "benchmark"}) {
    SCOPED_TRACE(scene);
    const CheckRun r =
        run_check(std::filesystem::path(SCENE_PLUGIN_DIR) / (std::string(scene) + ".so"));
    EXPECT_EQ(r.exit_code, 0) << r.out;
    for (const char* check :
         {"descriptor", "de-compiles", "de-returns", "de-finite", "de-lipschitz", "de-bounded",
          "lanes-agree", "update", "create-destroy", "render", "unload"})
      EXPECT_EQ(status_of(r.out, check), "PASS") << check << "\n" << r.out;
    EXPECT_NE(r.json.find("\"result\": \"pass\""), std::string::npos) << r.json;
    EXPECT_NE(r.json.find("\"scene\": \"" + std::string(scene) + "\""), std::string::npos);
  }
}

// The compatibility scene, built against the frozen ABI 1.0 headers, passes on this 1.1 host.
TEST(Check, SceneBuiltAgainstAbi10Passes) {
  const CheckRun r = run_check(std::filesystem::path(COMPAT_PLUGIN_DIR) / "abi10_scene.so");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(status_of(r.out, "render"), "PASS") << r.out;
}

// Each broken plugin fails the check named after its fault; the checks before it pass.
TEST(Check, EachBrokenFixtureFailsItsCheck) {
  const std::filesystem::path check_dir = CHECK_PLUGIN_DIR, hostile = HOSTILE_PLUGIN_DIR;
  const std::map<std::filesystem::path, std::pair<std::string, std::string>> cases = {
      {check_dir / "check_de_nan.so", {"de-finite", "DE is nan"}},
      {check_dir / "check_de_overstep.so", {"de-lipschitz", "the DE oversteps"}},
      {check_dir / "check_surface_outside.so", {"de-bounded", "outside the bounding radius 0.8"}},
      {check_dir / "check_nondeterministic.so", {"update", "not deterministic"}},
      {check_dir / "check_create_leak.so", {"create-destroy", "bytes per create/destroy"}},
      {check_dir / "check_thread_leak.so", {"unload", "thread(s) of the plugin still run"}},
      {check_dir / "check_blank.so", {"render", "nothing visible from the default camera"}},
      {test::fixture_plugin("bad_de"), {"de-compiles", "fixture.cl:3:"}},
      {test::fixture_plugin("wrong_major"), {"descriptor", "wrong ABI major: plugin 2, host 1"}},
      {test::fixture_plugin("update_error"), {"update", "fixture refuses to update"}},
      {hostile / "hostile_update_crash.so", {"update", "crashed (SIG"}},
      {hostile / "hostile_ctor_abort.so", {"descriptor", "crashed (SIGABRT"}},
      {hostile / "hostile_de_loop.so", {"de-returns", "did not finish within 8 s"}},
  };
  for (const auto& [plugin, expected] : cases) {
    SCOPED_TRACE(plugin.filename().string());
    const CheckRun r = run_check(plugin, "--set plugins.vet_timeout_s=8");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_EQ(status_of(r.out, expected.first), "FAIL") << r.out;
    EXPECT_NE(r.out.find(expected.second), std::string::npos) << r.out;
    EXPECT_NE(r.json.find("\"result\": \"fail\""), std::string::npos) << r.json;
    if (expected.first != "descriptor") {
      EXPECT_EQ(status_of(r.out, "descriptor"), "PASS") << r.out;
    }
  }
}

TEST(Check, UsageErrors) {
  EXPECT_EQ(
      std::system((std::string(FRACTALIS_EXECUTABLE) + " check > /dev/null 2>&1").c_str()) >> 8, 2);
  EXPECT_EQ(
      std::system((std::string(FRACTALIS_EXECUTABLE) + " check x.so --frobnicate > /dev/null 2>&1")
                      .c_str()) >>
          8,
      2);
}

}  // namespace
}  // namespace fr
