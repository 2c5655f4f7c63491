#include "render/kernel_assembly.hpp"

#include "render/cl_runtime.hpp"
#include "render/kernel_sources.hpp"
#include "render/scene_source_guard.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <initializer_list>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace fr {
namespace {

// The optional renderer stages and the names users see. A stage is in the kernel when its file
// is (kRenderPipeline below): each file defines the hooks render.cl calls (FR_APPLY_AO, ...).
struct OptionalStage {
  fr_features feature;
  const char* name;
};
const OptionalStage kOptionalStages[] = {
    {kStageDepthOfField, "dof"}, {FR_FEATURE_GLOW, "glow"},
    {FR_FEATURE_AO, "ao"},       {FR_FEATURE_SHADOWS, "shadows"},
    {FR_FEATURE_FOG, "fog"},     {FR_FEATURE_REFLECTIONS, "reflections"},
};

// The render kernel's files in the order they are pasted (each uses only what comes before it);
// a file with a stage is left out when that stage is off, and a file of one integrator when the
// other is chosen. The one place this order is kept.
enum class For { Both, Fast, Path };
struct PipelineFile {
  fr_features stage;  // 0: always
  const char* file;
  For integrator = For::Both;
};
const PipelineFile kRenderPipeline[] = {
    {0, "eval_counts.cl"},
    {0, "rays.cl"},
    {kStageDepthOfField, "lens.cl"},
    {FR_FEATURE_GLOW, "glow.cl"},
    {0, "march.cl"},
    {kStageCone, "cone.cl"},
    {0, "normals.cl"},
    {FR_FEATURE_AO, "ao.cl"},
    {0, "lights.cl"},
    {FR_FEATURE_SHADOWS, "shadow.cl"},
    {kStageEnvironment, "environment.cl"},
    {0, "shade.cl"},
    {FR_FEATURE_FOG, "fog.cl"},
    {FR_FEATURE_REFLECTIONS, "reflect.cl"},
    {0, "film.cl"},
    {0, "render.cl", For::Fast},
    {0, "material.cl", For::Path},
    {0, "area_lights.cl", For::Path},
    {0, "path.cl", For::Path},
};

// What the host's kernel files define: the prelude and the DE library come before a scene's
// code, every render stage and the probe after it.
const HostKernelNames& host_kernel_names() {
  static const HostKernelNames names = [] {
    std::vector<std::string_view> before = {kernel_source("frame_constants.h"),
                                            kernel_source("wide_lanes.cl"),
                                            kernel_source("prelude.cl")};
    for (const auto& library : kernel_library_files())
      before.push_back(kernel_source("de/" + library.substr(3)));
    std::vector<std::string_view> after = {kernel_source("probe.cl"),
                                           kernel_source("material_probe.cl")};
    for (const PipelineFile& f : kRenderPipeline) after.push_back(kernel_source(f.file));
    return collect_host_names(before, after);
  }();
  return names;
}

// `#define FAMILY_VALUE n` for every value of the enum (numbered by its row in the enum's name
// table), then `#define FAMILY FAMILY_CHOSEN`: kernels compare names, never numbers.
template <typename Enum>
void define_choice(std::ostringstream& out, const char* family, Enum chosen) {
  int number = 0;
  for (const auto& row : enum_names(chosen))
    out << "#define " << row.kernel_define << " " << number++ << "\n";
  out << "#define " << family << " " << enum_row(chosen).kernel_define << "\n";
}

const fr_features kSceneStages =
    FR_FEATURE_SHADOWS | FR_FEATURE_AO | FR_FEATURE_GLOW | FR_FEATURE_FOG | FR_FEATURE_REFLECTIONS;

void append_file(std::ostringstream& out, std::string_view name, std::string_view text) {
  out << "#line 1 \"" << name << "\"\n" << text;
  if (!text.empty() && text.back() != '\n') out << '\n';
}

// Pastes `text` with its #include "fr/NAME.cl" lines replaced by the library files (each once,
// recursively), keeping line numbers right with #line directives. Unless `pairs`, an include
// inside an `#if FR_DD` block (a scene's pair estimate, compiled out there) is left out: the
// kernel then holds only what it compiles.
void append_with_includes(std::ostringstream& out, const std::string& scene_id,
                          std::string_view name, std::string_view text,
                          std::set<std::string>& included, bool pairs) {
  out << "#line 1 \"" << name << "\"\n";
  std::istringstream lines{std::string(text)};
  std::string line;
  int number = 0;
  // Per open #if: whether it lies in a pairs-only block, and whether it opened one.
  std::vector<std::pair<bool, bool>> blocks;
  const auto directive = [](const std::string& l, size_t at, const char* word) {
    return l.compare(at, std::strlen(word), word) == 0;
  };
  while (std::getline(lines, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t");
    const bool in_pairs_block = !blocks.empty() && blocks.back().first;
    if (first != std::string::npos && line[first] == '#') {
      std::string trimmed = line.substr(first);
      trimmed.erase(trimmed.find_last_not_of(" \t\r") + 1);
      if (trimmed == "#if FR_DD") {
        blocks.push_back({true, true});
      } else if (directive(line, first, "#if")) {  // #if, #ifdef, #ifndef
        blocks.push_back({in_pairs_block, false});
      } else if ((directive(line, first, "#else") || directive(line, first, "#elif")) &&
                 !blocks.empty() && blocks.back().second) {
        blocks.back() = {blocks.size() > 1 && blocks[blocks.size() - 2].first, false};
      } else if (directive(line, first, "#endif") && !blocks.empty()) {
        blocks.pop_back();
      }
    }
    if (!pairs && in_pairs_block && first != std::string::npos &&
        line.compare(first, 8, "#include") == 0) {
      out << '\n';
      continue;
    }
    if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
      const auto open = line.find('"'), close = line.rfind('"');
      const std::string target =
          open != std::string::npos && close > open ? line.substr(open + 1, close - open - 1) : "";
      const auto library = kernel_library_files();
      if (target.rfind("fr/", 0) != 0 ||
          std::find(library.begin(), library.end(), target) == library.end()) {
        std::string names;
        for (const auto& l : library) names += (names.empty() ? "" : ", ") + l;
        throw KernelBuildError("scene '" + scene_id + "': " + std::string(name) + ":" +
                               std::to_string(number) + ": unknown library file '" +
                               (target.empty() ? line : target) +
                               "' (the DE library has: " + names + ")");
      }
      if (included.insert(target).second)
        append_with_includes(out, scene_id, target, kernel_source("de/" + target.substr(3)),
                             included, pairs);
      out << "#line " << number + 1 << " \"" << name << "\"\n";
      continue;
    }
    out << line << '\n';
  }
}

// Writes a number so that OpenCL C reads it back exactly, in the kernel's precision.
std::string literal(double v, Precision p) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  std::string text = s.str();
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return "((scalar_t)" + text + (p == Precision::Float ? "f" : "") + ")";
}

