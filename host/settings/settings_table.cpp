#include "settings/settings_table.hpp"

#include "io/environment_image.hpp"
#include "render/kernel_assembly.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fr {
namespace {

SettingSpec spec_of(const char* key, SettingKind kind, const char* comment, double lo = 0,
                    double hi = 0, bool lo_open = false) {
  SettingSpec spec;
  spec.key = key;
  spec.kind = kind;
  spec.comment = comment;
  spec.min = lo;
  spec.max = hi;
  spec.min_open = lo_open;
  return spec;
}

// The member a chain of member pointers names: member<&Settings::render, &RenderSettings::lanes>.
template <auto... Path>
auto& member(Settings& s) {
  return (s.*....*Path);
}
template <auto... Path>
const auto& member(const Settings& s) {
  return (s.*....*Path);
}

template <auto... Path>
SettingSpec bool_setting(const char* key, const char* comment) {
  SettingSpec spec = spec_of(key, SettingKind::Bool, comment);
  spec.get = [](const Settings& s) -> SettingValue { return member<Path...>(s); };
  spec.set = [](Settings& s, const SettingValue& v) { member<Path...>(s) = std::get<bool>(v); };
  return spec;
}

template <auto... Path>
SettingSpec int_setting(const char* key, long long lo, long long hi, const char* comment) {
  SettingSpec spec =
      spec_of(key, SettingKind::Int, comment, static_cast<double>(lo), static_cast<double>(hi));
  spec.get = [](const Settings& s) -> SettingValue {
    return static_cast<long long>(member<Path...>(s));
  };
  spec.set = [](Settings& s, const SettingValue& v) {
    member<Path...>(s) = static_cast<int>(std::get<long long>(v));
  };
  return spec;
}

// A float or double member; `lo_open`: the range excludes lo.
template <auto... Path>
SettingSpec number_setting(const char* key, double lo, double hi, bool lo_open,
                           const char* comment) {
  using T = std::remove_cvref_t<decltype(member<Path...>(std::declval<Settings&>()))>;
  SettingSpec spec = spec_of(key, SettingKind::Number, comment, lo, hi, lo_open);
  spec.single_precision = std::is_same_v<T, float>;
  spec.get = [](const Settings& s) -> SettingValue {
    return static_cast<double>(member<Path...>(s));
  };
  spec.set = [](Settings& s, const SettingValue& v) {
    // An integer is a number too ("--set render.watchdog_s=2").
    const auto* i = std::get_if<long long>(&v);
    member<Path...>(s) = static_cast<T>(i ? static_cast<double>(*i) : std::get<double>(v));
  };
  return spec;
}

// A colour member (std::array<float, 3>), linear RGB, each channel in [0, hi].
template <auto... Path>
SettingSpec color_setting(const char* key, double hi, const char* comment) {
  SettingSpec spec = spec_of(key, SettingKind::Color, comment, 0, hi);
  spec.single_precision = true;
  spec.get = [](const Settings& s) -> SettingValue {
    const auto& c = member<Path...>(s);
    return SettingColor{c[0], c[1], c[2]};
  };
  spec.set = [](Settings& s, const SettingValue& v) {
    const SettingColor& c = std::get<SettingColor>(v);
    member<Path...>(s) = {static_cast<float>(c[0]), static_cast<float>(c[1]),
                          static_cast<float>(c[2])};
  };
  return spec;
}

// An enum member, by the names in its table (io/enum_names.hpp).
template <auto... Path>
SettingSpec choice_setting(const char* key, const char* comment) {
  using Enum = std::remove_cvref_t<decltype(member<Path...>(std::declval<Settings&>()))>;
  SettingSpec spec = spec_of(key, SettingKind::Choice, comment);
  for (const auto& row : enum_names(Enum{})) spec.choices.push_back({row.name, row.label});
  spec.get = [](const Settings& s) -> SettingValue {
    return std::string(enum_name(member<Path...>(s)));
  };
  spec.set = [](Settings& s, const SettingValue& v) {
    member<Path...>(s) = *enum_from_name<Enum>(std::get<std::string>(v));
  };
  return spec;
}

// render.effects.NAME: on unless the user disabled the stage.
template <fr_features Stage>
SettingSpec effect_setting(const char* key) {
  SettingSpec spec = spec_of(key, SettingKind::Bool, "");
  spec.get = [](const Settings& s) -> SettingValue {
    return (s.render.disabled_stages & Stage) == 0;
  };
  spec.set = [](Settings& s, const SettingValue& v) {
    if (std::get<bool>(v))
      s.render.disabled_stages &= ~Stage;
    else
      s.render.disabled_stages |= Stage;
  };
  return spec;
}

SettingSpec in_overlay(SettingSpec spec, const char* label, double ui_min = 0, double ui_max = 0,
                       bool ui_log = false) {
  spec.label = label;
  spec.ui_min = ui_min;
  spec.ui_max = ui_max;
  spec.ui_log = ui_log;
  return spec;
}

// The explorer's still-image quality presets, as samples.
struct QualityPreset {
  const char* name;
  int samples;
};
const QualityPreset kQualityPresets[] = {{"fast", 2}, {"balanced", 8}, {"high", 32}};

std::vector<SettingSpec> make_table() {
  using S = Settings;
  using R = RenderSettings;
  using E = ExplorerSettings;
  using P = PluginPolicy;
  std::vector<SettingSpec> t;

  SettingSpec folders = spec_of(
      "plugins.folders", SettingKind::TextList,
      "Folders searched for scene plugins (*.so), in order. Empty: the scenes built with "
      "fractalis\n(the build tree's scenes/ folder, or the installed <prefix>/lib/fractalis/"
      "plugins), then your\nown folder $XDG_DATA_HOME/fractalis/scenes "
      "(~/.local/share/fractalis/scenes) when it exists.\n`--plugins DIR` replaces this list (and "
      "the defaults) with that one folder.");
  folders.get = [](const Settings& s) -> SettingValue {
    std::vector<std::string> out;
    for (const auto& f : s.plugin_folders) out.push_back(f.string());
    return out;
  };
  folders.set = [](Settings& s, const SettingValue& v) {
    s.plugin_folders.assign(std::get<std::vector<std::string>>(v).begin(),
                            std::get<std::vector<std::string>>(v).end());
  };
  t.push_back(folders);
  t.push_back(choice_setting<&S::plugins, &P::isolation>(
      "plugins.isolation",
      "Where plugin code runs: \"process\" (each scene in a fractalis-scene-host process of its "
      "own, its\nkernels in a fractalis-render-worker process, so a plugin that crashes, hangs or "
      "throws fails\nalone) or \"none\" (in fractalis itself: only for debugging a plugin in "
      "gdb; a crash in the\nplugin ends fractalis)."));
  t.push_back(number_setting<&S::plugins, &P::load_timeout_s>(
      "plugins.load_timeout_s", 0, 3600, true,
      "Seconds a plugin may take to load (its constructors and descriptor), and to answer one "
      "create,\nupdate or destroy call. A plugin over its limit is stopped and reported."));
  t.push_back(
      number_setting<&S::plugins, &P::call_timeout_s>("plugins.call_timeout_s", 0, 3600, true, ""));
  t.push_back(number_setting<&S::plugins, &P::vet_timeout_s>(
      "plugins.vet_timeout_s", 0, 3600, true,
      "Seconds the 8x8 test render of a scene (in a child process, before the explorer, "
      "`render`,\n`bench`, `animate` or `sweep` first use it; once per file content) may take, "
      "kernel build\nincluded, before the scene is refused as one whose DE may never return."));
  t.push_back(number_setting<&S::plugins, &P::vet_render_timeout_s>(
      "plugins.vet_render_timeout_s", 0, 3600, true,
      "Seconds the 8x8 test render itself may take, its kernel build not counted "
      "(plugins.build_timeout_s\nhas that): a DE that never returns is said this soon. 0: no limit "
      "of its own "
      "(plugins.vet_timeout_s\nstill ends the test)."));
  t.push_back(number_setting<&S::plugins, &P::build_timeout_s>(
      "plugins.build_timeout_s", 1, 3600, true,
      "Seconds one kernel build of a scene may take in the render worker (the process that "
      "compiles and\nruns scene kernels) before the worker is ended and the scene reported."));
  t.push_back(number_setting<&S::plugins, &P::worker_memory_mib>(
      "plugins.worker_memory_mib", 64, 1048576, true,
      "MiB of memory the render worker may use before it is ended and the scene reported."));
  t.push_back(number_setting<&S::plugins, &P::frame_limit_s>(
      "plugins.frame_limit_s", 1, 3600, true,
      "Seconds the explorer's first sample of a scene may take in the render worker; later "
      "samples may\ntake 20 times the slowest time per pixel the scene has needed so far, and at "
      "least 5 s. (Commands\nuse render.watchdog_s.)"));
  t.push_back(bool_setting<&S::plugins, &P::allow_writable>(
      "plugins.allow_writable",
      "Load plugins from folders or files that users other than you (and root) can write to. "
      "Off: such\nplugins are refused with a message naming the folder or file, since another "
      "user could swap\nthe code fractalis runs."));

  SettingSpec device =
      spec_of("device.select", SettingKind::Text,
              "OpenCL device: \"\" picks the first GPU, else the first CPU device (PoCL); "
              "or \"gpu\", \"cpu\",\n\"P:D\" (platform:device, as `fractalis devices` lists "
              "them), or part of the device's name.");
  device.get = [](const Settings& s) -> SettingValue { return s.device; };
  device.set = [](Settings& s, const SettingValue& v) { s.device = std::get<std::string>(v); };
  t.push_back(device);

  t.push_back(int_setting<&S::cache, &CacheSettings::kernel_cache_mib>(
      "cache.kernel_cache_mib", 16, 1 << 20,
      "Most MiB of compiled kernels kept in $XDG_CACHE_HOME/fractalis/kernels (PoCL's kernel "
      "cache);\nthe least recently used programs go first. `fractalis cache --clear` empties "
      "every cache."));

  SettingSpec lanes = int_setting<&S::render, &R::lanes>(
      "render.lanes", 0, 64,
      "Rays per work-item: 0 lets the device decide (on CPUs 16, with AVX-512 64 in float and\n"
      "32 in double; 1 on GPUs).");
  lanes.only_ints = {0, 1, 4, 8, 16, 32, 64};
  lanes.only_ints_text = "one of 0 (device's choice), 1, 4, 8, 16, 32, 64";
  t.push_back(lanes);
  t.push_back(in_overlay(
      choice_setting<&S::render, &R::precision>(
          "render.precision",
          "Arithmetic precision of the render kernel: \"auto\" (float, or double where the pixel "
          "footprint at\nthe surface comes near float's resolution, or pairs of doubles past "
          "double's where the scene has\na pair estimate), \"float\", \"double\" (the accuracy "
          "reference), or \"dd\" (double-double: a deep\nzoom's, docs/deep_zoom.md)."),
      "Precision"));
  t.push_back(choice_setting<&S::render, &R::integrator>(
      "render.integrator",
      "How light is computed: \"fast\" (direct light, soft shadows, occlusion; the explorer's "
      "while flying) or\n\"path\" (path tracing: light from the sky and the lights bouncing "
      "between surfaces; noisy,\nconverging as render.samples accumulate)."));
  t.push_back(int_setting<&S::render, &R::path_max_bounces>(
      "render.path_max_bounces", 1, 1024,
      "Path tracing: surface interactions a path may have after the first hit (Russian roulette "
      "ends most\nsooner; glass wants more: light bounces inside it)."));
  t.push_back(int_setting<&S::render, &R::seed>(
      "render.seed", 0, 1 << 30,
      "Path tracing and depth of field: the random numbers' seed. A pixel's samples depend only "
      "on the pixel,\nthe sample's index and this seed, so an image rendered in bands or by "
      "several ranks is\nthe same."));
  t.push_back(int_setting<&S::render, &R::samples>(
      "render.samples", 1, 4096,
      "Jittered samples accumulated per image: 1 is no anti-aliasing; depth of field needs "
      "several."));
  t.push_back(
      in_overlay(int_setting<&S::render, &R::max_steps>(
                     "render.max_steps", 1, 10000, "Sphere-tracing iterations per primary ray."),
                 "Max steps", 16, 1000));
  t.push_back(number_setting<&S::render, &R::watchdog_s>(
      "render.watchdog_s", 0, 1e6, false,
      "Seconds one image of `render`, `bench` or `animate` may take before it ends with an "
      "error\nnaming the scene (a DE that returns at the test render's pixels but never at "
      "others would\notherwise hang it forever); 0: no limit."));
  t.push_back(in_overlay(
      int_setting<&S::render, &R::refine_steps>(
          "render.refine_steps", 0, 8,
          "Plain DE steps after a hit, towards the surface (0 to 8): closes the gap the hit "
          "threshold\nleaves (the silhouette bias), at one DE evaluation each."),
      "Refine steps", 0, 8));
  t.push_back(int_setting<&S::render, &R::max_bounces>(
      "render.max_bounces", 0, 8,
      "Mirror bounces after the primary hit, when reflections are on (0 to 8)."));
  t.push_back(int_setting<&S::render, &R::bounce_max_steps>(
      "render.bounce_max_steps", 1, 10000,
      "Sphere-tracing iterations per mirror-bounce ray (at most max_steps)."));
  t.push_back(int_setting<&S::render, &R::bounce_shadow_max_steps>(
      "render.bounce_shadow_max_steps", 0, 10000,
      "Iterations per shadow ray at a mirror bounce (0: reflections show no shadows; 16: the sweep "
      "found\n32 no more accurate, and slower)."));
  t.push_back(in_overlay(
      number_setting<&S::render, &R::hit_threshold_k>(
          "render.hit_threshold_k", 0, 100, true,
          "Hit threshold factor k: a ray has hit when the DE < k * distance * pixel angle."),
      "Detail (k)", 0.05, 4, true));
  t.push_back(number_setting<&S::render, &R::hit_threshold_abs>(
      "render.hit_threshold_abs", 0, 1e6, false,
      "When above 0, a ray has hit when the DE < this distance (world units), near or far,\n"
      "instead of k * distance * pixel angle (Mandelbulber2's constant DE threshold)."));
  t.push_back(in_overlay(
      number_setting<&S::render, &R::step_scale>(
          "render.step_scale", 0, 1, true,
          "Multiplies every DE step, in (0, 1]: below 1 for a DE that over-estimates the "
          "distance (one that\n`fractalis check` flags, or a twisted domain; Fragmentarium's "
          "fudge factor),\nat the cost of more steps."),
      "Step scale", 0.05, 1));
  t.push_back(in_overlay(
      number_setting<&S::render, &R::relaxation>(
          "render.relaxation", 1, 1.95, false,
          "Over-relaxation of the march (Keinert et al. 2014), in [1, 1.95]: steps are up to this "
          "times the\nDE, with a step back where that overshoots; 1 is plain sphere tracing."),
      "Relaxation", 1, 1.95));
  t.push_back(bool_setting<&S::render, &R::adaptive_relaxation>(
      "render.adaptive_relaxation",
      "Adapt the over-relaxation to the DE's slope along each ray (up to render.relaxation), and "
      "relax\nagain after a step back (Bán and Valasek 2023); false: render.relaxation "
      "throughout, plain\nsteps after the first overshoot."));
  t.push_back(bool_setting<&S::render, &R::cone_prepass>(
      "render.cone_prepass",
      "Cone pre-pass: one cone per 8x8 pixels marches through the empty space first, and the "
      "pixels'\nrays start where it stopped (the same hits for fewer DE evaluations; off with "
      "depth of field)."));
  t.push_back(bool_setting<&S::render, &R::auto_iterations>(
      "render.auto_iterations",
      "Add iterations to a scene's counts as the eye closes in on the surface, up to what the "
      "view's\npixels resolve (a deep zoom: the Mandelbox's 14 become 76 at 1e-19); never lowers "
      "a count."));
  t.push_back(bool_setting<&S::render, &R::fast_math>(
      "render.fast_math",
      "Build the kernels with -cl-fast-relaxed-math (finite-math-only, relaxed trigonometry): "
      "measured\nno faster on PoCL; off."));
  t.push_back(in_overlay(
      number_setting<&S::render, &R::exposure>("render.exposure", 0, 100, true,
                                               "Linear exposure applied before tonemapping."),
      "Exposure", 0.1, 4, true));
  t.push_back(
      in_overlay(number_setting<&S::render, &R::ao_strength>(
                     "render.ao_strength", 0, 100, true,
                     "Ambient occlusion strength, in (0, 100]: larger is darker in crevices."),
                 "AO strength", 0.1, 10, true));
  t.push_back(int_setting<&S::render, &R::ao_reference_steps>(
      "render.ao_reference_steps", 1, 100000,
      "Step-count ambient occlusion: this many march steps is full occlusion. A fixed count, so "
      "that\nraising max_steps does not darken converged pixels."));
  t.push_back(in_overlay(number_setting<&S::render, &R::roughness>(
                             "render.roughness", 0, 1.5, false,
                             "Surface roughness of the Oren-Nayar model, radians (0 is Lambert)."),
                         "Roughness", 0, 1.5));
  t.push_back(in_overlay(
      number_setting<&S::render, &R::reflectivity>(
          "render.reflectivity", 0, 1, false,
          "Reflectivity of the default material, for scenes without their own materials (0 to "
          "1)."),
      "Reflectivity", 0, 1));
  t.push_back(number_setting<&S::render, &R::transmission>(
      "render.transmission", 0, 1, false,
      "Path tracing: the share of the light not mirrored that enters the surface as into glass "
      "(0: opaque,\n1: clear glass; refracted, reflected and absorbed inside)."));
  t.push_back(number_setting<&S::render, &R::ior>(
      "render.ior", 1, 4, false,
      "Path tracing: the glass's index of refraction (1: no bending; water 1.33, glass 1.5, "
      "diamond 2.42)."));
  t.push_back(number_setting<&S::render, &R::absorption>(
      "render.absorption", 0, 1000, false,
      "Path tracing: how much of the light the glass absorbs per bounding radius travelled "
      "(Beer-Lambert),\nless of the surface's own colour: a tinted glass."));
  t.push_back(number_setting<&S::render, &R::emission>(
      "render.emission", 0, 1000, false,
      "Path tracing: light the surface gives off, times its colour (0: none; 1: as bright as a "
      "white surface\nunder a light of colour 1)."));
  t.push_back(number_setting<&S::render, &R::metalness>(
      "render.metalness", 0, 1, false,
      "Path tracing: the share of the default material that is metal, reflecting in its own "
      "colour (0 to 1)."));
  t.push_back(number_setting<&S::render, &R::specular_roughness>(
      "render.specular_roughness", 0, 1, false,
      "Path tracing: roughness of the mirror, metal and glass (0: polished; 1: fully rough; GGX "
      "alpha is its\nsquare)."));
  t.push_back(number_setting<&S::render, &R::subsurface>(
      "render.subsurface", 0, 1, false,
      "Path tracing: the share of the diffuse light that enters the surface and scatters under "
      "it (wax,\nmarble), in the surface's colour."));
  t.push_back(number_setting<&S::render, &R::mean_free_path>(
      "render.mean_free_path", 0, 100, true,
      "Path tracing: subsurface light's mean distance between scatterings, per bounding radius "
      "(small:\nnearly opaque; large: translucent)."));
  t.push_back(bool_setting<&S::render, &R::denoise>(
      "render.denoise",
      "Filter the picture's noise, guided by the first hits' normals, depths and albedos (an "
      "edge-avoiding\nà-trous filter): for path tracing at few samples. Not with bands (posters, "
      "MPI ranks)."));
  SettingSpec environment = spec_of(
      "render.environment", SettingKind::Text,
      "The sky as an equirectangular HDR panorama: a Radiance .hdr or an OpenEXR .exr file "
      "(twice as wide as\nhigh, the zenith at the top), seen by both integrators where rays "
      "leave the scene and, in path\ntracing, lighting it. A relative path is from the current "
      "folder. \"\": the gradient of sky_zenith\nand sky_horizon.");
  environment.check = [](const SettingValue& v) -> std::string {
    const std::string& text = std::get<std::string>(v);
    if (text.empty()) return "";
    const std::filesystem::path path = std::filesystem::absolute(text).lexically_normal();
    if (path.string().size() >= PathText::kCapacity)
      return "the path is longer than " + std::to_string(PathText::kCapacity - 1) + " bytes";
    EnvironmentImage image;
    std::string error;
    return read_environment_image(path, &image, &error) ? "" : error;
  };
  environment.get = [](const Settings& s) -> SettingValue {
    return std::string(s.render.environment.view());
  };
  environment.set = [](Settings& s, const SettingValue& v) {
    const std::string& text = std::get<std::string>(v);
    s.render.environment.assign(
        text.empty() ? "" : std::filesystem::absolute(text).lexically_normal().string());
  };
  t.push_back(environment);
  t.push_back(color_setting<&S::render, &R::sky_zenith>(
      "render.sky_zenith", 1e3,
      "Without a panorama: the sky's colour straight up (the camera's up), linear RGB; it "
      "blends to\nsky_horizon at the horizon and stays that below it."));
  t.push_back(color_setting<&S::render, &R::sky_horizon>(
      "render.sky_horizon", 1e3, "Without a panorama: the sky's colour at and below the horizon."));
  t.push_back(number_setting<&S::render, &R::environment_intensity>(
      "render.environment_intensity", 0, 1e6, false,
      "Multiplies the panorama's radiance (render.environment)."));
  t.push_back(number_setting<&S::render, &R::environment_rotation_deg>(
      "render.environment_rotation_deg", -360, 360, false,
      "Turns the panorama about the camera's up vector, degrees (where its sun stands)."));
  t.push_back(int_setting<&S::render, &R::aperture_blades>(
      "render.aperture_blades", 0, 32,
      "Sides of the lens's aperture, the shape of out-of-focus highlights (bokeh): 0 (or 1, 2) "
      "is round."));
  t.push_back(bool_setting<&S::render, &R::mirror_vertical>(
      "render.mirror_vertical",
      "Mirror the picture top to bottom, as Mandelbulber2's legacy_coordinate_system does\n"
      "(imported .fract files set it)."));
  t.push_back(bool_setting<&S::render, &R::pixel_corners>(
      "render.pixel_corners",
      "Sample each pixel at its top-left corner, the field of view spanning the image edge to\n"
      "edge, as Mandelbulber2 does (imported .fract files set it); false: pixel centres, the\n"
      "first and last on the field of view's edges."));
  t.push_back(in_overlay(number_setting<&S::render, &R::aperture_radius>(
                             "render.aperture", 0, 10, false,
                             "Thin-lens aperture radius in world units; 0 is a pinhole (no depth "
                             "of field)."),
                         "Aperture", 0, 0.5));
  t.push_back(number_setting<&S::render, &R::focus_distance>(
      "render.focus_distance", 0, 1000, false,
      "Distance that stays sharp with an aperture; 0 means the distance from the eye to the "
      "target."));
  t.push_back(
      in_overlay(choice_setting<&S::render, &R::shading>(
                     "render.shading_model",
                     "Shading model: \"lambert\", \"blinn-phong\", or \"oren-nayar\" (with a "
                     "Fresnel-weighted highlight)."),
                 "Shading"));
  t.push_back(in_overlay(
      choice_setting<&S::render, &R::normals>(
          "render.normal_method",
          "Surface normals: \"central\" (6 DE evaluations, central differences; on the sweep's "
          "Pareto front\nfor every scene) or \"tetrahedron\" (4)."),
      "Normals"));
  t.push_back(in_overlay(choice_setting<&S::render, &R::ao_method>(
                             "render.ao_method",
                             "Ambient occlusion: \"step-count\" (free, from the march) or "
                             "\"sampled\" (DE samples along the normal)."),
                         "AO method"));
  // "Shadow edges", not "Shadows": that label (and so ImGui's id) is the effect's checkbox.
  t.push_back(in_overlay(choice_setting<&S::render, &R::shadow_method>(
                             "render.shadow_method", "Shadows: \"soft\" (penumbra) or \"hard\"."),
                         "Shadow edges"));
  t.push_back(int_setting<&S::render, &R::shadow_max_steps>(
      "render.shadow_max_steps", 1, 10000,
      "Sphere-tracing iterations per shadow ray (32: the sweep found 64 no more accurate, and "
      "slower)."));
  t.push_back(in_overlay(choice_setting<&S::render, &R::fog_method>(
                             "render.fog_method",
                             "Fog: \"exponential\" (1 - exp(-density t)) or \"power\" (fog_scale * "
                             "t^0.75)."),
                         "Fog curve"));
  t.push_back(number_setting<&S::render, &R::fog_density>(
      "render.fog_density", 0, 1e9, false,
      "The exponential fog's density per bounding radius (1 - exp(-density t / R))."));
  t.push_back(color_setting<&S::render, &R::fog_color>("render.fog_color", 1e3,
                                                       "The fog's colour, linear RGB."));
  t.push_back(color_setting<&S::render, &R::glow_color>(
      "render.glow_color", 1e3, "The glow's colour around the surface, linear RGB."));

  t.push_back(in_overlay(effect_setting<FR_FEATURE_SHADOWS>("render.effects.shadows"), "Shadows"));
  t.push_back(in_overlay(effect_setting<FR_FEATURE_AO>("render.effects.ao"), "Ambient occlusion"));
  t.push_back(in_overlay(effect_setting<FR_FEATURE_GLOW>("render.effects.glow"), "Glow"));
  t.push_back(in_overlay(effect_setting<FR_FEATURE_FOG>("render.effects.fog"), "Fog"));
  t.push_back(in_overlay(effect_setting<FR_FEATURE_REFLECTIONS>("render.effects.reflections"),
                         "Reflections"));
  t.push_back(
      in_overlay(effect_setting<kStageDepthOfField>("render.effects.dof"), "Depth of field"));

  t.push_back(int_setting<&S::explorer, &E::window_width_px>(
      "window.width", 64, 16384,
      "Window size in pixels (--size overrides), and whether to start fullscreen (F11 "
      "toggles)."));
  t.push_back(int_setting<&S::explorer, &E::window_height_px>("window.height", 64, 16384, ""));
  t.push_back(bool_setting<&S::explorer, &E::fullscreen>("window.fullscreen", ""));

  t.push_back(number_setting<&S::explorer, &E::target_fps>(
      "explorer.target_fps", 1, 240, false,
      "Frame rate held while the camera moves, by tracing fewer pixels."));
  t.push_back(bool_setting<&S::explorer, &E::temporal>(
      "explorer.temporal",
      "While moving, trace a rotating share of the pixels, the rest reused from earlier frames."));
  SettingSpec quality =
      spec_of("explorer.quality", SettingKind::Choice,
              "Anti-aliasing once the camera stops: \"fast\" (2 samples), \"balanced\" "
              "(8) or \"high\" (32).");
  for (const auto& q : kQualityPresets) quality.choices.push_back({q.name, q.name});
  quality.get = [](const Settings& s) -> SettingValue {
    for (const auto& q : kQualityPresets)  // the preset at or above the samples in use
      if (s.explorer.full_quality_samples <= q.samples) return std::string(q.name);
    return std::string(std::end(kQualityPresets)[-1].name);
  };
  quality.set = [](Settings& s, const SettingValue& v) {
    for (const auto& q : kQualityPresets)
      if (std::get<std::string>(v) == q.name) s.explorer.full_quality_samples = q.samples;
  };
  t.push_back(quality);
  t.push_back(int_setting<&S::explorer, &E::path_samples>(
      "explorer.path_samples", 1, 1 << 20,
      "With render.integrator = \"path\": path-traced samples a view accumulates once the "
      "camera stops\n(flying stays on the fast integrator; any change starts again)."));

  t.push_back(bool_setting<&S::explorer, &E::denoise>(
      "explorer.denoise",
      "With render.integrator = \"path\": filter the picture's noise over its first 16 "
      "samples (as\nrender.denoise does), so that a few samples already show the picture."));

  t.push_back(number_setting<&S::explorer, &E::mouse_sensitivity_deg_per_px>(
      "controls.mouse_sensitivity", 0, 10, true,
      "Mouse look, degrees per pixel of mouse movement; invert_y flips up and down."));
  t.push_back(bool_setting<&S::explorer, &E::invert_y>("controls.invert_y", ""));
  t.push_back(number_setting<&S::explorer, &E::speed>(
      "controls.speed", 0, 100, true,
      "Flying speed, in distances-to-the-nearest-surface per second (Shift is 4x faster)."));
  // controls.keys is a table of action = "key name", read and written by settings.cpp.
  return t;
}

std::string number_text(double v, bool single_precision) {
  char buf[64];
  // Shortest text that reads back to the same value, at the precision it is stored in.
  const auto end = single_precision
                       ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(v)).ptr
                       : std::to_chars(buf, buf + sizeof buf, v).ptr;
  std::string text(buf, end);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // a TOML float, not an int
  return text;
}

