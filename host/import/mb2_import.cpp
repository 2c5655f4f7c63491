#include "import/mb2_import.hpp"

#include "import/fract_values.hpp"
#include "import/mb2_defaults.hpp"
#include "import/mb2_palette.hpp"
#include "io/echo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace fr {
namespace {

using Kind = ImportNote::Kind;

// Mandelbulber2 2.20's formula ids that the scene has, with its kind names (mandelbulber.c).
struct Formula {
  int id;
  const char* kind;             // the scene's choice name
  const char* estimate;         // the analytic estimate of the formula alone
  const char* hybrid_estimate;  // its DE-function family in a hybrid: linear, logarithmic, pk
  bool adds_c;                  // c added unless dont_add_c_constant (else only with it)
  double bailout;               // its default bailout
};
const Formula kFormulas[] = {
    {2, "mandelbulb", "logarithmic", "logarithmic", true, 10},
    {3, "power2", "logarithmic", "logarithmic", true, 10},
    {4, "hypercomplex", "logarithmic", "logarithmic", true, 10},
    {5, "quaternion", "logarithmic", "logarithmic", true, 10},
    {7, "menger", "ifs", "linear", false, 10},
    {8, "mandelbox", "linear", "linear", true, 100},
    {10, "kifs", "ifs", "linear", false, 100},
    {103, "pseudo_kleinian", "pseudo_kleinian", "pseudo_kleinian", false, 100},
};

// Names of other formulas the examples use, for refusals that say what the formula is.
// clang-format off
const std::map<long long, const char*> kOtherFormulaNames = {
    {11, "xenodreambuie"}, {13, "mandelbulb2"}, {14, "mandelbulb3"}, {15, "mandelbulb4"},
    {16, "box_fold_bulb_pow2"}, {17, "mandelbox_smooth"}, {18, "mandelbox_vary_scale4d"},
    {19, "aexion"}, {20, "benesi"}, {21, "bristorbrot"}, {101, "pseudo_kleinian_std_de"},
    {104, "pseudo_kleinian_mod1"}, {117, "pseudo_kleinian_mod2"}};
// clang-format on

const Formula* find_formula(long long id) {
  for (const Formula& f : kFormulas)
    if (f.id == id) return &f;
  return nullptr;
}

// Each kind's parameters: the scene's key and the [fractal_N] key it comes from.
struct KindParam {
  const char* scene_key;
  const char* fract_key;
  enum Type { Number, Vec3, Bool, Degrees, Degrees3, Direction } type;
};
const std::map<std::string, std::vector<KindParam>> kKindParams = {
    {"mandelbulb",
     {{"bulb_power", "power", KindParam::Number},
      {"bulb_alpha", "alpha_angle_offset", KindParam::Degrees},
      {"bulb_beta", "beta_angle_offset", KindParam::Degrees}}},
    {"mandelbox",
     {{"box_scale", "mandelbox_scale", KindParam::Number},
      {"box_fold_limit", "mandelbox_folding_limit", KindParam::Number},
      {"box_fold_value", "mandelbox_folding_value", KindParam::Number},
      {"box_min_radius", "mandelbox_folding_min_radius", KindParam::Number},
      {"box_fixed_radius", "mandelbox_folding_fixed_radius", KindParam::Number},
      {"box_offset", "mandelbox_offset", KindParam::Vec3},
      {"box_main_rotation", "mandelbox_main_rotation_enabled", KindParam::Bool},
      {"box_rotation", "mandelbox_rotation_main", KindParam::Degrees3},
      {"box_fold_rotations", "mandelbox_rotations_enabled", KindParam::Bool},
      {"box_rotation_neg_1", "mandelbox_rotation_neg_1", KindParam::Degrees3},
      {"box_rotation_neg_2", "mandelbox_rotation_neg_2", KindParam::Degrees3},
      {"box_rotation_neg_3", "mandelbox_rotation_neg_3", KindParam::Degrees3},
      {"box_rotation_pos_1", "mandelbox_rotation_pos_1", KindParam::Degrees3},
      {"box_rotation_pos_2", "mandelbox_rotation_pos_2", KindParam::Degrees3},
      {"box_rotation_pos_3", "mandelbox_rotation_pos_3", KindParam::Degrees3}}},
    {"menger", {{"menger_scale", "transf_scale_3", KindParam::Number}}},
    {"kifs",
     [] {
       std::vector<KindParam> v = {
           {"kifs_scale", "IFS_scale", KindParam::Number},
           {"kifs_offset", "IFS_offset", KindParam::Vec3},
           {"kifs_rotation_enabled", "IFS_rotation_enabled", KindParam::Bool},
           {"kifs_rotation", "IFS_rotation", KindParam::Degrees3},
           {"kifs_edge", "IFS_edge", KindParam::Vec3},
           {"kifs_abs_x", "IFS_abs_x", KindParam::Bool},
           {"kifs_abs_y", "IFS_abs_y", KindParam::Bool},
           {"kifs_abs_z", "IFS_abs_z", KindParam::Bool},
           {"kifs_menger_mode", "IFS_menger_sponge_mode", KindParam::Bool}};
       static const char* const plane_keys[9][10] = {
#define FR_PLANE_KEYS(i)                                                                   \
  {                                                                                        \
    "kifs_plane" #i, "IFS_enabled_" #i, "kifs_plane" #i "_direction", "IFS_direction_" #i, \
        "kifs_plane" #i "_distance", "IFS_distance_" #i, "kifs_plane" #i "_intensity",     \
        "IFS_intensity_" #i, "kifs_plane" #i "_rotation", "IFS_rotations_" #i              \
  }
           FR_PLANE_KEYS(0), FR_PLANE_KEYS(1), FR_PLANE_KEYS(2), FR_PLANE_KEYS(3), FR_PLANE_KEYS(4),
           FR_PLANE_KEYS(5), FR_PLANE_KEYS(6), FR_PLANE_KEYS(7), FR_PLANE_KEYS(8)};
#undef FR_PLANE_KEYS
       for (const auto& k : plane_keys) {
         v.push_back({k[0], k[1], KindParam::Bool});
         v.push_back({k[2], k[3], KindParam::Direction});
         v.push_back({k[4], k[5], KindParam::Number});
         v.push_back({k[6], k[7], KindParam::Number});
         v.push_back({k[8], k[9], KindParam::Degrees3});
       }
       return v;
     }()},
    {"pseudo_kleinian",
     {{"pk_box", "transf_addition_constant_0777", KindParam::Vec3},
      {"pk_min_r2", "transf_minimum_radius_05", KindParam::Number},
      {"pk_tweak", "analyticDE_tweak_005", KindParam::Number},
      {"pk_de_offset", "analyticDE_scale_1", KindParam::Number},
      {"pk_offset", "transf_addition_constant", KindParam::Vec3}}},
};

// The pseudo-Kleinian's optional steps, which the scene does not have.
const std::pair<const char*, const char*> kPseudoKleinianOptions[] = {
    {"transf_function_enabledR_false", "its rotation"},
    {"transf_function_enabledBx_false", "its box fold"},
    {"transf_function_enabledBy_false", "its Tglad fold"},
    {"transf_function_enabledP_false", "its prism shape"},
    {"transf_sphere_inversion_enabled_false", "its sphere inversion"}};

// Main keys that do not change the picture (views of the GUI, animation, file paths, info).
// clang-format off
const std::set<std::string> kNotPicture = {
    "camera_rotation", "camera_distance_to_target", "image_width", "image_height",
    "image_proportion", "keyframe_last_to_render", "flight_last_to_render", "frames_per_keyframe",
    "flight_speed", "flight_rotation_speed_vector", "flight_movement_speed_vector", "info",
    "description", "stereo_eye_distance", "stereo_mode", "analityc_DE_mode",
    "coloring_random_seed", "mat1_coloring_random_seed", "DOF_samples", "DOF_min_samples",
    "DOF_max_noise", "DOF_monte_carlo", "DOF_number_of_passes", "voxel_custom_limit_enabled",
    "file_destination", "file_background", "file_envmap", "file_lightmap", "formula_maxiter"};
// clang-format on

std::string number_text(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  std::string s = buffer;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

std::string vec3_text(const std::array<double, 3>& v) {
  std::string s = "[";
  s.append(number_text(v[0])).append(", ").append(number_text(v[1])).append(", ");
  return s.append(number_text(v[2])).append("]");
}

// An angle in degrees brought into [-360, 360] (the scene's range): the same rotation.
double wrap_degrees(double deg) {
  return std::fmod(deg, 360.0);
}

// A display colour (Mandelbulber2 shades its colours as they are) as a linear one (Fractalis
// shades linear values and encodes the result).
std::array<double, 3> decoded(std::array<double, 3> c) {
  for (double& v : c) v = srgb_to_linear(v);
  return c;
}

double length(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

struct Importer {
  explicit Importer(const FractFile& file) : f(file) {}
  const FractFile& f;
  Mb2Import out;
  std::string camera_toml;
  std::string lights_toml;
  std::vector<std::pair<std::string, std::string>> params;    // scene key, TOML value
  std::vector<std::pair<std::string, std::string>> settings;  // settings key, TOML value
  std::set<std::string> handled;                              // main keys looked at

  void note(Kind kind, const std::string& item, const std::string& text) {
    out.notes.push_back({kind, item, text});
  }
  void refuse(const std::string& item, const std::string& text) { note(Kind::Refused, item, text); }

  FractEntry main(const std::string& key) {
    handled.insert(key);
    return mb2_main_entry(f, key);
  }
  double number(const std::string& key) { return fract_number(f, key, main(key)); }
  long long integer(const std::string& key) { return fract_integer(f, key, main(key)); }
  bool flag(const std::string& key) { return fract_bool(f, key, main(key)); }
  std::array<double, 3> vec3(const std::string& key) { return fract_vec3(f, key, main(key)); }
  // A colour key as Fractalis takes it: decoded from sRGB.
  std::array<double, 3> colour(const std::string& key) {
    return decoded(fract_colour(f, key, main(key)));
  }
  bool given(const std::string& key) const { return f.main.count(key) != 0; }
  // The scene's bounding radius: what Mandelbulber2 can see from the camera.
  double bound_radius() {
    return std::clamp(length(vec3("camera")) + number("view_distance_max"), 0.1, 1e6);
  }

  void param(const std::string& key, const std::string& toml) { params.emplace_back(key, toml); }
  void setting(const std::string& key, const std::string& toml) {
    settings.emplace_back(key, toml);
  }

  void run(const std::string& name);
  void version();
  void refuse_unsupported_features();
  void formulas();
  void camera();
  void quality();
  void look();
  void colouring();
  void unhandled_keys();
  std::string toml(const std::string& name) const;
};

void Importer::version() {
  if (f.version > kMb2NewestVersion + 1e-9) {
    char v[32];
    std::snprintf(v, sizeof v, "%.2f", f.version);
    refuse("version", std::string("version ") + v +
                          ": newer than Mandelbulber2 2.20, the format read here (2.21 changed "
                          "fov to degrees and later versions renamed the lights)");
  }
}

void Importer::refuse_unsupported_features() {
  if (flag("boolean_operators")) refuse("boolean_operators", "not supported");
  {
    const FractEntry e = main("perspective_type");
    const std::string t = e.value;
    if (t != "three_point" && t != "0") refuse("perspective_type " + echo(t), "not supported");
  }
  for (const char* key : {"interior_mode", "box_folding", "spherical_folding", "stereo_enabled"})
    if (flag(key)) refuse(key, "not supported");
  for (const char* key : {"fractal_position", "fractal_rotation", "repeat"}) {
    const auto v = vec3(key);
    if (v[0] != 0 || v[1] != 0 || v[2] != 0) refuse(key, "not supported");
  }
  if (number("initial_waxis") != 0) refuse("initial_waxis", "not supported");
  if (integer("minN") > 1) refuse("minN", "a minimum iteration count is not supported");
  if (integer("delta_DE_method") == 1)
    refuse("delta_DE_method", "the numerical (delta) distance estimate is not supported");
  // Primitives: enabled ones change the shape.
  std::set<std::string> primitives;
  for (const auto& [key, entry] : f.main) {
    if (key.rfind("primitive_", 0) != 0) continue;
    handled.insert(key);
    const size_t enabled = key.rfind("_enabled");
    if (enabled != std::string::npos && enabled + 8 == key.size() && fract_bool(f, key, entry))
      primitives.insert(key.substr(0, enabled));
  }
  for (const std::string& p : primitives) refuse(p, "primitives are not supported");
}

void Importer::formulas() {
  const bool hybrid = flag("hybrid_fractal_enable");
  const int slots = hybrid ? kFractFormulaSlots : 1;
  long long n = integer("N");
  if (n < 1 || n > 1000) refuse("N", std::to_string(n) + ": 1 to 1000 iterations are supported");
  n = std::clamp(n, 1LL, 1000LL);
  param("iterations", std::to_string(n));
  param("hybrid", hybrid ? "true" : "false");
  const long long repeat_from = integer("repeat_from");
  if (repeat_from < 1 || repeat_from > 9) refuse("repeat_from", "expected 1 to 9");
  param("repeat_from", std::to_string(std::clamp(repeat_from, 1LL, 9LL)));

  // Each slot's formula; a kind's parameters from the first slot using it, the others compared.
  std::map<std::string, int> kind_slot;  // kind -> first slot (0-based)
  std::map<std::string, long long> estimate_iterations;
  double bailout_max = 1;
  const Formula* first = nullptr;
  for (int s = 0; s < kFractFormulaSlots; ++s) {
    const std::string k = std::to_string(s + 1);
    const std::string slot = "slot " + k;
    const Formula* formula = nullptr;
    long long id = 0;
    if (s < slots) {
      id = integer("formula_" + k);
      if (!flag("fractal_enable_" + k)) id = 0;
    }
    if (id != 0) {
      formula = find_formula(id);
      if (!formula) {
        const auto named = kOtherFormulaNames.find(id);
        refuse(slot,
               "formula " + std::to_string(id) +
                   (named != kOtherFormulaNames.end() ? std::string(" (") + named->second + ")"
                    : (id == 1 || id == 6 || id == 9 || id == 12)
                        ? std::string(" (none in Mandelbulber2 2.20)")
                        : std::string()) +
                   " is not supported");
      }
    }
    if (s == 0 && id == 0) refuse(slot, "no formula (Mandelbulber2 draws nothing)");
    const std::string f_key = "f" + k;
    param(f_key, "\"" + std::string(formula ? formula->kind : "none") + "\"");
    if (!formula) continue;
    if (!first) first = formula;
    note(Kind::Mapped, slot,
         "formula " + std::to_string(id) + " -> " + f_key + " = " + formula->kind);
    bailout_max = std::max(bailout_max, formula->bailout);
    long long iterations = 1, start = 0, stop = 1000;
    bool check = true;
    if (hybrid) {
      iterations = integer("formula_iterations_" + k);
      start = integer("formula_start_iteration_" + k);
      stop = integer("formula_stop_iteration_" + k);
      check = flag("check_for_bailout_" + k);
      if (iterations < 1 || iterations > 1000)
        refuse("formula_iterations_" + k, "1 to 1000 are supported");
      if (start < 0 || start > 1000 || stop < 0 || stop > 1000)
        refuse(slot, "start and stop iterations from 0 to 1000 are supported");
      if (number("formula_weight_" + k) != 1)
        refuse("formula_weight_" + k, "a weight other than 1 is not supported");
      estimate_iterations[formula->hybrid_estimate] += std::max(iterations, 1LL);
    }
    param(f_key + "_iterations", std::to_string(std::clamp(iterations, 1LL, 1000LL)));
    param(f_key + "_start", std::to_string(std::clamp(start, 0LL, 1000LL)));
    param(f_key + "_stop", std::to_string(std::clamp(stop, 0LL, 1000LL)));
    const bool dont_add = flag("dont_add_c_constant_" + k);
    param(f_key + "_add_c", (formula->adds_c ? !dont_add : dont_add) ? "true" : "false");
    param(f_key + "_check_bailout", check ? "true" : "false");

    // The kind's parameters.
    const auto& kind_params =
        kKindParams.count(formula->kind) ? kKindParams.at(formula->kind) : std::vector<KindParam>{};
    const auto seen = kind_slot.find(formula->kind);
    for (const KindParam& p : kind_params) {
      const FractEntry e = mb2_fractal_entry(f, s, p.fract_key);
      std::string value;
      switch (p.type) {
        case KindParam::Number:
          value = number_text(fract_number(f, p.fract_key, e));
          break;
        case KindParam::Degrees:
          value = number_text(wrap_degrees(fract_number(f, p.fract_key, e)));
          break;
        case KindParam::Bool:
          value = fract_bool(f, p.fract_key, e) ? "true" : "false";
          break;
        case KindParam::Vec3:
          value = vec3_text(fract_vec3(f, p.fract_key, e));
          break;
        case KindParam::Degrees3: {
          auto v = fract_vec3(f, p.fract_key, e);
          for (double& c : v) c = wrap_degrees(c);
          value = vec3_text(v);
          break;
        }
        case KindParam::Direction: {
          auto v = fract_vec3(f, p.fract_key, e);
          const double len = length(v);
          if (!(len > 0)) {
            refuse(slot, std::string(p.fract_key) + ": a plane's direction of length 0");
            v = {1, 0, 0};
          } else {
            for (double& c : v) c /= len;
          }
          value = vec3_text(v);
          break;
        }
      }
      if (seen == kind_slot.end()) {
        param(p.scene_key, value);
      } else {
        const auto it = std::find_if(params.begin(), params.end(),
                                     [&](const auto& kv) { return kv.first == p.scene_key; });
        if (it != params.end() && it->second != value)
          refuse(slot, "formula " + std::to_string(id) + " (" + formula->kind + ") in slot " +
                           std::to_string(seen->second + 1) + " too, with another " + p.fract_key +
                           ": two different sets are not supported");
      }
    }
    if (std::string(formula->kind) == "mandelbox") {
      const double min_r = fract_number(f, "mandelbox_folding_min_radius",
                                        mb2_fractal_entry(f, s, "mandelbox_folding_min_radius"));
      if (min_r < 0) refuse(slot, "mandelbox_folding_min_radius below 0");
    }
    if (std::string(formula->kind) == "pseudo_kleinian")
      for (const auto& [key, what] : kPseudoKleinianOptions)
        if (fract_bool(f, key, mb2_fractal_entry(f, s, key)))
          refuse(slot, std::string(key) + " (" + what + ") is not supported");
    if (std::string(formula->kind) == "kifs" && f.version <= 2.06 + 1e-9 && s < 4 &&
        seen == kind_slot.end()) {
      // Mandelbulber2's fix-up for files from 2.06 and before: the IFS rotation is on.
      auto it = std::find_if(params.begin(), params.end(),
                             [](const auto& kv) { return kv.first == "kifs_rotation_enabled"; });
      if (it != params.end()) it->second = "true";
    }
    if (seen == kind_slot.end()) kind_slot.emplace(formula->kind, s);
  }
  if (!first) return;

  // The estimate: the formula's own; in a hybrid the family with the most iterations (linear
  // first on a tie); an explicit delta_DE_function overrides either.
  // Mandelbulber2's fix-ups of the stored choice: before 2.09 0 and 2 were swapped; 2.06 and
  // before had linear_DE_mode (linear, else logarithmic); before 2.20 the choice is reset to the
  // formulas' own unless the DE method was forced.
  long long function = integer("delta_DE_function");
  if (f.version < 2.09 - 1e-9 && given("delta_DE_function"))
    function = function == 0 ? 2 : function == 2 ? 0 : function;
  handled.insert("linear_DE_mode");
  if (f.version <= 2.06 + 1e-9) {
    if (given("linear_DE_mode")) function = 1;
    if (function != 1) function = 2;
  }
  if (f.version < 2.20 - 1e-9 && integer("delta_DE_method") == 0) function = 0;
  std::string estimate;
  if (function == 0) {
    if (!hybrid) {
      estimate = first->estimate;
    } else {
      long long best = -1;
      for (const char* family : {"linear", "logarithmic", "pseudo_kleinian"}) {
        const auto it = estimate_iterations.find(family);
        if (it != estimate_iterations.end() && it->second > best) {
          best = it->second;
          estimate = family;
        }
      }
    }
  } else if (function == 1) {
    estimate = "linear";
  } else if (function == 2) {
    estimate = "logarithmic";
  } else if (function == 3) {
    estimate = "pseudo_kleinian";
  } else {
    refuse("delta_DE_function", std::to_string(function) +
                                    (function == 4   ? " (Jos-Kleinian)"
                                     : function == 5 ? " (dIFS)"
                                                     : "") +
                                    " is not supported");
    estimate = "linear";
  }
  param("estimate", "\"" + estimate + "\"");
  param("linear_offset",
        number_text(hybrid && estimate == "linear" ? number("linear_DE_offset") : 0));

  const double bailout =
      flag("use_default_bailout") ? (hybrid ? bailout_max : first->bailout) : number("bailout");
  if (!(bailout >= 0.01 && bailout <= 1e10)) refuse("bailout", "0.01 to 1e10 is supported");
  param("bailout", number_text(std::clamp(bailout, 0.01, 1e10)));

  const bool julia = flag("julia_mode");
  const auto julia_c = vec3("julia_c");
  std::array<double, 3> factor;
  {
    // Files from 2.04 and before wrote the factor as one number.
    const FractEntry e = main("fractal_constant_factor");
    if (e.value.find(' ') == std::string::npos) {
      const double v = fract_number(f, "fractal_constant_factor", e);
      factor = {v, v, v};
    } else {
      factor = fract_vec3(f, "fractal_constant_factor", e);
    }
  }
  param("julia", julia ? "true" : "false");
  param("julia_c", vec3_text(julia_c));
  param("constant_factor", vec3_text(factor));

  // The bound: everything Mandelbulber2 can see, view_distance_max from its eye. (Not the
  // formulas' escape radii: the surface drawn is where the estimate falls below the hit
  // threshold, which reaches past the set by up to a threshold; at a coarse detail level a bound
  // at the set's radius cut transparent002's thick rounded cube into a ball.)
  param("bound", number_text(bound_radius()));
}

void Importer::camera() {
  const auto eye = vec3("camera"), target = vec3("target"), top = vec3("camera_top");
  const auto w = integer("image_width"), h = integer("image_height");
  const double fov = number("fov");
  if (eye == target) refuse("camera", "the camera is at the target");
  if (!(fov > 0 && fov < 100))
    refuse("fov", "expected a value above 0 (the image plane's height at unit distance)");
  if (w < 1 || h < 1 || w > 65535 || h > 65535)
    refuse("image_width", "a size of 1 to 65535 pixels");
  const double aspect =
      static_cast<double>(std::max(w, 1LL)) / static_cast<double>(std::max(h, 1LL));
  // Mandelbulber2's fov is the image plane's height at unit distance; Fractalis's fov_deg the
  // horizontal angle, so the same picture at Mandelbulber2's aspect.
  const double fov_deg =
      2 * std::atan(std::clamp(fov, 1e-9, 99.0) * aspect / 2) * 180 / std::numbers::pi;
  std::ostringstream c;
  c << "eye = " << vec3_text(eye) << "\ntarget = " << vec3_text(target)
    << "\nup = " << vec3_text(top) << "\nfov_deg = " << number_text(fov_deg) << "\n";
  camera_toml = c.str();
  note(Kind::Mapped, "camera, target, camera_top, fov",
       "the view (fov " + number_text(fov) + " -> fov_deg " + number_text(fov_deg) + ")");
  note(Kind::Approximated, "image_width, image_height",
       std::to_string(w) + "x" + std::to_string(h) +
           ": the view keeps its width; render at the "
           "same aspect (--size " +
           std::to_string(w) + "x" + std::to_string(h) +
           " or a multiple) for Mandelbulber2's height");
  const bool mirror = flag("legacy_coordinate_system");
  setting("render.mirror_vertical", mirror ? "true" : "false");
  if (mirror) note(Kind::Mapped, "legacy_coordinate_system", "render.mirror_vertical = true");
  // Mandelbulber2's pixel (x, y) looks through its corner, at x / W - 1/2 of the image's width.
  setting("render.pixel_corners", "true");
  handled.insert("camera_rotation");
  handled.insert("camera_distance_to_target");
}

void Importer::quality() {
  const double detail = number("detail_level");
  if (!(detail > 0)) refuse("detail_level", "expected a value above 0");
  // With limits an orbit that never escapes is surface. (Iteration-threshold mode makes that the
  // only surface: an escaping point is never hit, its distance raised to above the hit
  // threshold, which an estimate cannot know here; refused.)
  if (flag("iteration_threshold_mode"))
    refuse("iteration_threshold_mode",
           "not supported (only orbits that never escape are surface there)");
  const bool limits = flag("limits_enabled");
  param("solid_interior", limits ? "true" : "false");
  param("limits", limits ? "true" : "false");
  param("limit_min", vec3_text(vec3("limit_min")));
  param("limit_max", vec3_text(vec3("limit_max")));
  if (limits)
    note(Kind::Mapped, "limits_enabled", "limits, limit_min, limit_max, solid_interior = true");
  // DE_factor scales Mandelbulber2's steps only; Fractalis's step scale multiplies the estimate
  // before the hit test too, so the threshold is scaled by it to hit where Mandelbulber2 does.
  const double de_factor = number("DE_factor");
  if (!(de_factor > 0)) refuse("DE_factor", "expected a value above 0");
  if (de_factor > 1)
    note(Kind::Approximated, "DE_factor",
         number_text(de_factor) + ": steps longer than the estimate are not taken (step scale 1)");
  const double step = std::clamp(de_factor, 1e-3, 1.0);
  setting("render.step_scale", number_text(step));
  note(Kind::Mapped, "DE_factor", "render.step_scale = " + number_text(step));
  // Mandelbulber2 marches up to 10000 steps; grazing rays of its scenes need more than
  // Fractalis's default (hybrid34: 19% of the rays out of 200 steps, none out of 1000).
  setting("render.max_steps",
          std::to_string(std::min(10000, static_cast<int>(std::ceil(1000 / step)))));
  if (flag("constant_DE_threshold")) {
    const double thr = number("DE_thresh");
    if (!(thr > 0 && thr <= 1e6)) refuse("DE_thresh", "expected a distance above 0");
    const double abs = std::clamp(thr * step, 1e-12, 1e6);
    setting("render.hit_threshold_abs", number_text(abs));
    note(Kind::Mapped, "constant_DE_threshold, DE_thresh",
         "render.hit_threshold_abs = " + number_text(abs));
  }
  // Mandelbulber2 hits at distance < |eye - p| fov / (height detail_level): one pixel's
  // footprint over detail_level, Fractalis's k times the footprint.
  const double k = step / std::max(detail, 1e-12);
  if (k > 100) note(Kind::Approximated, "detail_level", "below 0.01: hit threshold factor 100");
  setting("render.hit_threshold_k", number_text(std::min(k, 100.0)));
  note(Kind::Mapped, "detail_level", "render.hit_threshold_k = " + number_text(std::min(k, 100.0)));
  number("view_distance_max");  // read by the bound
  number("view_distance_min");
}

void Importer::look() {
  const bool light = flag("main_light_enable");
  const bool shadows = flag("shadows_enabled");
  setting("render.effects.shadows", light && shadows ? "true" : "false");
  {
    // The main light as the scene's key light. Mandelbulber2's points from the surface towards
    // the light: (sin a cos b, -cos a cos b, sin b) in the camera's frame (x right, y forward,
    // z up) when relative, in the world's otherwise; a directional light here travels the
    // other way. The scene's key light has intensity 1.3 where Mandelbulber2's has 1.
    const double a = number("main_light_alpha") * std::numbers::pi / 180,
                 b = number("main_light_beta") * std::numbers::pi / 180;
    const std::array<double, 3> local = {std::sin(a) * std::cos(b), -std::cos(a) * std::cos(b),
                                         std::sin(b)};
    std::array<double, 3> to_light = local;
    if (flag("main_light_position_relative")) {
      const auto eye = vec3("camera"), target = vec3("target"), top = vec3("camera_top");
      std::array<double, 3> fw = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]};
      const double fl = std::max(length(fw), 1e-300);
      for (double& c : fw) c /= fl;
      const double along = top[0] * fw[0] + top[1] * fw[1] + top[2] * fw[2];
      std::array<double, 3> up = {top[0] - along * fw[0], top[1] - along * fw[1],
                                  top[2] - along * fw[2]};
      const double ul = length(up);
      if (ul > 0) {
        for (double& c : up) c /= ul;
        const std::array<double, 3> right = {fw[1] * up[2] - fw[2] * up[1],
                                             fw[2] * up[0] - fw[0] * up[2],
                                             fw[0] * up[1] - fw[1] * up[0]};
        for (int i = 0; i < 3; ++i)
          to_light[i] = right[i] * local[0] + fw[i] * local[1] + up[i] * local[2];
      }
    }
    const auto light_colour = colour("main_light_colour");
    const double intensity =
        light ? 1.3 * std::clamp(number("main_light_intensity"), 0.0, 1e5) : 0.0;
    std::ostringstream t;
    t << "[[lights]]\ndirection = " << vec3_text({-to_light[0], -to_light[1], -to_light[2]})
      << "\ncolor = " << vec3_text(light_colour) << "\nintensity = " << number_text(intensity)
      << "\n";
    lights_toml = t.str();
    note(Kind::Approximated,
         "main_light_alpha, main_light_beta, main_light_colour, main_light_intensity",
         "the scene's key light");
  }
  const bool ao = flag("ambient_occlusion_enabled");
  setting("render.effects.ao", ao ? "true" : "false");
  if (ao) note(Kind::Approximated, "ambient_occlusion_enabled", "Fractalis's step-count occlusion");
  handled.insert({"ambient_occlusion", "ambient_occlusion_mode", "ambient_occlusion_quality",
                  "ambient_occlusion_fast_tune"});
  const bool glow = flag("glow_enabled");
  setting("render.effects.glow", glow ? "true" : "false");
  if (glow) {
    setting("render.glow_color", vec3_text(colour("glow_color_1")));
    note(Kind::Approximated, "glow_enabled, glow_color_1",
         "Fractalis's glow in glow_color_1, its own strength (Mandelbulber2's counts steps)");
  }
  handled.insert({"glow_intensity", "glow_color_1", "glow_color_2"});
  // Mandelbulber2's basic fog takes step / visibility of each step's colour: 1 - exp(-t /
  // visibility) in all, the exponential fog of density R / visibility per bounding radius R.
  const bool fog = flag("basic_fog_enabled");
  setting("render.effects.fog", fog ? "true" : "false");
  if (fog) {
    const double visibility = std::max(number("basic_fog_visibility"), 1e-300);
    const double density = std::clamp(bound_radius() / visibility, 0.0, 1e9);
    setting("render.fog_method", "\"exponential\"");
    setting("render.fog_density", number_text(density));
    setting("render.fog_color", vec3_text(colour("basic_fog_color")));
    note(Kind::Approximated, "basic_fog_enabled, basic_fog_visibility, basic_fog_color",
         "exponential fog, 1 - exp(-t / basic_fog_visibility), in basic_fog_color");
  }
  handled.insert({"basic_fog_visibility", "basic_fog_color"});
  // Depth of field. Mandelbulber2 blurs after rendering: a pixel at distance z by
  // |z - focus| / z * DOF_radius * (width + height) / 2000 pixels. A thin lens of radius A focused
  // at f blurs by A |z - f| / (f z) radians, A |z - f| / (f z) * height / fov pixels (fov: the
  // image plane's height at unit distance); the two agree for A = f fov DOF_radius (1 + aspect)
  // / 2000. (The lens's focus is a plane across the view, Mandelbulber2's a distance.)
  const bool dof = flag("DOF_enabled");
  setting("render.effects.dof", dof ? "true" : "false");
  if (dof) {
    const double focus = number("DOF_focus"), radius = number("DOF_radius");
    const auto w = integer("image_width"), h = integer("image_height");
    const double aspect =
        static_cast<double>(std::max(w, 1LL)) / static_cast<double>(std::max(h, 1LL));
    const double f = std::clamp(focus, 1e-6, 1000.0);
    const double aperture = std::clamp(
        f * std::clamp(number("fov"), 0.0, 100.0) * std::max(radius, 0.0) * (1 + aspect) / 2000,
        0.0, 10.0);
    setting("render.focus_distance", number_text(f));
    setting("render.aperture", number_text(aperture));
    note(Kind::Approximated, "DOF_enabled, DOF_focus, DOF_radius",
         "a thin lens focused at " + number_text(f) +
             " with the blur Mandelbulber2's gives: "
             "render.aperture = " +
             number_text(aperture) + " (it needs samples: --samples 64)");
  }
  handled.insert({"DOF_focus", "DOF_radius"});
  const bool reflections = flag("raytraced_reflections");
  setting("render.effects.reflections", reflections ? "true" : "false");
  if (reflections) {
    setting("render.max_bounces", std::to_string(std::clamp(integer("reflections_max"), 0LL, 8LL)));
    note(Kind::Approximated, "raytraced_reflections",
         "mirror bounces with reflectivity mat1_reflectance");
  }
  setting("render.reflectivity", number_text(std::clamp(number("mat1_reflectance"), 0.0, 1.0)));
  // The auxiliary lights, as the mandelbulber scene's point lights 3 to 6 (its first two are the
  // key light, above, and a fill light, turned off; an empty [[lights]] entry keeps a light that
  // is not enabled off). Mandelbulber2 lights a surface d away with 100 intensity / (d^2 4 6)
  // (its four lights, and a 6 kept "for backward compatibility"), its main light with 1 where the
  // key light here has 1.3. Here k / (1 + a d^2) with a = 1 / d0^2 and k = 1.3 (100 / 24)
  // intensity a: the same beyond d0, a hundredth of the view's distance (so that a close-up's
  // lights fall off as its own), capped within it.
  const auto eye = vec3("camera"), target = vec3("target");
  const double view_distance = length({target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]});
  int last_aux = 0;
  std::string aux_toml[4];
  for (int i = 1; i <= 4; ++i) {
    const std::string k = std::to_string(i);
    handled.insert(
        {"aux_light_position_" + k, "aux_light_colour_" + k, "aux_light_intensity_" + k});
    if (!flag("aux_light_enabled_" + k)) continue;
    const auto position = vec3("aux_light_position_" + k);
    const auto light_colour = colour("aux_light_colour_" + k);
    const double mb2 = 1.3 * 100 / 24 * std::max(number("aux_light_intensity_" + k), 0.0);
    const double d0 = std::max(0.01 * view_distance, 1e-12);
    const double attenuation = 1 / (d0 * d0);
    const double intensity = std::min(mb2 * attenuation, 1e30);
    std::ostringstream t;
    t << "position = " << vec3_text(position) << "\ncolor = " << vec3_text(light_colour)
      << "\nintensity = " << number_text(intensity)
      << "\nattenuation = " << number_text(attenuation) << "\nfalloff = 2\n";
    aux_toml[i - 1] = t.str();
    last_aux = i;
    note(Kind::Approximated, "aux_light_enabled_" + k,
         "a point light at " + vec3_text(position) + ", falling off as 1 / d^2 beyond " +
             number_text(d0));
  }
  // The scene's fill light off: Mandelbulber2 has none.
  lights_toml += "[[lights]]\nintensity = 0\n";
  for (int i = 1; i <= last_aux; ++i) lights_toml += "[[lights]]\n" + aux_toml[i - 1];
  handled.insert({"aux_light_visibility", "aux_light_visibility_size"});
  // The background: Mandelbulber2's gradient runs along the world's z, from background_color_3
  // straight down through _2 at the horizon to _1 straight up (or is _1 alone); Fractalis's sky
  // runs from horizon to zenith about the camera's up and keeps the horizon's colour below it.
  {
    const bool three = flag("background_3_colors_enable");
    const auto top = colour("background_color_1");
    const auto middle = three ? colour("background_color_2") : top;
    const double brightness = std::clamp(number("background_brightness"), 0.0, 1e3);
    auto rgb = [&](const std::array<double, 3>& c) {
      return vec3_text({std::min(c[0] * brightness, 1e3), std::min(c[1] * brightness, 1e3),
                        std::min(c[2] * brightness, 1e3)});
    };
    setting("render.sky_zenith", rgb(top));
    setting("render.sky_horizon", rgb(middle));
    note(Kind::Approximated, "background_color_1, background_color_2, background_color_3",
         three ? "the sky from background_color_2 at the horizon to background_color_1 at the "
                 "zenith, about the camera's up (background_color_3, below, is not used)"
               : "a sky of background_color_1");
    handled.insert({"background_color_1", "background_color_2", "background_color_3",
                    "background_3_colors_enable", "background_brightness"});
  }
  for (const char* key : {"brightness", "contrast", "gamma"})
    if (given(key)) note(Kind::Ignored, key, "Fractalis's own tone mapping");
  handled.insert({"brightness", "contrast", "gamma"});
}

