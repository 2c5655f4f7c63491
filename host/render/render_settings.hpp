// render_settings.hpp — how a frame is rendered: size, kernel shape, which effects and how, and
// the shading constants. Plain data with defaults; settings files and the CLI fill it in.
// Lengths marked "x bounding radius" scale with the scene, so one default suits every scene.
#pragma once

#include <fractalis/scene.h>

#include "io/enum_names.hpp"

#include <array>
#include <span>
#include <string>
#include <string_view>

namespace fr {

// Auto: float, unless the pixel footprint at the surface comes near float's resolution there
// (resolve_precision in render/precision.hpp), then double, and past double's, double-double
// (where the scene has a pair estimate). DoubleDouble ("dd"): the kernel works in coordinates
// relative to the eye, in double, and the scene's estimate gets its point as a double-double
// (docs/deep_zoom.md). The numbers travel between processes: keep them.
enum class Precision { Float = 0, Double = 1, Auto = 2, DoubleDouble = 3 };
inline constexpr EnumName<Precision> kPrecisionNames[] = {
    {Precision::Auto, "auto", "auto", nullptr},
    {Precision::Float, "float", "float", nullptr},
    {Precision::Double, "double", "double", nullptr},
    {Precision::DoubleDouble, "dd", "double-double", nullptr},
};
constexpr std::span<const EnumName<Precision>> enum_names(Precision) {
  return kPrecisionNames;
}

enum class ShadingModel { Lambert, BlinnPhong, OrenNayar };
inline constexpr EnumName<ShadingModel> kShadingModelNames[] = {
    {ShadingModel::Lambert, "lambert", "Lambert", "FR_SHADING_LAMBERT"},
    {ShadingModel::BlinnPhong, "blinn-phong", "Blinn-Phong", "FR_SHADING_BLINN_PHONG"},
    {ShadingModel::OrenNayar, "oren-nayar", "Oren-Nayar", "FR_SHADING_OREN_NAYAR"},
};
constexpr std::span<const EnumName<ShadingModel>> enum_names(ShadingModel) {
  return kShadingModelNames;
}

enum class NormalMethod { Tetrahedron, CentralDifferences };
inline constexpr EnumName<NormalMethod> kNormalMethodNames[] = {
    {NormalMethod::CentralDifferences, "central", "central differences", "FR_NORMALS_CENTRAL"},
    {NormalMethod::Tetrahedron, "tetrahedron", "tetrahedron", "FR_NORMALS_TETRAHEDRON"},
};
constexpr std::span<const EnumName<NormalMethod>> enum_names(NormalMethod) {
  return kNormalMethodNames;
}

enum class AoMethod { StepCount, Sampled };
inline constexpr EnumName<AoMethod> kAoMethodNames[] = {
    {AoMethod::StepCount, "step-count", "step count", "FR_AO_STEP_COUNT"},
    {AoMethod::Sampled, "sampled", "sampled", "FR_AO_SAMPLED"},
};
constexpr std::span<const EnumName<AoMethod>> enum_names(AoMethod) {
  return kAoMethodNames;
}

enum class ShadowMethod { Hard, Soft };
inline constexpr EnumName<ShadowMethod> kShadowMethodNames[] = {
    {ShadowMethod::Soft, "soft", "soft", "FR_SHADOW_SOFT"},
    {ShadowMethod::Hard, "hard", "hard", "FR_SHADOW_HARD"},
};
constexpr std::span<const EnumName<ShadowMethod>> enum_names(ShadowMethod) {
  return kShadowMethodNames;
}

enum class FogMethod { PowerLaw, Exponential };
inline constexpr EnumName<FogMethod> kFogMethodNames[] = {
    {FogMethod::Exponential, "exponential", "exponential", "FR_FOG_EXPONENTIAL"},
    {FogMethod::PowerLaw, "power", "power law", "FR_FOG_POWER"},
};
constexpr std::span<const EnumName<FogMethod>> enum_names(FogMethod) {
  return kFogMethodNames;
}

// How a sample's light is computed. Fast: today's direct-light models (shade.cl: the lights with
// DE soft shadows, ambient light scaled by occlusion, mirror bounces, fog, glow), the explorer's
// while flying. Path: a path tracer (kernels/path.cl): diffuse and mirror bounces lit by the sky
// and, by next-event estimation, the lights; unbiased, noisy, converging as samples accumulate.
enum class Integrator { Fast, Path };
inline constexpr EnumName<Integrator> kIntegratorNames[] = {
    {Integrator::Fast, "fast", "fast", "FR_INTEGRATOR_FAST"},
    {Integrator::Path, "path", "path tracing", "FR_INTEGRATOR_PATH"},
};
constexpr std::span<const EnumName<Integrator>> enum_names(Integrator) {
  return kIntegratorNames;
}

// What `Renderer::finish` reads back from the device besides the display image, and so what the
// render kernel writes (FR_OUTPUTS). Reading everything costs 33 MB of copies per 1280x720
// frame, so the explorer asks only for steps.
enum class Readback {
  Display,          // rgba8 only
  DisplayAndSteps,  // rgba8, steps and ray status (the DE-evaluations statistic, ray counts)
  Everything,       // every field of FrameImage
};

inline const char* precision_name(Precision p) {
  return enum_name(p);
}

// A window of a larger image: rendering it gives those pixels of the whole image exactly (the
// kernel computes its rays from the whole image's pixel grid: kernels/rays.cl, camera_ray; the
// pixel angle, and so the hit threshold, is the whole image's). full_width_px 0: the image is the
// whole. With a stride above
// 1 the window is a lattice: its pixel (x, y) is the whole image's (x0 + x * stride_x,
// y0 + y * stride_y) (the explorer's temporal reuse traces one such lattice a frame).
struct ImageWindow {
  int full_width_px = 0;
  int full_height_px = 0;
  int x0_px = 0;
  int y0_px = 0;
  int stride_x_px = 1;
  int stride_y_px = 1;
};

// The rows of the image that one sample's call renders: rows_px rows from first_row_px (rows_px
// 0: all of them). The other rows keep what they hold, so a sample may be added band by band, each
// pixel getting what the whole image's sample gives it (the kernel runs as for the whole image,
// offset): the explorer's path-traced refinement, which so answers input between bands. A band
// starts at a multiple of kRowBandAlign rows (every packet's height divides it) and, unless it
// ends the image, spans such a multiple.
struct RowBand {
  int first_row_px = 0;
  int rows_px = 0;
};
constexpr int kRowBandAlign = 16;

// A file path as plain data: RenderSettings travels to the render worker as its bytes. Empty
// (the first character NUL) means none.
struct PathText {
  static constexpr size_t kCapacity = 1024;  // bytes, the terminating NUL included
  std::array<char, kCapacity> text{};
  bool empty() const { return text[0] == '\0'; }
  std::string_view view() const {
    return {text.data(), std::char_traits<char>::length(text.data())};
  }
  // False (and unchanged) when `path` does not fit or holds a NUL.
  bool assign(std::string_view path) {
    if (path.size() >= kCapacity || path.find('\0') != std::string_view::npos) return false;
    text.fill('\0');
    path.copy(text.data(), path.size());
    return true;
  }
  friend bool operator==(const PathText& a, const PathText& b) { return a.view() == b.view(); }
};

struct RenderSettings {
  int width_px = 1280;  // of the image rendered (the window's size when `window` is set)
  int height_px = 720;
  ImageWindow window;
  int lanes = 0;  // 1, 4, 8, 16, 32 or 64; 0 picks the device's preferred width
  Precision precision = Precision::Auto;
  int samples = 1;                  // jittered samples accumulated per image (anti-aliasing)
  fr_features disabled_stages = 0;  // effects the user switched off
  Integrator integrator = Integrator::Fast;
  int path_max_bounces = 6;  // path tracing: surface interactions after the first hit, at most
  int seed = 0;              // path tracing and the lens: another seed, other (equally good) noise