// Double and double-double kernels compute in double (scalar_t); a float kernel in float.
bool computes_in_double(Precision p) {
  return p == Precision::Double || p == Precision::DoubleDouble;
}

void append_params(std::ostringstream& out, const SceneInfo& info,
                   const std::vector<fr_value>& values, Precision precision) {
  // A number travels as three floats, its value rounded to float and the rest in two more
  // (key__mid, key__lo), so that a double kernel gets the host's double back exactly (a deep
  // view of an imported scene moves by a float-rounded rotation angle or constant); a float
  // kernel reads key alone. (mid + lo is exact in double, and so is adding it to key.)
  const auto number = [&](const std::string& key, const char* index) {
    const std::string hi = "(scalar_t)params->" + key + index;
    if (!computes_in_double(precision)) return "(" + hi + ")";
    return "(" + hi + " + ((scalar_t)params->" + key + "__mid" + index + " + (scalar_t)params->" +
           key + "__lo" + index + "))";
  };
  out << "/* Generated from the scene's parameter table. */\n";
  out << "typedef struct scene_params_t {\n";
  int runtime_count = 0;
  for (const ParamInfo& p : info.params) {
    if (p.specialized()) continue;
    ++runtime_count;
    switch (p.type) {
      case FR_PARAM_FLOAT:
        out << "  float " << p.key << ";\n  float " << p.key << "__mid;\n  float " << p.key
            << "__lo;\n";
        break;
      case FR_PARAM_INT:
      case FR_PARAM_BOOL:
      case FR_PARAM_CHOICE:
        out << "  int " << p.key << ";\n";
        break;
      default:
        out << "  float " << p.key << "[3];\n  float " << p.key << "__mid[3];\n  float " << p.key
            << "__lo[3];\n";
        break;
    }
  }
  if (precision == Precision::DoubleDouble) {
    // The frame's origin (pack_scene_params, PairOrigin): dd_relative.cl reads it.
    out << "  uint fr_eye_bits[12]; /* x.hi, x.lo, y.hi, ...: each double as (low word, high word) "
           "*/\n  float fr_resolution_rad; /* the estimate's resolution over the distance from "
           "the eye */\n";
    ++runtime_count;
  }
  if (runtime_count == 0) out << "  int unused; /* OpenCL C has no empty structs */\n";
  out << "} scene_params_t;\n";
  out << "#define PARAM(key) FR_PARAM_##key\n";
  for (size_t i = 0; i < info.params.size(); ++i) {
    const ParamInfo& p = info.params[i];
    const fr_value& v = values[i];
    out << "#define FR_PARAM_" << p.key << " ";
    if (p.specialized()) {
      switch (p.type) {
        case FR_PARAM_FLOAT:
          out << literal(v.v[0], precision);
          break;
        case FR_PARAM_INT:
        case FR_PARAM_BOOL:
        case FR_PARAM_CHOICE:
          out << "(" << static_cast<long long>(v.v[0]) << ")";
          break;
        default:
          out << "v3s(" << literal(v.v[0], precision) << ", " << literal(v.v[1], precision) << ", "
              << literal(v.v[2], precision) << ")";
      }
    } else {
      switch (p.type) {
        case FR_PARAM_FLOAT:
          out << number(p.key, "");
          break;
        case FR_PARAM_INT:
        case FR_PARAM_BOOL:
        case FR_PARAM_CHOICE:
          out << "(params->" << p.key << ")";
          break;
        default:
          out << "v3s(" << number(p.key, "[0]") << ", " << number(p.key, "[1]") << ", "
              << number(p.key, "[2]") << ")";
      }
    }
    out << "\n";
    for (size_t c = 0; c < p.choices.size(); ++c)
      out << "#define FR_CHOICE_" << p.key << "_" << p.choices[c] << " " << c << "\n";
  }
}