// A TOML basic string: quoted, with backslash, quote and control characters escaped.
std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04X", u);
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::span<const SettingSpec> settings_table() {
  static const std::vector<SettingSpec> table = make_table();
  return table;
}

const SettingSpec* find_setting(const std::string& key) {
  for (const SettingSpec& spec : settings_table())
    if (key == spec.key) return &spec;
  return nullptr;
}

std::span<const SettingsSection> settings_sections() {
  static const SettingsSection sections[] = {
      {"plugins", ""},
      {"device", ""},
      {"cache", ""},
      {"render", ""},
      {"render.effects",
       "Effects a scene may ask for; false switches one off, and its code is then not compiled."},
      {"window",
       "The explorer (`fractalis explore`, or ./scripts/run.sh on a machine with a "
       "display)."},
      {"explorer", ""},
      {"controls", ""},
  };
  return sections;
}

std::string check_setting(const SettingSpec& spec, const SettingValue& value) {
  std::ostringstream range;
  range << spec.min << ", " << spec.max << "]";
  switch (spec.kind) {
    case SettingKind::Bool:
      return std::holds_alternative<bool>(value) ? "" : "expected true or false";
    case SettingKind::Int: {
      const auto* v = std::get_if<long long>(&value);
      if (!spec.only_ints.empty()) {
        bool listed = v && std::find(spec.only_ints.begin(), spec.only_ints.end(), *v) !=
                               spec.only_ints.end();
        return listed ? "" : std::string("expected ") + spec.only_ints_text;
      }
      if (!v || *v < spec.min || *v > spec.max) return "expected an integer in [" + range.str();
      return "";
    }
    case SettingKind::Number: {
      const double* d = std::get_if<double>(&value);
      std::optional<double> v;
      if (d) v = *d;
      if (const auto* i = std::get_if<long long>(&value)) v = static_cast<double>(*i);
      const bool above_min = v && (spec.min_open ? *v > spec.min : *v >= spec.min);
      if (!v || !std::isfinite(*v) || !above_min || !(*v <= spec.max))
        return std::string("expected a number in ") + (spec.min_open ? "(" : "[") + range.str();
      return "";
    }
    case SettingKind::Choice: {
      const auto* v = std::get_if<std::string>(&value);
      std::string names;
      for (const SettingChoice& c : spec.choices) {
        if (v && *v == c.name) return "";
        names += (names.empty() ? "\"" : ", \"") + std::string(c.name) + "\"";
      }
      return "expected one of " + names;
    }
    case SettingKind::Text:
      if (!std::holds_alternative<std::string>(value)) return "expected a string";
      return spec.check ? spec.check(value) : "";
    case SettingKind::TextList:
      return std::holds_alternative<std::vector<std::string>>(value)
                 ? ""
                 : "expected an array of strings (folder paths)";
    case SettingKind::Color: {
      const auto* c = std::get_if<SettingColor>(&value);
      const bool ok = c && std::all_of(c->begin(), c->end(), [&](double x) {
        return std::isfinite(x) && x >= spec.min && x <= spec.max;
      });
      return ok ? "" : "expected [r, g, b], each a number in [" + range.str();
    }
  }
  return "unknown setting kind";
}

std::string toml_basic_string(const std::string& text) {
  return toml_string(text);
}

std::string setting_value_toml(const SettingSpec& spec, const SettingValue& value) {
  return std::visit(
      [&](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>)
          return "\"\"";
        else if constexpr (std::is_same_v<T, bool>)
          return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, long long>)
          return std::to_string(v);
        else if constexpr (std::is_same_v<T, double>)
          return number_text(v, spec.single_precision);
        else if constexpr (std::is_same_v<T, std::string>)
          return toml_string(v);
        else if constexpr (std::is_same_v<T, SettingColor>) {
          std::string out = "[";
          for (size_t i = 0; i < 3; ++i) out.append(i ? ", " : "").append(number_text(v[i], true));
          return out.append("]");
        }
        else {
          std::string out = "[";
          for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + toml_string(v[i]);
          return out + "]";
        }
      },
      value);
}

}  // namespace fr
