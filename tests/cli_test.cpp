// The CLI's error paths: every wrong option or value gets one line naming it and exit code 2.
#include "cli/cli.hpp"
#include "cli_run.hpp"
#include "in_tree_scenes.hpp"
#include "plugin/scene_instance.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fr {
namespace {

using test::CliRun;
using test::expect_usage_error;
using test::run;

TEST(Cli, UsageErrors) {
  expect_usage_error({"frobnicate"}, "unknown command 'frobnicate'");
  expect_usage_error({"render", "--bogus"}, "unknown option '--bogus'");
  expect_usage_error({"render", "--out"}, "option '--out' needs a value");
  // Output paths are refused before any work: the benchmark would otherwise run first.
  expect_usage_error({"bench", "--json", "/no/such/folder/b.json"},
                     "--json: folder '/no/such/folder' does not exist");
  expect_usage_error({"bench", "--json", TEST_OUTPUT_DIR}, "is a folder, not a file");
  expect_usage_error({"render", "--out", TEST_OUTPUT_DIR}, "is a folder, not a file");
  // Forty scenes are too many for one line: the count, and the ids that look like the typo.
  expect_usage_error({"render", "--scene", "nope"},
                     "unknown scene 'nope' (" + std::to_string(test::in_tree_scene_ids().size()) +
                         " scenes, `fractalis list` shows them)");
  expect_usage_error({"render", "--scene", "mandelbix"},
                     "scenes, `fractalis list` shows them; did you mean: mandelbox");
  expect_usage_error({"render", "--scene", "kifs"},
                     "did you mean: kifs_cube, kifs_dodecahedron, kifs_icosahedron, "
                     "kifs_octahedron, kifs_tetrahedron)");
  expect_usage_error({"render", "--param", "nokey=1"}, "has no parameter 'nokey'");
  expect_usage_error({"render", "--param", "power"}, "expected KEY=VALUE");
  expect_usage_error({"render", "--band-rows", "0"}, "--band-rows: 0 is outside [1, 65535]");
  expect_usage_error({"render", "--band-rows", "12x"}, "--band-rows: '12x' is not a whole number");
  expect_usage_error({"render", "--size", "64x40", "--band-rows", "8", "--counts"},
                     "--counts: not for images rendered in bands");
  expect_usage_error({"render", "--param", "power=nan"}, "'nan' is not a finite number");
  expect_usage_error({"render", "--param", "power=inf"}, "is not a finite number");
  expect_usage_error({"render", "--param", "power=abc"}, "'abc' is not a number");
  expect_usage_error({"render", "--param", "power=40"}, "outside the range of 'power'");
  expect_usage_error({"render", "--param", "iterations=2.5"}, "not a whole number");
  expect_usage_error({"render", "--param", "animate_power=maybe"}, "expected true or false");
  expect_usage_error({"render", "--size", "0x10"}, "--size width: 0 is outside [1, 65535]");
  expect_usage_error({"render", "--size", "100000x100000"}, "outside [1, 65535]");
  expect_usage_error({"render", "--size", "10x65536"},
                     "--size height: 65536 is outside [1, 65535]");
  expect_usage_error({"bench", "--size", "16385x10"}, "outside [1, 16384]");
  expect_usage_error({"render", "--size", "big"}, "is not WIDTHxHEIGHT");
  expect_usage_error({"render", "--eye", "1,2,3", "--target", "1,2,3"},
                     "camera: target equals eye");
  expect_usage_error({"render", "--eye", "1,2"}, "not three comma-separated numbers");
  expect_usage_error({"render", "--up", "0,0,0"}, "--up: 0,0,0 has no direction");
  expect_usage_error({"render", "--up", "0,nan,1"}, "is not a finite number");
  expect_usage_error({"render", "--fov", "200"}, "outside (0, 180) degrees");
  expect_usage_error({"render", "--lanes", "3"}, "--lanes: expected 1, 4, 8, 16, 32 or 64");
  expect_usage_error({"render", "--precision", "half"}, "expected auto, float, double or dd");
  expect_usage_error({"render", "--integrator", "photon"},
                     "--integrator: expected fast or path, got 'photon'");
  expect_usage_error({"render", "--set", "render.integrator=\"paths\""}, "render.integrator");
  expect_usage_error({"render", "--integrator", "path", "--samples", "0"},
                     "--samples: 0 is outside");
  expect_usage_error({"render", "--integrator", "path", "--samples", "1000000000000"},
                     "--samples: 1000000000000 is outside");
  expect_usage_error({"render", "--device", "no-such-device"},
                     "--device no-such-device: matches no device");
  expect_usage_error({"render", "--plugins", "/no/such/folder"},
                     "--plugins: '/no/such/folder' is not a folder");
  expect_usage_error({"render", "--config", "/no/such/file.toml"}, "--config: no such file");
  expect_usage_error({"bench", "--frames", "0"}, "--frames: 0 is outside");
  expect_usage_error({"list", "--size", "1x1"}, "unknown option '--size' for 'list'");
  expect_usage_error({"render", "--set", "render.lanse=16"},
                     "key 'render.lanse': unknown key (did you mean 'render.lanes'?)");
  expect_usage_error({"render", "--set", "render.shading_model=phong"},
                     "expected one of \"lambert\", \"blinn-phong\", \"oren-nayar\"");
  expect_usage_error({"render", "--set", "render.effects.fog=maybe"}, "render.effects.fog");
  expect_usage_error({"render", "--samples", "0"}, "--samples: 0 is outside [1, 4096]");
  expect_usage_error({"render", "--out", "/no/such/folder/x.png"},
                     "--out: folder '/no/such/folder' does not exist");
  expect_usage_error({"bench", "--runs", "0"}, "--runs: 0 is outside");
  expect_usage_error({"bench", "--explore", "--scene", "nope"}, "unknown scene 'nope'");
  expect_usage_error({"bench", "--counts"}, "--counts: only with --explore");
  // --config names what it got when that is not a file.
  expect_usage_error({"render", "--config", TEST_OUTPUT_DIR}, "is a folder, not a settings file");
  expect_usage_error({"render", "--config", NULL_DEVICE}, "'" NULL_DEVICE "' is a device");
}

// Values are quoted back cut short, with their length, and with control characters escaped.
TEST(Cli, LongAndHostileValuesAreEchoedShort) {
  const std::string huge(100000, 'k');
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"render", "--scene", huge},
           {"render", "--set", huge + "=1"},
           {"render", "--set", "render." + huge + "=1"},
           {"render", "--param", huge},
           {"render", "--size", huge},
           {"render", "--out", "/no/such/" + huge + "/x.png"},
           {huge},
       }) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 2);
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
    EXPECT_NE(r.err.find(" bytes)"), std::string::npos) << r.err.substr(0, 400);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err.substr(0, 400);
  }
  // A measurement never runs with a setting that does not exist (bench --explore as render).
  for (const std::string command : {"render", "bench"}) {
    std::vector<std::string> args = {command, "--set", "render.nonsense=1"};
    if (command == "bench") args.push_back("--explore");
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 2) << command;
    EXPECT_NE(r.err.find("render.nonsense"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("unknown key"), std::string::npos) << r.err;
  }
  const CliRun escape = run({"render", "--scene", "\x1b]0;owned\x07"});
  EXPECT_EQ(escape.code, 2);
  EXPECT_NE(escape.err.find("unknown scene '\\x1b]0;owned\\x07'"), std::string::npos) << escape.err;
  // A C1 control (CSI as U+009B, which some terminals obey) and a byte that is not UTF-8.
  const CliRun c1 = run({"render", "--scene",
                         "a\xc2\x9b"
                         "2Jb\xff"});
  EXPECT_EQ(c1.code, 2);
  EXPECT_NE(c1.err.find("unknown scene 'a\\xc2\\x9b"
                        "2Jb\\xff'"),
            std::string::npos)
      << c1.err;
}