// What every kernel of a scene starts with: defines, shared structs, prelude, parameter block,
// the scene's DE and (for rendering) its surface source.
void append_scene_prefix(std::ostringstream& out, const SceneInfo& info,
                         const std::vector<fr_value>& values, const KernelConfig& config,
                         const char* kind, bool with_surface) {
  const bool has_surface = with_surface && !info.surface_source.empty();
  out << "/* Fractalis " << kind << " kernel for scene '" << info.id
      << "'. Generated; see kernels/. */\n";
  out << "#define FR_LANES " << config.lanes << "\n";
  out << "#define FR_DOUBLE " << (computes_in_double(config.precision) ? 1 : 0) << "\n";
  out << "#define FR_DD " << (config.precision == Precision::DoubleDouble ? 1 : 0) << "\n";
  define_choice(out, "FR_SHADING", config.shading);
  define_choice(out, "FR_NORMALS", config.normals);
  define_choice(out, "FR_AO", config.ao_method);
  define_choice(out, "FR_SHADOW", config.shadow_method);
  define_choice(out, "FR_FOG", config.fog_method);
  out << "#define FR_HAS_SURFACE " << (has_surface ? 1 : 0) << "\n";
  // The surface source's optional material function (path tracing; prelude.cl's material_t).
  const bool has_material = has_surface && has_material_function(info);
  out << "#define FR_SCENE_MATERIAL " << (has_material ? 1 : 0) << "\n";
  out << "#define FR_COUNT_EVALS " << (config.count_evaluations ? 1 : 0) << "\n";
  out << "#define FR_RELAX_ADAPTIVE " << (config.adaptive_relaxation ? 1 : 0) << "\n";
  // 0: colour; 1: and steps and ray status; 2: every pass (render.cl).
  out << "#define FR_OUTPUTS " << static_cast<int>(config.outputs) << "\n";
  append_file(out, "frame_constants.h", kernel_source("frame_constants.h"));
  append_file(out, "wide_lanes.cl", kernel_source("wide_lanes.cl"));
  append_file(out, "prelude.cl", kernel_source("prelude.cl"));
  append_params(out, info, values, config.precision);
  // The scene's own code, kept from the host's (scene_source_guard.hpp): checked first, and
  // every macro it defines or undefines saved before it and restored after it. (Restored, not
  // just undefined: the OpenCL implementation's own headers define built-ins such as fmax as
  // macros, and a scene's `#define fmax` would otherwise take them from the host's code.)
  std::vector<std::string> scene_macros =
      guard_scene_source(info.id, info.de_source_name, info.de_source, host_kernel_names());
  if (has_surface)
    for (auto& m : guard_scene_source(info.id, info.surface_source_name, info.surface_source,
                                      host_kernel_names()))
      scene_macros.push_back(std::move(m));
  std::sort(scene_macros.begin(), scene_macros.end());
  scene_macros.erase(std::unique(scene_macros.begin(), scene_macros.end()), scene_macros.end());
  for (const auto& m : scene_macros) out << "#pragma push_macro(\"" << m << "\")\n";
  std::set<std::string> included;
  const bool pairs = config.precision == Precision::DoubleDouble;
  append_with_includes(out, info.id, info.de_source_name, info.de_source, included, pairs);
  if (has_surface)
    append_with_includes(out, info.id, info.surface_source_name, info.surface_source, included,
                         pairs);
  if (!scene_macros.empty()) out << "/* The scene's macros end with its code. */\n";
  for (const auto& m : scene_macros) out << "#pragma pop_macro(\"" << m << "\")\n";
  // A double-double kernel: every stage's scene_de becomes the scene's pair estimate at the eye
  // plus the stage's point, which is relative to the eye.
  if (config.precision == Precision::DoubleDouble)
    append_file(out, "dd_relative.cl", kernel_source("dd_relative.cl"));
}

