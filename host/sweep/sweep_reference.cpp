#include "sweep/sweep_reference.hpp"

#include "io/atomic_file.hpp"
#include "io/fnv1a.hpp"
#include "render/camera.hpp"
#include "render/kernel_assembly.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <type_traits>

namespace fr {
namespace {

constexpr char kMagic[8] = {'F', 'R', 'S', 'W', 'R', 'E', 'F', '1'};

template <typename T>
void append(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <typename T>
void append_vector(std::string& out, const std::vector<T>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

bool read_cache(const std::filesystem::path& file, const RenderSettings& s, SweepReference* r) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return false;
  char magic[8];
  int32_t w = 0, h = 0, refinements = 0;
  double k = 0, mae = 0, depth = 0;
  in.read(magic, 8);
  in.read(reinterpret_cast<char*>(&w), 4);
  in.read(reinterpret_cast<char*>(&h), 4);
  in.read(reinterpret_cast<char*>(&refinements), 4);
  in.read(reinterpret_cast<char*>(&k), 8);
  in.read(reinterpret_cast<char*>(&mae), 8);
  in.read(reinterpret_cast<char*>(&depth), 8);
  if (!in || std::memcmp(magic, kMagic, 8) != 0 || w != s.width_px || h != s.height_px)
    return false;
  const size_t n = size_t(w) * h;
  ReferenceImage img;
  img.width_px = w;
  img.height_px = h;
  img.rgba8.resize(n * 4);
  img.depth.resize(n);
  img.normal.resize(n * 3);
  in.read(reinterpret_cast<char*>(img.rgba8.data()), n * 4);
  in.read(reinterpret_cast<char*>(img.depth.data()), n * 4);
  in.read(reinterpret_cast<char*>(img.normal.data()), n * 12);
  if (!in || in.peek() != EOF) return false;
  r->image = std::move(img);
  r->refinements = refinements;
  r->hit_threshold_k = k;
  r->convergence_mae = mae;
  r->convergence_depth_px = depth;
  r->from_cache = true;
  return true;
}

std::string cache_bytes(const SweepReference& r) {
  std::string out(kMagic, 8);
  append(out, int32_t(r.image.width_px));
  append(out, int32_t(r.image.height_px));
  append(out, int32_t(r.refinements));
  append(out, r.hit_threshold_k);
  append(out, r.convergence_mae);
  append(out, r.convergence_depth_px);
  append_vector(out, r.image.rgba8);
  append_vector(out, r.image.depth);
  append_vector(out, r.image.normal);
  return out;
}

}  // namespace

RenderSettings reference_settings(const RenderSettings& base, int path_samples) {
  RenderSettings ref = base;
  ref.precision = Precision::Double;
  ref.relaxation = 1;
  ref.cone_prepass = false;  // every ray marches from its own origin
  ref.max_steps = 5000;
  ref.shadow_max_steps = std::max(ref.shadow_max_steps, 1024);
  ref.bounce_max_steps = ref.max_steps;
  ref.bounce_shadow_max_steps = ref.shadow_max_steps;
  ref.normals = NormalMethod::CentralDifferences;
  ref.refine_steps = 0;
  ref.fast_math = false;
  ref.step_scale = std::min(ref.step_scale, 1.0f);  // a scale above 1 over-steps: never truth
  ref.denoise = false;  // the filter's bias is an error the truth must not have
  // (the refinements render 1, for geometry, and these)
  ref.samples = ref.integrator == Integrator::Path ? path_samples : kReferenceSamples;
  // What only says how the frame is read or watched, not what it shows.
  ref.outputs = Readback::Everything;
  ref.count_evaluations = false;
  ref.watchdog_s = 0;
  return ref;
}

std::string reference_key(const SceneInfo& info, const SceneState& state, const RenderSettings& s,
                          const std::string& device_name, int path_samples) {
  std::ostringstream k;
  k.precision(17);
  k << info.id << '\n' << info.version << '\n' << device_name << '\n';
  for (const fr_value& v : state.params) k << v.v[0] << ',' << v.v[1] << ',' << v.v[2] << ';';
  const fr_camera& c = state.camera;
  for (int a = 0; a < 3; ++a) k << c.eye[a] << ',' << c.target[a] << ',' << c.up[a] << ';';
  k << c.fov_deg << '\n';
  for (const fr_light& l : state.lights) {
    k << l.kind << ':' << l.intensity << ':' << l.attenuation << ':' << l.falloff << ':'
      << l.radius;
    for (int a = 0; a < 3; ++a) k << ',' << l.vector[a] << ',' << l.color[a];
    k << ';';
  }
  k << state.time_s << ',' << state.bounding_radius << '\n';
  // Every field of the settings the reference is rendered with.
  const RenderSettings ref = reference_settings(s, path_samples);
  visit_render_fields(ref, [&](const char* name, const auto& value) {
    k << name << '=';
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_enum_v<T>)
      k << static_cast<long long>(value);
    else if constexpr (std::is_same_v<T, std::array<float, 3>>)
      k << value[0] << ',' << value[1] << ',' << value[2];
    else if constexpr (std::is_same_v<T, PathText>)
      k << std::quoted(std::string(value.view()));  // the file's name, not its content
    else
      k << value;
    k << ' ';
  });
  // The kernel source itself: a changed renderer or DE is a new reference.
  k << '\n' << assemble_render_kernel(info, state.params, make_kernel_config(info, ref, 1)).source;
  return hex16(fnv1a(k.str()));
}

SweepReference make_reference(RenderWorker& renderer, const SceneInfo& info,
                              const SceneState& state, const RenderSettings& settings,
                              const std::string& device_name,
                              const std::filesystem::path& cache_dir,
                              const std::function<bool(double, int)>& progress,
                              std::string* warning, int path_samples) {
  const auto file =
      cache_dir / (reference_key(info, state, settings, device_name, path_samples) + ".ref");
  SweepReference r;
  RenderSettings ref = reference_settings(settings, path_samples);
  const int picture_samples = ref.samples;
  r.samples = picture_samples;
  if (read_cache(file, settings, &r)) return r;

  const bool path = ref.integrator == Integrator::Path;
  const double pixel_angle =
      make_camera_rays(state.camera, settings.width_px, settings.height_px).pixel_angle_rad;
  ReferenceImage previous;
  double k = settings.hit_threshold_k;
  for (int level = 0; level < 5; ++level, k /= 4) {
    if (progress && !progress(k, level)) return {};
    ref.hit_threshold_k = static_cast<float>(k);
    ref.samples = 1;  // centred rays: the geometry
    const FrameImage geometry = renderer.render(info, state, ref, true);
    ReferenceImage current;
    current.width_px = settings.width_px;
    current.height_px = settings.height_px;
    current.depth = geometry.depth;
    current.normal = geometry.normal;
    // The picture. A path-traced picture's noise moves it more than the threshold does at any
    // level, so there the surface alone decides, and the long picture is rendered once, at the
    // level that ends (it was rendered at every level: five times the time at most).
    const auto picture = [&] {
      ref.samples = picture_samples;
      current.rgba8 = renderer.render(info, state, ref).rgba8;
    };
    if (path)  // (black until then: the comparison below reads only the surface for it)
      current.rgba8.assign(geometry.rgba8.size(), 0);
    else
      picture();
    r.refinements = level + 1;
    r.hit_threshold_k = k;
    bool converged = false;
    if (level > 0) {
      const ErrorMetrics change =
          compare_to_reference(reference_as_frame(current), previous, pixel_angle);
      r.convergence_mae = path ? 0 : change.mean_abs_error;
      r.convergence_depth_px = change.depth_median_px;
      // Converged: the picture moved by less than a quarter of an 8-bit level on average, and
      // the surface by less than 2% of a footprint.
      converged = (path || change.mean_abs_error < 0.25) && change.depth_median_px < 0.02;
    }
    if (path && (converged || level == 4)) {
      if (progress && !progress(k, level)) return {};  // (the long render's own report)
      picture();
    }
    previous = current;
    r.image = std::move(current);
    if (converged) break;
  }
  std::error_code ec;
  std::filesystem::create_directories(cache_dir, ec);
  std::string error;
  if (ec || !write_file_atomic(file, cache_bytes(r), &error))
    *warning = "could not cache the reference in " + cache_dir.string() + ": " +
               (ec ? ec.message() : error);
  return r;
}

}  // namespace fr