// The surface colour. Mandelbulber2 colours the fractal from its palette (a colouring pass over
// the hit point's orbit gives an index, the index a position in the gradient) unless the file
// turns that off, and then in mat1_surface_color. The scene does the same (colour_mode palette:
// mandelbulber_surface.cl) with the gradient sampled at 64 even positions. Colours are
// Mandelbulber2's display values; the scene's albedo is linear, so they are decoded from sRGB.
void Importer::colouring() {
  const int kSamples = 64;
  handled.insert({"mat1_coloring_palette_size", "mat1_is_defined", "mat1_coloring_saturation"});
  if (!flag("mat1_use_colors_from_palette") || !flag("mat1_surface_gradient_enable")) {
    param("colour_mode", "\"surface\"");
    param("surface_colour", vec3_text(colour("mat1_surface_color")));
    note(Kind::Approximated, "mat1_surface_color", "surface_colour (decoded from sRGB)");
    return;
  }
  handled.insert({"mat1_surface_color", "mat1_surface_color_palette"});
  // Files from before 2.19 keep a palette; Mandelbulber2 turns it into a gradient of n evenly
  // spaced colours, its speed into speed 10 / n and its offset into offset / n.
  Mb2Gradient gradient;
  double speed = number("mat1_coloring_speed"), offset = number("mat1_coloring_palette_offset");
  std::string source;
  if (f.version < 2.19 - 1e-9) {
    const std::string key = "mat1_surface_color_palette";
    if (given(key)) {
      gradient = mb2_parse_old_palette(f, key, f.main.at(key));
      source = key;
    } else {
      gradient =
          mb2_parse_gradient(f, "mat1_surface_color_gradient", main("mat1_surface_color_gradient"));
      source = "the default gradient";
    }
    speed *= 10.0 / gradient.colours;
    offset /= gradient.colours;
  } else {
    gradient =
        mb2_parse_gradient(f, "mat1_surface_color_gradient", main("mat1_surface_color_gradient"));
    source = given("mat1_surface_color_gradient") ? "mat1_surface_color_gradient"
                                                  : "the default gradient";
  }
  handled.insert("mat1_surface_color_gradient");
  param("colour_mode", "\"palette\"");
  for (int j = 0; j < kSamples; ++j)
    param("palette_" + std::to_string(j),
          vec3_text(decoded(mb2_gradient_colour(gradient, static_cast<float>(j) / kSamples))));
  if (speed > 1e6 || std::fabs(offset) > 1e6)
    note(Kind::Approximated, "mat1_coloring_speed, mat1_coloring_palette_offset",
         "beyond 1e6: clamped to it (the colour changes faster than a pixel either way)");
  param("colour_speed", number_text(std::clamp(speed, 0.0, 1e6)));
  param("colour_offset", number_text(std::clamp(offset, -1e6, 1e6)));
  const long long algorithm = integer("mat1_fractal_coloring_algorithm");
  if (algorithm < 0 || algorithm > 4) {
    // -1 (none) and out-of-range values: the standard trap, said.
    note(Kind::Approximated, "mat1_fractal_coloring_algorithm",
         std::to_string(algorithm) + ": the standard trap (|z|) instead");
  }
  static const char* const kAlgorithms[] = {"standard", "z_dot_point", "sphere", "cross", "line"};
  param("colour_algorithm",
        std::string("\"") + kAlgorithms[algorithm >= 0 && algorithm <= 4 ? algorithm : 0] + "\"");
  param("colour_sphere_radius",
        number_text(std::clamp(number("mat1_fractal_coloring_sphere_radius"), 0.0, 1e6)));
  {
    // A 4-vector in Mandelbulber2; its w meets the trap's w, which is 0 (4D colouring is off).
    FractEntry e = main("mat1_fractal_coloring_line_direction");
    std::istringstream in(e.value);
    std::vector<std::string> w;
    for (std::string t; in >> t;) w.push_back(t);
    if (w.size() == 4) e.value = w[0] + " " + w[1] + " " + w[2];
    auto d = fract_vec3(f, "mat1_fractal_coloring_line_direction", e);
    for (double& c : d) c = std::clamp(c, -1e6, 1e6);
    param("colour_line_direction", vec3_text(d));
  }
  // The Mandelbox's fold colours, from the first slot running one (Mandelbulber2 keeps them per
  // slot; a second Mandelbox slot's own are not used).
  int box_slot = -1;
  for (const auto& [key, value] : params)
    if (key.size() == 2 && key[0] == 'f' && value == "\"mandelbox\"" && box_slot < 0)
      box_slot = key[1] - '1';
  const int s = std::max(box_slot, 0);
  auto clamp3 = [](std::array<double, 3> v) {
    for (double& c : v) c = std::clamp(c, -1e6, 1e6);
    return v;
  };
  param("box_colour", vec3_text(clamp3(fract_vec3(f, "mandelbox_color",
                                                  mb2_fractal_entry(f, s, "mandelbox_color")))));
  for (const auto& [scene_key, fract_key] : {std::pair{"box_colour_sp1", "mandelbox_color_Sp1"},
                                             std::pair{"box_colour_sp2", "mandelbox_color_Sp2"},
                                             std::pair{"box_colour_r", "mandelbox_color_R"}})
    param(scene_key,
          number_text(std::clamp(fract_number(f, fract_key, mb2_fractal_entry(f, s, fract_key)),
                                 -1e6, 1e6)));
  note(Kind::Approximated,
       "mat1_surface_color_gradient, mat1_coloring_speed, "
       "mat1_coloring_palette_offset, mat1_fractal_coloring_algorithm",
       "Mandelbulber2's palette colouring (colour_mode = palette) from " + source + " (" +
           std::to_string(gradient.colours) + " colours), sampled at 64 positions" +
           (gradient.colours > 32 ? ": finer detail is smoothed" : ""));
  if (flag("mat1_fractal_coloring_extra_color_enabled_false"))
    note(Kind::Ignored, "mat1_fractal_coloring_extra_color_enabled_false",
         "colouring by numbers: the standard colour index is used");
  if (flag("mat1_fractal_coloring_color_4D_enabled_false"))
    note(Kind::Ignored, "mat1_fractal_coloring_color_4D_enabled_false", "the trap is 3D here");
  if (flag("mat1_fractal_coloring_color_preV215_false"))
    note(Kind::Ignored, "mat1_fractal_coloring_color_preV215_false",
         "the colouring pass's bailouts are 2.15's");
}