AssembledKernel finish(std::ostringstream& out, const SceneInfo& info, const KernelConfig& config,
                       const char* kind) {
  AssembledKernel k;
  k.source = out.str();
  // No -cl-fast-relaxed-math: it permits atan2 as atan(y/x) and finite-math-only, which break
  // the DEs' polar-axis and origin guards, and on PoCL it measured no faster (Mandelbulb 640x360:
  // 205 ms with it, 200 ms without, before the exp2/native trig changes). mad contraction costs
  // little accuracy and is checked against the double build by the tests. render.fast_math
  // turns it on for experiments; the stability tier renders with it.
  // -w: PoCL's compiler otherwise prints "247 warnings generated." on the terminal for every
  // kernel it builds on a CPU without AVX-512 (each a -Wpsabi note that a float16 argument is
  // passed in memory there), and nothing of them reaches anyone who could act on it; errors,
  // with the build log, still do.
  k.build_options = "-cl-std=CL1.2 -cl-mad-enable -w";
  // Double-double's error terms need every rounding as written: no contraction, no fast math
  // (on PoCL either zeroes them; the self-test, render/dd_selftest.hpp, shows it).
  if (config.precision == Precision::DoubleDouble)
    k.build_options = "-cl-std=CL1.2 -w";
  else if (config.fast_math)
    k.build_options += " -cl-fast-relaxed-math";
  if (config.quick_build) k.build_options += " -cl-opt-disable";
  k.description = "scene '" + info.id + "' " + kind + " kernel (" +
                  (config.integrator == Integrator::Path ? "path tracing, " : "") + "lanes " +
                  std::to_string(config.lanes) + ", " + enum_row(config.precision).label +
                  ", stages: " + stage_names(config.stages) +
                  ((config.stages & kStageCone) ? ", cone pre-pass" : "") +
                  ((config.stages & kStageEnvironment) ? ", environment image" : "") +
                  (config.count_evaluations ? ", counting DE evaluations" : "") +
                  (config.quick_build ? ", quick build" : "") + ")";
  return k;
}

}  // namespace