  ShadingModel shading = ShadingModel::BlinnPhong;
  // Central differences: the sweep put them on the Pareto front for every scene (Menger: image
  // error 3.64 vs 4.15 for the tetrahedron at the same frame time).
  NormalMethod normals = NormalMethod::CentralDifferences;
  AoMethod ao_method = AoMethod::StepCount;
  ShadowMethod shadow_method = ShadowMethod::Soft;
  FogMethod fog_method = FogMethod::Exponential;

  int max_steps = 160;
  // `render` and `bench` end with an error when one image takes longer than this (a DE
  // that never returns hangs the device); 0: no limit. Seconds.
  double watchdog_s = 600;
  int refine_steps = 0;  // plain DE steps after a hit, towards the surface (0 to 8)
  // 32, not 64: the sweep found 64 dominated (same image error to 0.6%, 4-7% slower) on every
  // scene with shadows.
  int shadow_max_steps = 32;
  int max_bounces = 2;  // mirror bounces, when reflections are on
  // Budgets of the mirror bounces' rays: march steps (at most max_steps) and shadow steps (0:
  // no shadows in reflections). 16 shadow steps: the sweep found the benchmark scene's error the
  // same as with 32 (image MAE 7.483 against 7.477, the reference itself uncertain by ~1), and
  // its frames 1.14x faster; its bounce rays never needed more than 64 march steps.
  int bounce_max_steps = 160;
  int bounce_shadow_max_steps = 16;
  int ao_samples = 5;
  float hit_threshold_k = 0.5f;  // epsilon = k * t * pixel angle
  // When above 0, epsilon is this distance everywhere instead (world units; Mandelbulber2's
  // constant DE threshold).
  float hit_threshold_abs = 0.0f;
  float step_scale = 1.0f;
  // Over-relaxed sphere tracing's largest omega; 1 is plain sphere tracing. 1.6 with the
  // adaptive omega: on the sweep's front for the benchmark scene (1.3 fixed was the default).
  float relaxation = 1.6f;
  // The march's omega follows the DE's slope along the ray, up to `relaxation` (march.cl); off:
  // `relaxation` throughout, plain after the first overshoot.
  bool adaptive_relaxation = true;
  bool cone_prepass = true;  // one cone per 8x8 pixels skips the empty space first (cone.cl)
  bool fast_math = false;    // build with -cl-fast-relaxed-math (finite-math-only, relaxed trig)
  // Iteration counts follow the view's depth (render/depth_iterations.hpp): a zoom adds to a
  // scene's counts as the eye closes in. Applied by the render worker's client.
  bool auto_iterations = true;
  // Build with LLVM's optimizations off (-cl-opt-disable): the same picture, a kernel that
  // compiles about three times faster and renders four to six times slower. Not a setting: the
  // explorer's edit mode asks for it for the first frame after a DE changes (app/scene_edit.hpp),
  // so that the change is on screen within a second, and the optimized build follows.
  bool quick_build = false;
  // Diagnostics, not a quality knob: build the kernel with the per-stage DE counters
  // (render/eval_counts.hpp; Renderer::eval_counts reads them). Changes no pixel.
  bool count_evaluations = false;
  // Which passes the kernel writes besides the colour (renderer.hpp's Readback); the renderer
  // sets it from what its caller will read back.
  Readback outputs = Readback::Everything;
  float ao_strength = 2.5f;
  int ao_reference_steps = 160;  // step-count AO: this many march steps is full occlusion
  float ao_distance = 0.1f;      // x bounding radius
  float shadow_softness = 12.0f;
  float specular_strength = 0.35f;
  float specular_power = 48.0f;
  float roughness = 0.5f;  // Oren-Nayar sigma, radians
  float fresnel_f0 = 0.04f;
  float exposure = 1.0f;
  float reflectivity = 0.0f;  // of the default material (scenes with a surface source set theirs)
  // Path tracing: the share of the light not mirrored that enters the surface as into glass, the
  // glass's index of refraction, and its absorption per bounding radius travelled (Beer-Lambert),
  // in the surface's colour's complement (light of the surface's colour passes).
  float transmission = 0.0f;
  float ior = 1.5f;
  float absorption = 0.0f;
  // Path tracing: radiance the surface gives off, times its colour (a glowing fractal).
  float emission = 0.0f;
  // Path tracing's default material beyond the colour (kernels/path.cl's material_t): the share
  // that is metal (reflects in its colour), the roughness of every glossy lobe (0: mirror), the
  // share of the diffuse light that scatters under the surface, and its mean free path there per
  // bounding radius.
  float metalness = 0.0f;
  float specular_roughness = 0.0f;
  float subsurface = 0.0f;
  float mean_free_path = 0.05f;
  float fog_density = 0.08f;  // exponential fog, per bounding radius
  float fog_scale = 0.12f;    // power-law fog: amount = fog_scale * (t / bounding radius)^0.75
  float glow_strength = 0.6f;
  float glow_falloff = 0.02f;    // x bounding radius
  float aperture_radius = 0.0f;  // thin lens, world units; 0: no depth of field
  float focus_distance = 0.0f;   // world units; 0: the distance from eye to target
  int aperture_blades = 0;       // the aperture's sides (bokeh shape); below 3: round
  // The picture mirrored top to bottom (Mandelbulber2's legacy_coordinate_system; camera.hpp).
  bool mirror_vertical = false;
  // Pixels sampled at their top-left corners, the field of view spanning the image edge to edge
  // (Mandelbulber2's grid; camera.hpp); false: pixel centres, the outer ones on its edges.
  bool pixel_corners = false;
  // An edge-avoiding filter over the accumulated picture, guided by the first hits' normals,
  // depths and albedos (kernels/denoise.cl): for path tracing at few samples.
  bool denoise = false;
  std::array<float, 3> albedo{0.72f, 0.52f, 0.36f};
  std::array<float, 3> ambient{0.16f, 0.19f, 0.25f};
  // The sky as an equirectangular HDR panorama (io/environment_image.hpp; kernels/
  // environment.cl), an absolute path; empty: the gradient below. Its radiance is scaled by the
  // intensity, and it is turned about the camera's up vector by the rotation.
  PathText environment;
  float environment_intensity = 1.0f;
  float environment_rotation_deg = 0.0f;
  std::array<float, 3> sky_zenith{0.22f, 0.36f, 0.62f};
  std::array<float, 3> sky_horizon{0.72f, 0.78f, 0.86f};
  std::array<float, 3> glow_color{0.55f, 0.75f, 1.0f};
  std::array<float, 3> fog_color{0.72f, 0.78f, 0.86f};
};

// Calls visit(name, field) for every field of `s` (const or not), in declaration order, for code
// that must see all of them (the sweep reference's cache key). The static_assert below fails
// when a field is added to RenderSettings (and so must be added to this list).
template <typename Settings, typename Visit>
void visit_render_fields(Settings& s, Visit&& visit) {
  visit("width_px", s.width_px);
  visit("height_px", s.height_px);
  visit("window.full_width_px", s.window.full_width_px);
  visit("window.full_height_px", s.window.full_height_px);
  visit("window.x0_px", s.window.x0_px);
  visit("window.y0_px", s.window.y0_px);
  visit("window.stride_x_px", s.window.stride_x_px);
  visit("window.stride_y_px", s.window.stride_y_px);
  visit("lanes", s.lanes);
  visit("precision", s.precision);
  visit("samples", s.samples);
  visit("disabled_stages", s.disabled_stages);
  visit("integrator", s.integrator);
  visit("path_max_bounces", s.path_max_bounces);
  visit("seed", s.seed);
  visit("shading", s.shading);
  visit("normals", s.normals);
  visit("ao_method", s.ao_method);
  visit("shadow_method", s.shadow_method);
  visit("fog_method", s.fog_method);
  visit("max_steps", s.max_steps);
  visit("watchdog_s", s.watchdog_s);
  visit("refine_steps", s.refine_steps);
  visit("shadow_max_steps", s.shadow_max_steps);
  visit("max_bounces", s.max_bounces);
  visit("bounce_max_steps", s.bounce_max_steps);
  visit("bounce_shadow_max_steps", s.bounce_shadow_max_steps);
  visit("ao_samples", s.ao_samples);
  visit("hit_threshold_k", s.hit_threshold_k);
  visit("hit_threshold_abs", s.hit_threshold_abs);
  visit("step_scale", s.step_scale);
  visit("relaxation", s.relaxation);
  visit("adaptive_relaxation", s.adaptive_relaxation);
  visit("cone_prepass", s.cone_prepass);
  visit("fast_math", s.fast_math);
  visit("auto_iterations", s.auto_iterations);
  visit("quick_build", s.quick_build);
  visit("count_evaluations", s.count_evaluations);
  visit("outputs", s.outputs);
  visit("ao_strength", s.ao_strength);
  visit("ao_reference_steps", s.ao_reference_steps);
  visit("ao_distance", s.ao_distance);
  visit("shadow_softness", s.shadow_softness);
  visit("specular_strength", s.specular_strength);
  visit("specular_power", s.specular_power);
  visit("roughness", s.roughness);
  visit("fresnel_f0", s.fresnel_f0);
  visit("exposure", s.exposure);
  visit("reflectivity", s.reflectivity);
  visit("transmission", s.transmission);
  visit("ior", s.ior);
  visit("absorption", s.absorption);
  visit("emission", s.emission);
  visit("metalness", s.metalness);
  visit("specular_roughness", s.specular_roughness);
  visit("subsurface", s.subsurface);
  visit("mean_free_path", s.mean_free_path);
  visit("fog_density", s.fog_density);
  visit("fog_scale", s.fog_scale);
  visit("glow_strength", s.glow_strength);
  visit("glow_falloff", s.glow_falloff);
  visit("aperture_radius", s.aperture_radius);
  visit("focus_distance", s.focus_distance);
  visit("aperture_blades", s.aperture_blades);
  visit("mirror_vertical", s.mirror_vertical);
  visit("pixel_corners", s.pixel_corners);
  visit("denoise", s.denoise);
  visit("albedo", s.albedo);
  visit("ambient", s.ambient);
  visit("environment", s.environment);
  visit("environment_intensity", s.environment_intensity);
  visit("environment_rotation_deg", s.environment_rotation_deg);
  visit("sky_zenith", s.sky_zenith);
  visit("sky_horizon", s.sky_horizon);
  visit("glow_color", s.glow_color);
  visit("fog_color", s.fog_color);
}
namespace detail {
// An aggregate's number of direct members: the most initializers `T{...}` accepts, each an
// `AnyField` that converts to whatever member it meets.
struct AnyField {
  template <typename T>
  operator T() const;
};
template <typename T, typename... Fields>
constexpr size_t aggregate_member_count() {
  if constexpr (requires { T{Fields{}..., AnyField{}}; })
    return aggregate_member_count<T, Fields..., AnyField>();
  else
    return sizeof...(Fields);
}
}  // namespace detail
// RenderSettings' direct members (the window counts once): a new field changes the count. List
// it in visit_render_fields, then update this number.
static_assert(detail::aggregate_member_count<RenderSettings>() == 71,
              "RenderSettings changed: list the new field in visit_render_fields");

}  // namespace fr