void Importer::unhandled_keys() {
  for (const auto& [key, entry] : f.main)
    if (!handled.count(key) && !kNotPicture.count(key)) note(Kind::Ignored, key, "not imported");
}

std::string Importer::toml(const std::string& name) const {
  std::ostringstream t;
  t << "# Imported by `fractalis import` from " << f.file.filename().string()
    << " (Mandelbulber2 settings, version " << number_text(f.version) << ")\n";
  t << "scene = \"" << kMb2SceneId << "\"\n";
  std::string escaped;
  for (char c : name) {
    if (c == '"' || c == '\\') escaped += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) escaped += c;
  }
  t << "name = \"" << escaped << "\"\n";
  t << "description = \"Imported from Mandelbulber2.\"\n";
  t << "[params]\n";
  for (const auto& [k, v] : params) t << k << " = " << v << "\n";
  t << "[camera]\n" << camera_toml;
  t << lights_toml;
  t << "[settings]\n";
  for (const auto& [k, v] : settings) t << "\"" << k << "\" = " << v << "\n";
  return t.str();
}

void Importer::run(const std::string& name) {
  version();
  refuse_unsupported_features();
  formulas();
  camera();
  quality();
  look();
  colouring();
  unhandled_keys();
  if (out.faithful()) out.preset_toml = toml(name);
}

}  // namespace

