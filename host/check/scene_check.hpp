// scene_check.hpp — the conformance checks `fractalis check` runs on one scene plugin.
//
// Like clap-validator and pluginval for audio plugins: everything a plugin does runs in its
// scene-host process, so a crash or hang is a finding, not the checker's end. The checks, in
// order (later ones are skipped when the plugin does not load or its DE does not compile):
//   descriptor        every rule of the loader (its own messages)
//   de-compiles       the DE builds at lane widths 1 and 16, in float and double, and the full
//                     render kernel builds; errors point at the author's file and line
//   wide-lanes        the DE builds at 64 lanes too, a CPU's width in float (a warning if not:
//                     the host then renders it at 16, slower)
//   de-returns        a test render in a child process finishes within plugins.vet_timeout_s
//   de-finite         no NaN or Inf at points sampled over the bounding sphere
//   de-lipschitz      |DE(p) - DE(q)| <= (1 + tol) |p - q| at nearby pairs (worst ratio, where)
//   de-overestimate   no surface inside the ball of radius DE(p) / (1 + tol) around points p
//                     outside the surface, found by fixed steps (worst ratio, where)
//   de-bounded        no surface outside the bounding radius (DE > 0 on shells from R to 2R)
//   lanes-agree       widths 1, 16 and 64 give the same values
//   precisions-agree  float and double agree (a chaotic DE may differ at some points: warned)
//   update            deterministic for the same time, valid across time samples and at every
//                     parameter's minimum, maximum and default
//   create-destroy    repeated without the scene host's heap or threads growing
//   render            a small render of the default view shows something, has no NaN pixel,
//                     and few rays run out of steps
//   render-careful    the same view by plain sphere tracing at full and at quarter steps: the
//                     share of the quarter steps' hits that the full steps go through (coarse:
//                     grazing rays count too; warn above 10%, fail above 25%)
//   material          a material function's values (scene_material, before the renderer clamps
//                     them) lie in their ranges at the surface points the render saw
//   unload            destroying every instance and closing the library leaves no thread and
//                     no mapping behind
#pragma once

#include "check/check_report.hpp"
#include "path/preset.hpp"
#include "plugin/plugin_policy.hpp"
#include "worker/render_worker.hpp"
#include "render/render_settings.hpp"

#include <filesystem>

namespace fr {

struct CheckOptions {
  PluginPolicy policy;    // isolation is always Process here
  RenderSettings render;  // the base settings of the sanity render
  int de_samples = 2048;  // points sampled over the bounding sphere
  // |dDE| <= (1 + tol) |dp|: pass when at most 1% of the sampled pairs exceed it, fail above 5%.
  double lipschitz_tolerance = 0.1;
  // Surface closer than DE(p) / (1 + tol) to p: pass when at most 1% of the tested points have
  // it, fail above 5%.
  double overestimate_tolerance = 0.1;
  // Checks the scene at this preset's values and view instead of its defaults (check --preset).
  std::optional<Preset> preset;
};

CheckReport check_scene_plugin(const std::filesystem::path& file, const CheckOptions& options,
                               RenderWorker& worker);

}  // namespace fr
