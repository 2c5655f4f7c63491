// The sweep: its metrics on hand-made images with known answers, the Pareto front on known
// points, the plan of configurations, bad input before any work, and one small sweep end to end
// (files written whole, the reference cached and reused).
#include "cli/cli.hpp"
#include "cli_run.hpp"
#include "plugin/scene_instance.hpp"
#include "sweep/sweep_metrics.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_reference.hpp"
#include "sweep/sweep_report.hpp"
#include "test_support.hpp"

#ifndef _WIN32  // the interrupted sweep, at the end: POSIX signals
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#endif

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <type_traits>

namespace fr {
namespace {

using test::CliRun;
using test::run;

// A 2x2 reference: two hits at depth 10 and 20 facing +z, two misses, grey pixels.
ReferenceImage two_by_two() {
  ReferenceImage r;
  r.width_px = 2;
  r.height_px = 2;
  r.rgba8 = std::vector<uint8_t>(16, 100);
  r.depth = {10, 20, INFINITY, INFINITY};
  r.normal = {0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0};
  return r;
}

FrameImage as_frame(const ReferenceImage& r) {
  FrameImage f = reference_as_frame(r);
  EXPECT_EQ(f.ray_status, (std::vector<uint8_t>{1, 1, 0, 0})) << "hits and misses from the depth";
  return f;
}

TEST(SweepMetrics, IdenticalImagesHaveNoError) {
  const ReferenceImage ref = two_by_two();
  const ErrorMetrics m = compare_to_reference(as_frame(ref), ref, 0.01);
  EXPECT_EQ(m.mean_abs_error, 0);
  EXPECT_TRUE(std::isinf(m.psnr_db));
  EXPECT_EQ(m.silhouette_mismatch, 0);
  EXPECT_EQ(m.depth_p95_px, 0);
  EXPECT_EQ(m.normal_p95_deg, 0);
  EXPECT_EQ(m.overstep_rate, 0);
  EXPECT_EQ(m.non_finite, 0u);
}

// Each metric against a value worked out by hand.
TEST(SweepMetrics, HandComputedValues) {
  const ReferenceImage ref = two_by_two();
  FrameImage f = as_frame(ref);
  f.rgba8[0] = 112;        // pixel 0, red: off by 12 (> 8)
  f.rgba8[4 + 1] = 104;    // pixel 1, green: off by 4
  f.depth[0] = 10 - 0.05;  // footprint 10 x 0.01 = 0.1: 0.5 footprints in front
  f.depth[1] = 20 + 0.1;   // footprint 0.2: 0.5 footprints behind (an overstep)
  f.normal[3] = 1;         // pixel 1's normal turned 90 degrees
  f.normal[5] = 0;
  f.depth[2] = 30;      // a hit where the reference misses
  f.ray_status[2] = 2;  // ... out of steps
  const ErrorMetrics m = compare_to_reference(f, ref, 0.01);
  EXPECT_NEAR(m.mean_abs_error, (12.0 + 4.0) / 12, 1e-12);
  EXPECT_NEAR(m.psnr_db, 20 * std::log10(255 / std::sqrt((144.0 + 16.0) / 12)), 1e-9);
  EXPECT_EQ(m.fraction_over_8, 0.25);
  EXPECT_NEAR(m.depth_median_px, 0.5, 1e-5);
  EXPECT_NEAR(m.depth_p95_px, 0.5, 1e-5);
  EXPECT_EQ(m.silhouette_mismatch, 0.25);
  EXPECT_NEAR(m.normal_p95_deg, 90, 1e-9);
  EXPECT_EQ(m.overstep_rate, 0.5) << "one of the two reference hits is behind";
  EXPECT_EQ(m.out_of_steps_fraction, 0.25);
  f.normal[7] = NAN;
  EXPECT_EQ(compare_to_reference(f, ref, 0.01).non_finite, 1u);
  f.depth.pop_back();
  EXPECT_THROW(compare_to_reference(f, ref, 0.01), std::invalid_argument);
}

// The reference cache key sees every field of RenderSettings (visit_render_fields): changing any
// one that shapes the reference changes the key, and changing one that the reference sets for
// itself (its precision, march, budgets, what is read back) does not. (The key once left out
// hit_threshold_k, which the reference starts from.)
TEST(SweepReference, KeyFollowsEveryFieldThatShapesTheReference) {
  SceneInfo info;
  info.id = "sphere";
  info.de_source =
      "real_t scene_de(vec3_t p, __constant const scene_params_t* params) {\n"
      "  return v3_length(p) - to_real(1);\n}\n";
  info.de_source_name = "sphere.cl";
  info.bounding_radius = 2;
  const SceneState state = make_default_state(info);
  const RenderSettings base;
  const std::string key = reference_key(info, state, base, "device");
  EXPECT_EQ(reference_key(info, state, base, "device"), key);
  EXPECT_NE(reference_key(info, state, base, "another device"), key);
  const std::set<std::string> set_by_the_reference = {"samples",
                                                      "max_steps",
                                                      "shadow_max_steps",
                                                      "refine_steps",
                                                      "relaxation",
                                                      "cone_prepass",
                                                      "fast_math",
                                                      "count_evaluations",
                                                      "watchdog_s",
                                                      "bounce_max_steps",
                                                      "bounce_shadow_max_steps",
                                                      "denoise"};
  size_t fields = 0;
  visit_render_fields(base, [&](const char* name, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_enum_v<T>) {
      return;  // an arbitrary number is no value of the enum: below, one by one
    } else {
      ++fields;
      RenderSettings changed = base;
      visit_render_fields(changed, [&](const char* n, auto& v) {
        using U = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<U, T>) {
          if (std::string(n) != name) return;
          if constexpr (std::is_same_v<U, bool>)
            v = !v;
          else if constexpr (std::is_same_v<U, std::array<float, 3>>)
            v[1] += 0.125f;
          else if constexpr (std::is_same_v<U, PathText>)
            v.assign("/a/panorama.hdr");
          else if constexpr (std::is_floating_point_v<U>)
            v = v * 0.5f + 0.125f;  // down: a step scale above 1 is clamped to 1
          else
            v += 1;
        }
      });
      const bool same = reference_key(info, state, changed, "device") == key;
      EXPECT_EQ(same, set_by_the_reference.count(name) > 0) << name;
    }
  });
  EXPECT_GT(fields, 40u);
  RenderSettings shading = base;
  shading.shading = ShadingModel::Lambert;
  EXPECT_NE(reference_key(info, state, shading, "device"), key);
  RenderSettings normals = base;
  normals.normals = NormalMethod::Tetrahedron;
  EXPECT_EQ(reference_key(info, state, normals, "device"), key) << "the reference picks its own";
}

