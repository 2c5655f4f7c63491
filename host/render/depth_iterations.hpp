// depth_iterations.hpp — iteration counts that follow a deep zoom (render.auto_iterations).
//
// A fractal's iteration count sets the finest detail its estimate resolves: after n steps of a
// formula whose each step magnifies by a ratio g (the Mandelbox's 2, the Menger sponge's 3), the
// estimate resolves detail of about R / g^n, R the scene's bounding radius (docs/deep_zoom.md
// measures it). A scene names its iteration counts and their g (fr_param_desc.detail_ratio,
// ABI 1.4). With render.auto_iterations (on by default) the host adds iterations as the view
// closes in: log_g(R / d) of them, d the distance from the eye to the surface, so that the count
// set keeps meaning the same detail relative to the view (a preset's deliberately coarse sponge
// stays coarse at its own view, and the Mandelbox's 14 become some 76 1e-19 from its surface);
// but never more than the view's pixels resolve, log_g(R / f) for a pixel footprint f at the
// surface (an explicit 90 at 1e-20 stays 90), never fewer than set, never past the max. Counts
// move in steps of kIterationStep, each new one a kernel build.
#pragma once

#include "render/camera.hpp"
#include "render/kernel_assembly.hpp"  // PairOrigin
#include "render/render_settings.hpp"
#include "scene/scene_data.hpp"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace fr {

// Counts move in steps of this many (each new count is a kernel build: a zoom from 1 to 1e-20
// builds some eighteen, not seventy).
constexpr int kIterationStep = 4;

struct RaisedIterations {
  std::string key;  // the parameter
  int set = 0;      // the value the user or scene set
  int used = 0;     // the value rendered: above `set`, at most the parameter's max
  int needed = 0;   // what the view's pixels could use (log_g(R / f))
  bool capped = false;  // the max stopped it short of what the view asks
};

// The counts a view needs, raised in `params` (SceneState.params' order) for an eye `distance`
// from the surface and pixels of `pixel_angle_rad`; what was raised (or is at its max and would
// need more), in parameter order. Nothing where the distance is not positive and finite, or not
// inside the bounding radius, or the scene names no iteration count.
std::vector<RaisedIterations> raise_iterations_for_depth(const SceneInfo& info,
                                                         double bounding_radius, double distance,
                                                         double pixel_angle_rad,
                                                         std::vector<fr_value>& params);

// A DE probe (render/de_probe.hpp's probe_de on this process's device or through a render
// worker): the scene's estimate with parameter values `params` at points, relative to `origin`
// in double-double.
using DeProbe = std::function<std::vector<float>(
    const std::vector<fr_value>& params, const std::vector<std::array<float, 3>>& points,
    Precision precision, const PairOrigin* origin)>;

// The pixel footprint at the nearest surface seen from the view's eye: the DE there (with
// `params`) times the pixel angle of a width_px x height_px image. Probed at the eye rounded to
// float (in double where the device has it), and again in pairs at the eye itself once that is
// past what float resolves and the scene has a pair estimate (as automatic precision does). 0
// where the eye is inside the surface or the estimate is not finite.
double eye_footprint(const DeProbe& probe, const SceneInfo& info, const SceneState& state,
                     const std::vector<fr_value>& params, int width_px, int height_px, bool fp64);

// The view's iteration counts: raised in `params` (a copy of state.params) as its footprint
// needs, and what was raised. An estimate with too few iterations cannot see a deep view (short
// of the surface by about R / ratio^n, it reads the eye as that far off): where the counts set
// seem to fall short, the footprint is probed again with every count at its max, which resolves
// what the scene can. No probe at all where the eye is so far outside the bounding sphere that
// no count could gain a step.
std::vector<RaisedIterations> raise_iterations_for_view(const DeProbe& probe,
                                                        const SceneInfo& info,
                                                        const SceneState& state, int width_px,
                                                        int height_px, bool fp64,
                                                        std::vector<fr_value>& params);

// "iterations 64 (the view needs 70; max 64)" for each, joined by "; ".
std::string describe_raised(const std::vector<RaisedIterations>& raised);

}  // namespace fr