// render --path: a keyframe's time renders exactly what that keyframe's view and parameters
// given as options render; half-way is neither; a bad file is FILE:LINE and exit code 2.
TEST(Cli, RenderAtATimeOfACameraPath) {
  const auto dir = test::fresh_dir("cli_path");
  const auto path = dir / "path.toml";
  std::ofstream(path) << "[[keyframe]]\ntime_s = 0\neye = [0.5, -2.5, 1.2]\n"
                         "target = [0, 0, 0]\n[keyframe.params]\npower = 6\n"
                         "[[keyframe]]\ntime_s = 2\neye = [2.6, 0.3, 0.4]\ntarget = [0, 0.1, 0]\n"
                         "fov_deg = 30\n";
  auto png = [&](const char* name) { return (dir / name).string(); };
  const std::vector<std::string> common = {"render", "--scene", "mandelbulb", "--size", "48x32"};
  auto render = [&](std::vector<std::string> extra, const char* name) {
    std::vector<std::string> args = common;
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"--out", png(name)});
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return test::read_file(png(name));
  };
  const std::string at_start = render({"--path", path.string()}, "start.png");
  const std::string by_hand =
      render({"--eye", "0.5,-2.5,1.2", "--target", "0,0,0", "--param", "power=6"}, "hand.png");
  EXPECT_FALSE(at_start.empty());
  EXPECT_EQ(at_start, by_hand) << "the first keyframe is the view it names";
  const std::string at_end = render({"--path", path.string(), "--time", "2"}, "end.png");
  const std::string end_by_hand =
      render({"--eye", "2.6,0.3,0.4", "--target", "0,0.1,0", "--fov", "30", "--param", "power=6"},
             "end_hand.png");
  EXPECT_EQ(at_end, end_by_hand) << "power 6 carries over to the second keyframe";
  EXPECT_NE(render({"--path", path.string(), "--time", "1"}, "mid.png"), at_start);
  std::ofstream(dir / "bad.toml") << "[[keyframe]]\ntime_s = 0\neye = [0, 0, 3]\n"
                                     "target = [0, 0, 0]\n";
  expect_usage_error({"render", "--path", (dir / "bad.toml").string()},
                     "bad.toml:1: a path needs at least two keyframes");
}