TEST(SweepMetrics, ParetoFront) {
  // time, error: a (1, 9), b (2, 5), c (3, 6) dominated by b, d (4, 1), e (2, 7) dominated by b.
  const std::vector<double> time = {1, 2, 3, 4, 2}, error = {9, 5, 6, 1, 7};
  EXPECT_EQ(pareto_front(time, error), (std::vector<size_t>{0, 1, 3}));
}

// The truth a sweep measures against is never filtered, and a path-traced one has many samples.
TEST(SweepReference, IsUnfilteredAndPathTracedWithManySamples) {
  RenderSettings base;
  base.denoise = true;
  EXPECT_FALSE(reference_settings(base).denoise);
  EXPECT_EQ(reference_settings(base).samples, kReferenceSamples);
  base.integrator = Integrator::Path;
  EXPECT_EQ(reference_settings(base).integrator, Integrator::Path);
  EXPECT_EQ(reference_settings(base).samples, kPathReferenceSamples);
  EXPECT_EQ(reference_settings(base, 256).samples, 256);
  const SceneInfo info;
  const SceneState state;
  EXPECT_NE(reference_key(info, state, base, "device", 256),
            reference_key(info, state, base, "device"))
      << "another reference";
}

TEST(SweepPlan, OneKnobAtATimeAroundTheDefaults) {
  SceneInfo info;
  info.features = FR_FEATURE_AO;
  const RenderSettings defaults;
  EXPECT_EQ(knob_names(info, defaults),
            (std::vector<std::string>{"precision", "hit_threshold_k", "max_steps", "refine_steps",
                                      "relaxation", "adaptive_relaxation", "cone_prepass",
                                      "normals", "samples", "lanes", "ao", "integrator"}));
  // Path tracing: its bounce limit, and no ambient occlusion (not in its kernel); its samples
  // reach further.
  RenderSettings path = defaults;
  path.integrator = Integrator::Path;
  const auto path_knobs = knob_names(info, path);
  EXPECT_EQ(std::find(path_knobs.begin(), path_knobs.end(), "ao"), path_knobs.end());
  EXPECT_NE(std::find(path_knobs.begin(), path_knobs.end(), "path_max_bounces"), path_knobs.end());
  int path_sample_rows = 0;
  for (const auto& c : plan_sweep(info, path, {"samples", "integrator"})) {
    if (c.knob == "samples") {
      ++path_sample_rows;
      EXPECT_EQ(c.settings.integrator, Integrator::Path);
    }
    if (c.knob == "integrator") {
      EXPECT_EQ(c.settings.integrator, Integrator::Fast) << c.value;
    }
  }
  EXPECT_EQ(path_sample_rows, 4) << "1, 4, 16, 64, 256 less the default's 1";
  const auto configs = plan_sweep(info, defaults, {"max_steps", "relaxation"});
  ASSERT_EQ(configs.size(), 1u + 4 + 3) << "the default's own values are the default row";
  EXPECT_EQ(configs[0].knob, "default");
  for (const auto& c : configs) {
    if (c.knob == "max_steps") {
      EXPECT_EQ(std::to_string(c.settings.max_steps), c.value);
      EXPECT_EQ(c.settings.relaxation, defaults.relaxation);
    }
    if (c.knob == "relaxation") {
      EXPECT_EQ(c.settings.max_steps, defaults.max_steps);
    }
  }
  EXPECT_THROW(plan_sweep(info, defaults, {"warp_drive"}), std::invalid_argument);
  // The mirror bounces' budgets, for a scene with mirrors (and their shadows, with shadows).
  info.features = FR_FEATURE_REFLECTIONS;
  const auto mirrors = knob_names(info, defaults);
  EXPECT_NE(std::find(mirrors.begin(), mirrors.end(), "bounce_steps"), mirrors.end());
  EXPECT_EQ(std::find(mirrors.begin(), mirrors.end(), "bounce_shadow_steps"), mirrors.end());
  info.features = FR_FEATURE_REFLECTIONS | FR_FEATURE_SHADOWS;
  const auto both = knob_names(info, defaults);
  EXPECT_NE(std::find(both.begin(), both.end(), "bounce_shadow_steps"), both.end());
  for (const auto& c : plan_sweep(info, defaults, {"bounce_shadow_steps"}))
    if (c.knob == "bounce_shadow_steps") {
      EXPECT_EQ(std::to_string(c.settings.bounce_shadow_max_steps), c.value);
      EXPECT_EQ(c.settings.shadow_max_steps, defaults.shadow_max_steps);
    }
}

