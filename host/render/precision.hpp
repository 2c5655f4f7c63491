// precision.hpp — choosing float or double for a view, and checking afterwards whether float
// resolved it.
//
// A float position near |p| is only good to about |p| * 2^-23. Where the pixel footprint at the
// surface (distance x pixel angle) comes within a small factor of that, float can no longer tell
// neighbouring pixels' hit points apart: deep zooms turn blocky and normals noisy. The automatic
// mode estimates the footprint before rendering from the scene's DE at the eye (the nearest
// surface is at least that far) and picks double there.
#pragma once

#include "render/camera.hpp"
#include "render/cl_runtime.hpp"
#include "render/kernel_assembly.hpp"  // PairOrigin, DoubleDouble
#include "render/render_settings.hpp"
#include "scene/scene_data.hpp"

#include <array>
#include <functional>
#include <vector>

namespace fr {

// Footprints smaller than this many float ulps of the surface position need double (and as many
// double ulps, double-double).
constexpr double kFloatFootprintUlps = 16;
constexpr double kDoubleFootprintUlps = 16;

// Float's resolution at world position scale |p|: one ulp, 2^-23 |p|.
double float_resolution(double position_scale);
// Double's: 2^-52 |p|.
double double_resolution(double position_scale);

// Whether float resolves every hit of this view that lies `distance` or farther from the eye: the
// footprint there (distance x pixel angle) is at least kFloatFootprintUlps float ulps of the
// positions such a hit can have. (Footprints grow with the distance faster than positions.)
bool float_resolves_beyond(double distance, const CameraRays& rays, double bounding_radius);

// The precision a frame of this view should use. Float, Double and DoubleDouble are returned as
// they are; Auto probes the DE at the eye (on the device) and returns Float when the footprint
// estimate is at least kFloatFootprintUlps float ulps (or the device has no doubles), else
// DoubleDouble when it is under kDoubleFootprintUlps double ulps at the eye (probed again in
// pairs) and the scene has a pair estimate, else Double.
Precision resolve_precision(ClRuntime& runtime, const SceneInfo& info, const SceneState& state,
                            const RenderSettings& settings);

// A pair estimate's values at points relative to an origin (probe_de in DoubleDouble, on this
// process's device or through a render worker).
using PairProbe = std::function<std::vector<float>(const std::vector<std::array<float, 3>>&,
                                                   const PairOrigin&)>;

// Whether a scene's pair estimate resolves what double cannot at this eye: 8 points a quarter of
// the footprint apart along each axis on which that spans under half an ulp of the eye's
// coordinate, and the estimate takes at least 6 different values along one of them. An estimate
// that rounds the point to double takes at most 2 there. Some scenes' pair estimates
// are double at some parameters (the Mandelbulb at a fractional power): this is how the host
// finds out without knowing the formula. True where the footprint is not positive or no axis
// qualifies (nothing to learn: double resolves the steps too).
bool pair_estimate_resolves(const PairProbe& probe, const std::array<DoubleDouble, 3>& eye,
                            double footprint);

// pair_estimate_resolves at this view's eye, its footprint from the pair estimate there.
bool pair_estimate_resolves_view(const PairProbe& probe, const SceneState& state,
                                 const CameraRays& rays);

// Throws std::invalid_argument, saying why, when this scene cannot render a double-double frame
// with these settings: it has no pair estimate, or the path tracer or fast math is asked for.
void check_pair_frame(const SceneInfo& info, const RenderSettings& settings);

// How finely a precision tells positions apart, relative to |p|: 2^-23, 2^-52, 2^-104 (a pair's;
// Auto counts as double).
double position_epsilon(Precision precision);

// The view's rays for a width_px x height_px image: the direction from the camera's pairs (so a
// view whose eye and target double cannot tell apart still has one), the eye its nearest double.
// mirror_vertical and pixel_corners as make_camera_rays takes them (render.mirror_vertical,
// render.pixel_corners): where a pixel's ray goes, for picking and reprojection.
CameraRays view_camera_rays(const SceneState& state, int width_px, int height_px,
                            bool mirror_vertical = false, bool pixel_corners = false);

// After a render: how many hit pixels (depth finite) have a footprint under
// kFloatFootprintUlps ulps (position_epsilon) of their hit position in the precision they were
// rendered in, i.e. were below what it resolves.
size_t pixels_below_resolution(const std::vector<float>& depth, const CameraRays& rays,
                               Precision precision);

}  // namespace fr