const char* import_note_kind_name(ImportNote::Kind kind) {
  switch (kind) {
    case Kind::Mapped:
      return "mapped";
    case Kind::Approximated:
      return "approximated";
    case Kind::Ignored:
      return "ignored";
    case Kind::Refused:
      return "refused";
  }
  return "?";
}

bool Mb2Import::faithful() const {
  return std::none_of(notes.begin(), notes.end(),
                      [](const ImportNote& n) { return n.kind == Kind::Refused; });
}

std::vector<std::string> Mb2Import::refusals() const {
  std::vector<std::string> out;
  for (const ImportNote& n : notes)
    if (n.kind == Kind::Refused) out.push_back(n.item + ": " + n.text);
  return out;
}

Mb2Import import_fract(const FractFile& file, const std::string& name) {
  // Mandelbulber2 renames the material keys of files from 2.071 and before to material 1's.
  FractFile renamed = file;
  if (file.version <= 2.071 + 1e-9) {
    static const std::pair<const char*, const char*> kRenames[] = {
        {"reflect", "mat1_reflectance"},
        {"coloring_speed", "mat1_coloring_speed"},
        {"coloring_palette_size", "mat1_coloring_palette_size"},
        {"coloring_palette_offset", "mat1_coloring_palette_offset"},
        {"coloring_random_seed", "mat1_coloring_random_seed"},
        {"coloring_saturation", "mat1_coloring_saturation"},
        {"fractal_color", "mat1_use_colors_from_palette"},
        {"surface_color_palette", "mat1_surface_color_palette"},
        {"fractal_coloring_algorithm", "mat1_fractal_coloring_algorithm"},
        {"fractal_coloring_sphere_radius", "mat1_fractal_coloring_sphere_radius"},
        {"fractal_coloring_line_direction", "mat1_fractal_coloring_line_direction"}};
    for (const auto& [from, to] : kRenames) {
      const auto it = renamed.main.find(from);
      if (it == renamed.main.end()) continue;
      renamed.main.emplace(to, it->second);
      renamed.main.erase(it);
    }
  }
  Importer importer(renamed);
  importer.run(name);
  return std::move(importer.out);
}

}  // namespace fr