// Over 8 M pixels, render goes in bands and streams the PNG: it says so, and the file decodes to
// the size asked for.
TEST(Cli, LargeRenderGoesInBands) {
  const auto file = test::fresh_dir("cli_poster") / "big.png";
  const CliRun r =
      run({"render", "--scene", "menger", "--size", "4000x2200", "--out", file.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rendered menger 4000x2200 in 2 bands"), std::string::npos) << r.out;
  int w = 0, h = 0, channels = 0;
  ASSERT_TRUE(stbi_info(file.string().c_str(), &w, &h, &channels));
  EXPECT_EQ(w, 4000);
  EXPECT_EQ(h, 2200);
}

TEST(Cli, HelpAndVersion) {
  for (const char* command : {"render", "bench", "list", "devices"}) {  // every command has --help
    const CliRun r = run({command, "--help"});
    EXPECT_EQ(r.code, 0) << command;
    EXPECT_NE(r.out.find(std::string("usage: fractalis ") + command), std::string::npos) << r.out;
  }
  // Every command --help lists has its own --help, and an unknown name's error names it (the
  // list is one table in cli.cpp; the error once lacked `animate`).
  const CliRun help = run({"--help"});
  const CliRun unknown = run({"frobnicate"});
  const size_t first = help.out.find("commands:\n"), last = help.out.find("\n\n", first);
  ASSERT_NE(first, std::string::npos);
  std::istringstream lines(help.out.substr(first + 10, last - first - 10));
  int listed = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    ++listed;
    EXPECT_NE(unknown.err.find(name), std::string::npos)
        << name << " missing from: " << unknown.err;
    if (name == "explore") continue;  // its --help is checked by the explorer's own tests
    const CliRun r = run({name, "--help"});
    EXPECT_EQ(r.code, 0) << name;
    EXPECT_NE(r.out.find("usage: fractalis " + name), std::string::npos) << r.out;
  }
  EXPECT_EQ(listed, 12);
  const CliRun v = run({"--version"});
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.out.find("scene ABI 1.4"), std::string::npos);
  EXPECT_EQ(run({}).code, 2);
}

