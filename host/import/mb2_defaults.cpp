#include "import/mb2_defaults.hpp"

#include <array>
#include <string>

namespace fr {
namespace {

#define FR_SLOTS(key, value)                                                                     \
  {key "_1", value}, {key "_2", value}, {key "_3", value}, {key "_4", value}, {key "_5", value}, \
      {key "_6", value}, {key "_7", value}, {key "_8", value}, {                                 \
    key "_9", value                                                                              \
  }
#define FR_PLANES(key, value)                                                                    \
  {key "_0", value}, {key "_1", value}, {key "_2", value}, {key "_3", value}, {key "_4", value}, \
      {key "_5", value}, {key "_6", value}, {key "_7", value}, {                                 \
    key "_8", value                                                                              \
  }

const Mb2Default kMain[] = {
    // The view.
    {"camera", "3 -6 2"},
    {"target", "0 0 0"},
    {"camera_top", "-0.1277753 0.2555506 0.958314"},
    {"fov", "1"},  // the image plane's height at unit distance (2.20: not an angle)
    {"perspective_type", "three_point"},
    {"legacy_coordinate_system", "false"},
    {"image_width", "800"},
    {"image_height", "600"},
    {"stereo_enabled", "false"},
    // The formulas and their sequence.
    {"formula_1", "2"},
    {"formula_2", "0"},
    {"formula_3", "0"},
    {"formula_4", "0"},
    {"formula_5", "0"},
    {"formula_6", "0"},
    {"formula_7", "0"},
    {"formula_8", "0"},
    {"formula_9", "0"},
    FR_SLOTS("formula_iterations", "1"),
    FR_SLOTS("formula_weight", "1"),
    FR_SLOTS("formula_start_iteration", "0"),
    FR_SLOTS("formula_stop_iteration", "250"),
    FR_SLOTS("fractal_enable", "true"),
    FR_SLOTS("dont_add_c_constant", "false"),
    FR_SLOTS("check_for_bailout", "true"),
    {"hybrid_fractal_enable", "false"},
    {"repeat_from", "1"},
    {"boolean_operators", "false"},
    {"julia_mode", "false"},
    {"julia_c", "0 0 0"},
    {"fractal_constant_factor", "1 1 1"},
    {"initial_waxis", "0"},
    {"N", "250"},
    {"minN", "1"},
    {"bailout", "100"},
    {"use_default_bailout", "true"},
    // How the surface is found.
    {"detail_level", "1"},
    {"DE_thresh", "0.01"},
    {"constant_DE_threshold", "false"},
    {"DE_factor", "1"},
    {"iteration_threshold_mode", "false"},
    {"interior_mode", "false"},
    {"delta_DE_method", "0"},
    {"delta_DE_function", "0"},
    {"linear_DE_offset", "0"},
    {"view_distance_max", "50"},
    {"view_distance_min", "1e-15"},
    {"limits_enabled", "false"},
    {"limit_min", "-10 -10 -10"},
    {"limit_max", "10 10 10"},
    {"fractal_position", "0 0 0"},
    {"fractal_rotation", "0 0 0"},
    {"repeat", "0 0 0"},
    {"box_folding", "false"},
    {"spherical_folding", "false"},
    // The look.
    {"main_light_enable", "true"},
    {"main_light_intensity", "1"},
    {"main_light_alpha", "-45"},
    {"main_light_beta", "45"},
    {"main_light_position_relative", "true"},
    {"main_light_colour", "ffff ffff ffff"},
    {"shadows_enabled", "true"},
    {"ambient_occlusion_enabled", "false"},
    {"ambient_occlusion", "1"},
    {"ambient_occlusion_mode", "2"},
    {"background_color_1", "0000 95a2 ffff"},
    {"background_color_2", "ffff ffff ffff"},
    {"background_color_3", "0000 2710 01f4"},
    {"background_3_colors_enable", "true"},
    {"background_brightness", "1"},
    {"basic_fog_enabled", "false"},
    {"basic_fog_visibility", "20"},
    {"basic_fog_color", "e807 ef12 ffff"},
    {"glow_enabled", "true"},
    {"glow_intensity", "0.2"},
    {"glow_color_1", "a018 aea9 c152"},
    {"glow_color_2", "df68 edd8 f3c8"},
    {"DOF_enabled", "false"},
    {"DOF_focus", "6"},
    {"DOF_radius", "10"},
    {"raytraced_reflections", "false"},
    {"reflections_max", "5"},
    {"aux_light_enabled_1", "false"},
    {"aux_light_enabled_2", "false"},
    {"aux_light_enabled_3", "false"},
    {"aux_light_enabled_4", "false"},
    {"aux_light_position_1", "3 -3 3"},
    {"aux_light_position_2", "-3 -3 0"},
    {"aux_light_position_3", "-3 3 -1"},
    {"aux_light_position_4", "0 -1 -3"},
    {"aux_light_intensity_1", "1.3"},
    {"aux_light_intensity_2", "1"},
    {"aux_light_intensity_3", "3"},
    {"aux_light_intensity_4", "2"},
    {"aux_light_colour_1", "b2c1 d181 e86a"},
    {"aux_light_colour_2", "f59b da0a c3a3"},
    {"aux_light_colour_3", "fd74 fda0 bed0"},
    {"aux_light_colour_4", "cde0 f41c b256"},
    {"aux_light_intensity", "1"},
    {"brightness", "1"},
    {"contrast", "1"},
    {"gamma", "1"},
    {"mat1_reflectance", "0"},
    // The surface colour (material 1, the fractal's).
    {"mat1_use_colors_from_palette", "true"},
    {"mat1_surface_gradient_enable", "true"},
    {"mat1_surface_color", "c350 c350 c350"},
    {"mat1_surface_color_gradient",
     "0 fd6029 1000 698403 2000 fff59b 3000 f5bd22 4000 0b5e87 5000 c68876 6000 a51c64 7000 "
     "3b9fee 8000 d4ffd4 9000 aba53c"},
    {"mat1_coloring_speed", "1"},
    {"mat1_coloring_palette_offset", "0"},
    {"mat1_fractal_coloring_algorithm", "0"},
    {"mat1_fractal_coloring_sphere_radius", "1"},
    {"mat1_fractal_coloring_line_direction", "1 0 0 0"},
    {"mat1_fractal_coloring_extra_color_enabled_false", "false"},
    {"mat1_fractal_coloring_color_4D_enabled_false", "false"},
    {"mat1_fractal_coloring_color_preV215_false", "false"},
};

const Mb2Default kFractal[] = {
    // Mandelbulb (2).
    {"power", "9"},
    {"alpha_angle_offset", "0"},
    {"beta_angle_offset", "0"},
    // Mandelbox (8).
    {"mandelbox_scale", "2"},
    {"mandelbox_folding_limit", "1"},
    {"mandelbox_folding_value", "2"},
    {"mandelbox_folding_min_radius", "0.5"},
    {"mandelbox_folding_fixed_radius", "1"},
    {"mandelbox_color", "0.03 0.05 0.07"},
    {"mandelbox_color_Sp1", "0.2"},
    {"mandelbox_color_Sp2", "0.2"},
    {"mandelbox_color_R", "0"},
    {"mandelbox_offset", "0 0 0"},
    {"mandelbox_main_rotation_enabled", "false"},
    {"mandelbox_rotation_main", "0 0 0"},
    {"mandelbox_rotations_enabled", "false"},
    {"mandelbox_rotation_neg_1", "0 0 0"},
    {"mandelbox_rotation_neg_2", "0 0 0"},
    {"mandelbox_rotation_neg_3", "0 0 0"},
    {"mandelbox_rotation_pos_1", "0 0 0"},
    {"mandelbox_rotation_pos_2", "0 0 0"},
    {"mandelbox_rotation_pos_3", "0 0 0"},
    // Menger sponge (7).
    {"transf_scale_3", "3"},
    // Kaleidoscopic IFS (10).
    {"IFS_scale", "2"},
    {"IFS_offset", "1 0 0"},
    {"IFS_rotation", "0 0 0"},
    {"IFS_rotation_enabled", "false"},
    {"IFS_edge", "0 0 0"},
    {"IFS_abs_x", "false"},
    {"IFS_abs_y", "false"},
    {"IFS_abs_z", "false"},
    {"IFS_menger_sponge_mode", "false"},
    FR_PLANES("IFS_direction", "1 0 0"),
    FR_PLANES("IFS_distance", "0"),
    FR_PLANES("IFS_intensity", "1"),
    FR_PLANES("IFS_rotations", "0 0 0"),
    FR_PLANES("IFS_enabled", "false"),
    // Pseudo-Kleinian (103).
    {"transf_addition_constant_0777", "0.7 0.7 0.7"},
    {"transf_minimum_radius_05", "0.5"},
    {"analyticDE_tweak_005", "0.05"},
    {"analyticDE_scale_1", "1"},
    {"transf_addition_constant", "0 0 0"},
    {"transf_function_enabledR_false", "false"},
    {"transf_function_enabledBx_false", "false"},
    {"transf_function_enabledBy_false", "false"},
    {"transf_function_enabledP_false", "false"},
    {"transf_sphere_inversion_enabled_false", "false"},
};

#undef FR_SLOTS
#undef FR_PLANES

const char* find(std::span<const Mb2Default> table, const std::string& key) {
  for (const Mb2Default& d : table)
    if (key == d.key) return d.value;
  return nullptr;
}

}  // namespace

std::span<const Mb2Default> mb2_main_defaults() {
  return kMain;
}
std::span<const Mb2Default> mb2_fractal_defaults() {
  return kFractal;
}

FractEntry mb2_main_entry(const FractFile& f, const std::string& key) {
  if (auto it = f.main.find(key); it != f.main.end()) return it->second;
  if (const char* d = find(kMain, key)) return {d, 0};
  throw FractError("mb2_main_entry: no default for '" + key + "'");
}

FractEntry mb2_fractal_entry(const FractFile& f, int slot, const std::string& key) {
  if (auto it = f.fractal[slot].find(key); it != f.fractal[slot].end()) return it->second;
  if (const char* d = find(kFractal, key)) return {d, 0};
  throw FractError("mb2_fractal_entry: no default for '" + key + "'");
}

}  // namespace fr