TileShape tile_shape(int lanes) {
  switch (lanes) {
    case 64:
      return {8, 8};
    case 32:
      return {8, 4};
    case 16:
      return {4, 4};
    case 8:
      return {4, 2};
    case 4:
      return {2, 2};
    default:
      return {1, 1};
  }
}

fr_features enabled_stages(const SceneInfo& info, fr_features disabled_by_user) {
  return info.features & kSceneStages & ~disabled_by_user;
}

KernelConfig make_kernel_config(const SceneInfo& info, const RenderSettings& s, int lanes) {
  KernelConfig c;
  c.lanes = lanes;
  c.precision = s.precision == Precision::Auto ? Precision::Float : s.precision;
  c.stages = enabled_stages(info, s.disabled_stages);
  if (s.aperture_radius > 0 && !(s.disabled_stages & kStageDepthOfField))
    c.stages |= kStageDepthOfField;
  // The lens moves every ray's origin: the block's rays no longer share a cone.
  else if (s.cone_prepass)
    c.stages |= kStageCone;
  if (!s.environment.empty()) c.stages |= kStageEnvironment;
  c.integrator = s.integrator;
  if (s.integrator == Integrator::Path) {
    // The path tracer computes what occlusion, glow, fog and mirror bounces approximate, and
    // needs every light's visibility, exactly: hard shadows, whatever the scene asks for.
    c.stages =
        (c.stages & (kStageDepthOfField | kStageCone | kStageEnvironment)) | FR_FEATURE_SHADOWS;
    c.shadow_method = ShadowMethod::Hard;
  } else {
    c.shadow_method = s.shadow_method;
  }
  c.shading = s.shading;
  c.normals = s.normals;
  c.ao_method = s.ao_method;
  c.fog_method = s.fog_method;
  c.fast_math = s.fast_math;
  c.quick_build = s.quick_build;
  c.count_evaluations = s.count_evaluations;
  c.adaptive_relaxation = s.adaptive_relaxation;
  c.outputs = s.outputs;
  return c;
}

fr_features all_optional_stages() {
  fr_features all = 0;
  for (const auto& s : kOptionalStages) all |= s.feature;
  return all;
}

std::string stage_names(fr_features stages) {
  std::string out;
  for (const auto& s : kOptionalStages)
    if (stages & s.feature) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out.empty() ? "none" : out;
}

AssembledKernel assemble_render_kernel(const SceneInfo& info, const std::vector<fr_value>& values,
                                       const KernelConfig& config) {
  std::ostringstream out;
  append_scene_prefix(out, info, values, config, "render", true);
  const For integrator = config.integrator == Integrator::Path ? For::Path : For::Fast;
  for (const PipelineFile& f : kRenderPipeline)
    if ((f.stage == 0 || (config.stages & f.stage)) &&
        (f.integrator == For::Both || f.integrator == integrator))
      append_file(out, f.file, kernel_source(f.file));
  return finish(out, info, config, "render");
}