// The written PNG is read back: its size, and the picture a headless render of the same scene,
// view and parameter gives (the CLI passes --size and --param through); and the parameter
// visibly matters (the default power renders a different picture).
TEST(Cli, RenderWritesThePng) {
  const auto dir = test::fresh_dir("cli_render");
  const auto file = (dir / "small.png").string();
  const CliRun r = run({"render", "--size", "48x32", "--out", file, "--param", "power=6"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + file), std::string::npos);
  const test::LoadedPng png = test::load_png(file);
  ASSERT_EQ(png.width_px, 48);
  ASSERT_EQ(png.height_px, 32);

  auto scene = test::mandelbulb();
  ASSERT_TRUE(scene);
  SceneState state = make_default_state(scene->info);
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  ASSERT_TRUE(instance) << error;
  RenderSettings settings;
  settings.width_px = 48;
  settings.height_px = 32;
  Renderer renderer(test::runtime());
  ASSERT_TRUE(instance->update(state, 0, &error)) << error;
  const FrameImage power8 = renderer.render(scene->info, state, settings);
  state.params[scene->info.find_param("power")].v[0] = 6;
  ASSERT_TRUE(instance->update(state, 0, &error)) << error;
  const FrameImage power6 = renderer.render(scene->info, state, settings);
  EXPECT_LE(test::pixels_differing(png.rgba8, power6.rgba8, 2), 48 * 32 / 100)
      << "the PNG is not the headless render of the same view";
  EXPECT_GT(test::pixels_differing(power6.rgba8, power8.rgba8, 8), 48 * 32 / 20)
      << "power 6 and 8 should look different";
}

// The explorer's fly-through, counting: the moving frames' DE evaluations by stage, a plausible
// total (the primary march and the normals, six evaluations per hit, at least), busy lanes.
TEST(Cli, ExploreBenchCountsTheMovingFrames) {
  const CliRun r = run({"bench", "--explore", "--counts", "--size", "96x54", "--frames", "4",
                        "--set", "explorer.quality=\"fast\""});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto at = r.out.find("while moving");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string counts = r.out.substr(at);
  for (const char* stage : {"primary  march", "primary  normals", "total"})
    EXPECT_NE(counts.find(stage), std::string::npos) << stage << " missing:\n" << counts;
  double total = 0, busy = 0;
  const auto line = counts.find("total");
  ASSERT_EQ(std::sscanf(counts.c_str() + line, "total %lf %lf%%", &total, &busy), 2) << counts;
  EXPECT_GT(total, 1.0) << counts;
  EXPECT_LT(total, 200.0) << counts;
  EXPECT_GT(busy, 10.0);
  EXPECT_LE(busy, 100.0);
  // Without --counts, no counting.
  const CliRun plain = run({"bench", "--explore", "--size", "96x54", "--frames", "2"});
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("while moving"), std::string::npos) << plain.out;
}