TEST(SweepReport, DefaultOffTheFrontIsSaid) {
  SweepResult r;
  r.rows = {{"default", "", 10, {}, false}, {"samples", "2", 5, {}, false}};
  r.rows[0].error.mean_abs_error = 4;
  r.rows[1].error.mean_abs_error = 1;  // faster and better: the default is off the front
  analyse_sweep(r, 0.0);
  EXPECT_FALSE(r.rows[0].on_front);
  EXPECT_TRUE(r.rows[1].on_front);
  ASSERT_EQ(r.notes.size(), 2u);
  EXPECT_NE(r.notes[0].find("OFF the Pareto front"), std::string::npos) << r.notes[0];
  EXPECT_NE(r.notes[1].find("error-neutral"), std::string::npos);
  const std::string svg = format_sweep_svg(r);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("default"), std::string::npos);
  EXPECT_EQ(format_sweep_csv(r).substr(0, 10), "knob,value");
}

TEST(SweepCommand, BadInputBeforeAnyWork) {
  const auto dir = test::fresh_dir("sweep_bad");
  // A file that exists, where a folder belongs, and a folder that cannot be made (under it).
  const std::string a_file = FRACTALIS_EXECUTABLE;
  const std::string under_a_file = (std::filesystem::path(a_file) / "no" / "such").string();
  for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"sweep", "--knobs", "warp_drive", "--out", dir.string()}, "unknown knob 'warp_drive'"},
           {{"sweep", "--knobs", ",", "--out", dir.string()}, "--knobs: empty sweep"},
           {{"sweep", "--out", a_file}, "is not a folder"},
           {{"sweep", "--out", under_a_file}, "--out: cannot create"},
           {{"sweep", "--frames", "0"}, "--frames: 0 is outside"}}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, 2) << message << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "nothing written";
}

