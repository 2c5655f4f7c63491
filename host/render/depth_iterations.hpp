// depth_iterations.hpp — iteration counts that follow a deep zoom (render.auto_iterations).
//
// A fractal's iteration count sets the finest detail its estimate resolves: after n steps of a
// formula whose each step magnifies by a ratio g (the Mandelbox's 2, the Menger sponge's 3), the
// estimate resolves detail of about R / g^n, R the scene's bounding radius (docs/deep_zoom.md
// measures it). A view whose pixel footprint at the surface is f therefore needs
// n = log(R / f) / log(g): some 70 for the Mandelbox 1e-19 from its surface, where its default 14
// draws a blur. A scene names its iteration counts and their g (fr_param_desc.detail_ratio,
// ABI 1.4); with render.auto_iterations (on by default) the host raises each where the view needs
// more than the value set, never lowers one and never past its max, and says what it did.
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

// Raised counts go up in steps of this many (each new count is a kernel build: a zoom from 1 to
// 1e-20 builds some seven, not fifty).
constexpr int kIterationStep = 8;

struct RaisedIterations {
  std::string key;  // the parameter
  int set = 0;      // the value the user or scene set
  int used = 0;     // the value rendered: above `set`, at most the parameter's max
  int needed = 0;   // what the view needs; above `used` where the max stopped it
};

// The counts `footprint` (a pixel's size at the surface, world units) needs, raised in `params`
// (SceneState.params' order); what was raised, in parameter order. Nothing where the footprint
// is not positive and finite or the scene names no iteration count.
std::vector<RaisedIterations> raise_iterations_for_footprint(const SceneInfo& info,
                                                             double bounding_radius,
                                                             double footprint,
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
// what the scene can.
std::vector<RaisedIterations> raise_iterations_for_view(const DeProbe& probe,
                                                        const SceneInfo& info,
                                                        const SceneState& state, int width_px,
                                                        int height_px, bool fp64,
                                                        std::vector<fr_value>& params);

// "iterations 64 (the view needs 70; max 64)" for each, joined by "; ".
std::string describe_raised(const std::vector<RaisedIterations>& raised);

}  // namespace fr