// --error judges each moving frame as the window showed it (a half-size frame stretched, with
// 60% of the steps: bench/image_error.hpp) against a fully traced one of the same camera: some
// error, never more than full scale, each worst frame at least as bad as the mean.
TEST(Cli, ExploreBenchJudgesTheShownFrames) {
  const auto dir = test::fresh_dir("cli_explore_error");
  const std::string prefix = (dir / "f-").string();
  const CliRun r = run({"bench", "--explore", "--error", "--size", "96x54", "--frames", "3",
                        "--set", "explorer.quality=\"fast\"", "--save-frame", "2:" + prefix});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto at = r.out.find("shown while moving");
  ASSERT_NE(at, std::string::npos) << r.out;
  int frames = 0;
  double mae = -1, worst_mae = -1, ssim = 2, worst_ssim = 2;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at,
                        "shown while moving, against fully traced frames (%d frames): mean "
                        "absolute error %lf (worst frame %lf), SSIM %lf (worst frame %lf)",
                        &frames, &mae, &worst_mae, &ssim, &worst_ssim),
            5)
      << r.out;
  EXPECT_EQ(frames, 3);
  EXPECT_GT(mae, 0);
  EXPECT_GE(worst_mae, mae);
  EXPECT_LE(worst_mae, 1);
  EXPECT_LT(ssim, 1);
  EXPECT_LE(worst_ssim, ssim);
  EXPECT_GE(worst_ssim, -1);
  // --save-frame wrote the last frame as shown (stretched to the window) and its reference: their
  // error, computed here, is one of the frames' the report averaged.
  const test::LoadedPng shown = test::load_png(prefix + "shown.png");
  const test::LoadedPng truth = test::load_png(prefix + "reference.png");
  ASSERT_EQ(shown.width_px, 96);
  ASSERT_EQ(shown.height_px, 54);
  ASSERT_EQ(truth.rgba8.size(), shown.rgba8.size());
  double sum = 0;
  for (size_t i = 0; i < shown.rgba8.size(); ++i)
    if (i % 4 != 3) sum += std::abs(int(shown.rgba8[i]) - int(truth.rgba8[i]));
  const double saved_mae = sum / (3.0 * 96 * 54 * 255);
  EXPECT_GT(saved_mae, 0) << "a stretched frame differs from a fully traced one";
  EXPECT_LE(saved_mae, worst_mae + 1e-4);
  EXPECT_GE(saved_mae, 3 * mae - 2 * worst_mae - 5e-4) << "the other two frames at their worst";
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"bench", "--explore", "--error", "--frames", "3", "--save-frame", "3:x"},
            "--save-frame: 3 is outside [0, 2]"},
           {{"bench", "--explore", "--error", "--save-frame", "7"}, "expected N:PREFIX"},
           {{"bench", "--explore", "--error", "--save-frame", "1:/no/such/folder/f-"},
            "--save-frame: folder '/no/such/folder' does not exist"},
           {{"bench", "--explore", "--save-frame", "1:x"}, "only with --explore --error"}}) {
    const CliRun bad = run(args);
    EXPECT_EQ(bad.code, 2) << args.back();
    EXPECT_NE(bad.err.find(says), std::string::npos) << bad.err;
  }
  // Every kept frame must fit: 1000 frames of 3840x2160 would be 31 GiB.
  const CliRun huge =
      run({"bench", "--explore", "--error", "--size", "3840x2160", "--frames", "1000"});
  EXPECT_EQ(huge.code, 2);
  EXPECT_NE(huge.err.find("could take 30.9 GiB; at most 129 frames at this size"),
            std::string::npos)
      << huge.err;
  // Too small for SSIM's window: refused before the flight, not after it.
  const CliRun tiny = run({"bench", "--explore", "--error", "--size", "8x8"});
  EXPECT_EQ(tiny.code, 2);
  EXPECT_NE(tiny.err.find("11x11 window: --size 8x8 is smaller"), std::string::npos) << tiny.err;
  // Only with --explore.
  const CliRun alone = run({"bench", "--error", "--size", "16x16"});
  EXPECT_EQ(alone.code, 2);
  EXPECT_NE(alone.err.find("--error: only with --explore"), std::string::npos) << alone.err;
}

// Temporal reuse in the report: with a fixed lattice of 1 in 3x2 pixels every moving frame traces
// exactly that share (the warm-up frame before the flight is the scaled one a new scene gets);
// --lattice is refused without reuse, out of its range, and without --explore.
TEST(Cli, ExploreBenchReportsTemporalReuse) {
  const CliRun r =
      run({"bench", "--explore", "--size", "96x54", "--frames", "4", "--set",
           "explorer.temporal=true", "--set", "explorer.quality=\"fast\"", "--lattice", "3x2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto at = r.out.find("temporal reuse in");
  ASSERT_NE(at, std::string::npos) << r.out;
  int used = 0, of = 0;
  double traced = 0;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at,
                        "temporal reuse in %d of %d moving frames; pixels per frame: %lf traced",
                        &used, &of, &traced),
            3)
      << r.out;
  EXPECT_EQ(used, 4);
  EXPECT_EQ(of, 4);
  EXPECT_EQ(traced, 32 * 27) << "96/3 columns of 54/2 rows";
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"bench", "--explore", "--lattice", "3x3"}, "only with temporal reuse"},
           {{"bench", "--explore", "--set", "explorer.temporal=true", "--lattice", "6x2"},
            "--lattice width: 6 is outside [1, 5]"},
           {{"bench", "--lattice", "2x2"}, "--lattice: only with --explore"}}) {
    const CliRun bad = run(args);
    EXPECT_EQ(bad.code, 2) << args.back();
    EXPECT_NE(bad.err.find(says), std::string::npos) << bad.err;
  }
}