// A small sweep of the unit ball: every file is written whole, the table names every
// configuration, and the reference converged far below the default's error.
// A view of empty space is said to be one, not reported as a perfect score.
TEST(SweepCommand, EmptyViewIsSaid) {
  const auto dir = test::fresh_dir("sweep_empty");
  const auto cache = test::fresh_dir("sweep_empty_cache");
  const CliRun r = run({"sweep", "--plugins", TEST_SCENE_DIR, "--scene", "unit_ball", "--size",
                        "16x12", "--eye", "3,0,0", "--target", "6,0,0", "--knobs", "samples",
                        "--frames", "1", "--out", dir.string(), "--cache", cache.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("the reference shows no surface in this view"), std::string::npos) << r.out;
}

TEST(SweepCommand, SmallSweepEndToEnd) {
  const auto dir = test::fresh_dir("sweep_small");
  const auto cache = test::fresh_dir("sweep_cache");
  const CliRun r = run({"sweep", "--plugins", TEST_SCENE_DIR, "--scene", "unit_ball", "--size",
                        "48x32", "--knobs", "hit_threshold_k,samples", "--frames", "1", "--out",
                        dir.string(), "--cache", cache.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"sweep.csv", "sweep.json", "sweep.svg"})
    EXPECT_TRUE(std::filesystem::file_size(dir / f) > 100) << f;
  int rows = 0;
  {  // closed before the next sweep replaces it (Windows cannot replace an open file)
    std::ifstream csv(dir / "sweep.csv");
    std::string line;
    while (std::getline(csv, line)) ++rows;
  }
  EXPECT_EQ(rows, 1 + 1 + 4 + 4) << "header, default, 4 thresholds, 4 sample counts";
  EXPECT_NE(r.out.find("hit_threshold_k=0.125"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("note: the default settings"), std::string::npos) << r.out;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(cache), {}), 1)
      << "one cached reference";
  // Again: the reference comes from the cache.
  const CliRun again = run({"sweep", "--plugins", TEST_SCENE_DIR, "--scene", "unit_ball", "--size",
                            "48x32", "--knobs", "samples", "--frames", "1", "--out", dir.string(),
                            "--cache", cache.string()});
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("(cached)"), std::string::npos) << again.out;
}

#ifndef _WIN32
// Ctrl-C (SIGINT) and SIGTERM during a sweep, as a user sends them to the real command: it
// stops with exit code 130 and writes nothing into --out, nor a partial reference.
TEST(SweepCommand, InterruptedSweepWritesNothing) {
  for (int signal_number : {SIGINT, SIGTERM}) {
    const auto dir = test::fresh_dir("sweep_interrupted");
    const auto cache = test::fresh_dir("sweep_interrupted_cache");
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const int devnull = open("/dev/null", O_WRONLY);
      dup2(devnull, 1);
      dup2(devnull, 2);
      execl(FRACTALIS_EXECUTABLE, "fractalis", "sweep", "--scene", "benchmark", "--size", "320x180",
            "--out", dir.c_str(), "--cache", cache.c_str(), nullptr);
      _exit(127);
    }
    // Long enough to be rendering (plugins loaded, kernels building or the reference running).
    usleep(1500 * 1000);
    kill(child, signal_number);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 130);
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << "an interrupted sweep wrote results";
    for (const auto& e : std::filesystem::directory_iterator(cache))
      EXPECT_EQ(e.path().extension(), ".ref") << "a temporary file was left: " << e.path();
  }
}
#endif

}  // namespace
}  // namespace fr