namespace {
// A probe kernel: the scene's code (with its surface source or not) and `files` after it, built
// for the config's lanes and precision alone.
AssembledKernel assemble_probe(const SceneInfo& info, const std::vector<fr_value>& values,
                               const KernelConfig& config, const char* kind, bool with_surface,
                               std::initializer_list<const char*> files) {
  std::ostringstream out;
  KernelConfig bare;
  bare.lanes = config.lanes;
  bare.precision = config.precision;
  append_scene_prefix(out, info, values, bare, kind, with_surface);
  for (const char* f : files) append_file(out, f, kernel_source(f));
  return finish(out, info, bare, kind);
}
}  // namespace

AssembledKernel assemble_probe_kernel(const SceneInfo& info, const std::vector<fr_value>& values,
                                      const KernelConfig& config) {
  return assemble_probe(info, values, config, "DE probe", false, {"probe.cl"});
}

bool has_material_function(const SceneInfo& info) {
  return !info.surface_source.empty() &&
         source_defines_function(info.surface_source, "scene_material");
}

AssembledKernel assemble_material_probe_kernel(const SceneInfo& info,
                                               const std::vector<fr_value>& values,
                                               const KernelConfig& config) {
  return assemble_probe(info, values, config, "material probe", true,
                        {"material.cl", "material_probe.cl"});
}

bool has_pair_estimate(const SceneInfo& info) {
  return source_defines_function(info.de_source, "scene_de_dd");
}

namespace {

// A double as three floats whose sum is exactly it.
struct FloatSplit {
  float hi = 0, mid = 0, lo = 0;
};

FloatSplit split_in_floats(double v) {
  FloatSplit s;
  s.hi = static_cast<float>(v);
  const double rest = v - static_cast<double>(s.hi);
  s.mid = static_cast<float>(rest);
  s.lo = static_cast<float>(rest - static_cast<double>(s.mid));
  return s;
}

}  // namespace

std::vector<uint8_t> pack_scene_params(const SceneInfo& info, const std::vector<fr_value>& values,
                                       const PairOrigin* origin) {
  std::vector<uint8_t> bytes;
  auto push = [&](const void* p) {
    const auto* b = static_cast<const uint8_t*>(p);
    bytes.insert(bytes.end(), b, b + 4);
  };
  for (size_t i = 0; i < info.params.size(); ++i) {
    const ParamInfo& p = info.params[i];
    if (p.specialized()) continue;
    if (p.whole()) {
      int32_t v = static_cast<int32_t>(values[i].v[0]);
      push(&v);
    } else {
      // hi + mid + lo is the double exactly: each remainder is exact in double and has 24
      // fewer significant bits than the last. One component at a time through split_in_floats:
      // GCC 12's SLP vectorizer at -O3 turned the same arithmetic over float[3] arrays into a
      // round trip it dropped, losing the x and y components' rest (kernel_assembly_test).
      std::array<FloatSplit, 3> parts{};
      const int n = p.component_count();
      for (int c = 0; c < n; ++c) parts[c] = split_in_floats(values[i].v[c]);
      for (int c = 0; c < n; ++c) push(&parts[c].hi);
      for (int c = 0; c < n; ++c) push(&parts[c].mid);
      for (int c = 0; c < n; ++c) push(&parts[c].lo);
    }
  }
  if (origin) {
    for (int a = 0; a < 3; ++a)
      for (double part : {origin->eye[a].hi, origin->eye[a].lo}) {
        uint64_t bits = 0;
        std::memcpy(&bits, &part, sizeof bits);
        const uint32_t low = static_cast<uint32_t>(bits), high = static_cast<uint32_t>(bits >> 32);
        push(&low);
        push(&high);
      }
    push(&origin->resolution_rad);
  }
  if (bytes.empty()) bytes.assign(4, 0);
  return bytes;
}

}  // namespace fr