// One channel: a warning reaches the error stream as "fractalis: warning: ...", -q hides it,
// --log-file gets it time-stamped whatever the verbosity, and -v with -q is refused.
TEST(Cli, WarningsGoThroughTheLogChannel) {
  const std::string png = std::string(TEST_OUTPUT_DIR) + "/log_channel.png";
  const std::vector<std::string> starved = {
      "render", "--scene", "menger", "--size", "16x16", "--set", "render.max_steps=2",
      "--out",  png};
  const CliRun normal = run(starved);
  ASSERT_EQ(normal.code, 0) << normal.err;
  EXPECT_NE(normal.err.find("fractalis: warning: "), std::string::npos) << normal.err;
  EXPECT_NE(normal.err.find("of rays ran out of steps (render.max_steps = 2)"), std::string::npos)
      << normal.err;

  const std::string log = std::string(TEST_OUTPUT_DIR) + "/log_channel.log";
  std::filesystem::remove(log);
  std::vector<std::string> quiet = starved;
  quiet.insert(quiet.begin(), {"-q", "--log-file", log});
  const CliRun q = run(quiet);
  ASSERT_EQ(q.code, 0) << q.err;
  EXPECT_EQ(q.err, "") << "-q says errors only";
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("] [warning] "), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("ran out of steps"), std::string::npos) << text.str();

  // Errors still show under -q, once.
  const CliRun bad = run({"render", "--quiet", "--scene", "nope"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err.rfind("fractalis: error: unknown scene 'nope'", 0), 0u) << bad.err;
  expect_usage_error({"-v", "render", "-q"}, "--verbose and --quiet: choose one");
  expect_usage_error({"render", "--log-file"}, "--log-file: expected a file name");
  expect_usage_error({"render", "--log-file", "/no/such/folder/x.log"},
                     "--log-file: folder '/no/such/folder' does not exist");
}

TEST(Cli, ListShowsParametersAndFailures) {
  const CliRun ok = run({"list"});
  EXPECT_EQ(ok.code, 0);
  EXPECT_NE(ok.out.find("mandelbulb 1.1.0"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("--param power=8  float in [2, 16]"), std::string::npos) << ok.out;
  const CliRun fixtures = run({"list", "--plugins", FIXTURE_PLUGIN_DIR});
  EXPECT_EQ(fixtures.code, 1) << "a folder with broken plugins lists them and exits 1";
  EXPECT_NE(fixtures.out.find("fixture_wrong_major" PLUGIN_SUFFIX
                              ": FAILED (wrong ABI major): wrong ABI major: plugin 2, host 1"),
            std::string::npos)
      << fixtures.out;
}

// list --verbose shows what each kernel compiles in: the Mandelbulb's has AO and not shadows, its
// own library file and not the sponge's, and its iteration count baked in.
TEST(Cli, ListVerboseShowsTheKernel) {
  const CliRun r = run({"list", "--verbose"});
  ASSERT_EQ(r.code, 0) << r.err;
  const size_t start = r.out.find("\nmandelbulb "), end = r.out.find("\n\n", start + 1);
  ASSERT_NE(start, std::string::npos);
  const std::string bulb = r.out.substr(start, end - start);
  EXPECT_NE(bulb.find("stages ao; left out: dof, glow, shadows, fog, reflections"),
            std::string::npos)
      << bulb;
  EXPECT_NE(bulb.find("DE library files: fr/mandelbulb.cl fr/palette.cl fr/powers.cl\n"),
            std::string::npos)
      << bulb;
  EXPECT_NE(bulb.find("baked in as constants: iterations=8;"), std::string::npos) << bulb;
}

TEST(Cli, Devices) {
  const CliRun r = run({"devices"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("[default]"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace fr
