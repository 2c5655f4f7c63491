/* mandelbulber.c — Mandelbulber2's formulas in Mandelbulber2's order: nine formula slots, each a
 * Mandelbulb (asin form), power-2 bulb, hypercomplex, quaternion, Menger sponge, Mandelbox,
 * kaleidoscopic IFS or pseudo-Kleinian step (fr/mandelbulber.cl), run as its hybrid sequence
 * (formula_iterations, start and stop iterations, repeat_from), c added after each slot that
 * adds it and the bailout checked after every step. `fractalis import` maps a `.fract` file onto
 * these parameters (host/import/mb2_import.cpp); the defaults are Mandelbulber2's own start: the
 * power-9 bulb, 250 iterations, bailout 10.
 *
 * One set of parameters per formula kind (Mandelbulber2 keeps one per slot): a file whose two
 * slots use the same kind with different values is refused by the importer, never merged. */
#include "fractalis/fractalis.h"

extern const char fr_de_source[];
extern const char fr_surface_source[];

/* In the order of fr/mandelbulber.cl's MB2_* kinds (mandelbulber.cl refuses to compile else). */
static const char* const kinds[] = {"none",         "mandelbulb", "power2",
                                    "hypercomplex", "quaternion", "menger",
                                    "mandelbox",    "kifs",       "pseudo_kleinian"};
static const char* const estimates[] = {"logarithmic", "linear", "ifs", "pseudo_kleinian"};

#define SLOT(n, kind)                                                                              \
  static const fr_param_desc f##n = FR_CHOICE_PARAM("f" #n, "Formula", "Slot " #n,                 \
                                                    "The formula in Mandelbulber2's slot " #n ".", \
                                                    kind, kinds, FR_PARAM_SPECIALIZE);             \
  static const fr_param_desc f##n##_iterations =                                                   \
      FR_INT_PARAM("f" #n "_iterations", "Iterations in a row", "Slot " #n,                        \
                   "How many iterations in a row the hybrid gives this slot.", 1, 1, 1000, 0);     \
  static const fr_param_desc f##n##_start =                                                        \
      FR_INT_PARAM("f" #n "_start", "First iteration", "Slot " #n,                                 \
                   "The slot is skipped before this iteration (counted from 0).", 0, 0, 1000, 0);  \
  static const fr_param_desc f##n##_stop =                                                         \
      FR_INT_PARAM("f" #n "_stop", "Last iteration", "Slot " #n,                                   \
                   "The slot is skipped after this iteration.", 250, 0, 1000, 0);                  \
  static const fr_param_desc f##n##_add_c =                                                        \
      FR_BOOL_PARAM("f" #n "_add_c", "Add c", "Slot " #n,                                          \
                    "Add the constant (the point, or Julia's c) after the step.", 1, 0);           \
  static const fr_param_desc f##n##_check_bailout =                                                \
      FR_BOOL_PARAM("f" #n "_check_bailout", "Check bailout", "Slot " #n,                          \
                    "Stop the orbit after this slot's step once |z| passes the bailout.", 1, 0);

SLOT(1, 1)
SLOT(2, 0)
SLOT(3, 0)
SLOT(4, 0)
SLOT(5, 0)
SLOT(6, 0)
SLOT(7, 0)
SLOT(8, 0)
SLOT(9, 0)

static const fr_param_desc iterations =
    FR_INT_PARAM("iterations", "Iterations (N)", "Iteration",
                 "Mandelbulber2's N: the most iterations an orbit runs.", 250, 1, 1000, 0);
static const fr_param_desc hybrid = FR_BOOL_PARAM(
    "hybrid", "Hybrid", "Iteration", "Run the slots in sequence; off, slot 1 runs every iteration.",
    0, FR_PARAM_SPECIALIZE);
static const fr_param_desc repeat_from =
    FR_INT_PARAM("repeat_from", "Repeat from slot", "Iteration",
                 "After slot 9 the hybrid sequence goes on from this slot.", 1, 1, 9, 0);
static const fr_param_desc bailout =
    FR_FLOAT_PARAM("bailout", "Bailout", "Iteration", "An orbit with |z| past this has escaped.",
                   10, 0.01, 1e10, FR_PARAM_LOG_SCALE);
static const fr_param_desc julia =
    FR_BOOL_PARAM("julia", "Julia mode", "Iteration", "Add julia_c instead of the point.", 0, 0);
static const fr_param_desc julia_c =
    FR_VEC3_PARAM("julia_c", "Julia c", "Iteration", "The constant of Julia mode.", 0, 0, 0, -1000,
                  1000, FR_PARAM_ANIMATABLE);
static const fr_param_desc constant_factor = FR_VEC3_PARAM(
    "constant_factor", "Constant factor", "Iteration",
    "Multiplies the added constant, component by component.", 1, 1, 1, -1000, 1000, 0);
static const fr_param_desc estimate =
    FR_CHOICE_PARAM("estimate", "Estimate", "Iteration",
                    "logarithmic: 0.5 r ln r / dr; linear: (r - offset) / dr; ifs: (r - 2) / dr; "
                    "pseudo_kleinian: Theli-at's cylinder estimate.",
                    0, estimates, FR_PARAM_SPECIALIZE);
static const fr_param_desc linear_offset =
    FR_FLOAT_PARAM("linear_offset", "Linear offset", "Iteration",
                   "Subtracted from r by the linear estimate (Mandelbulber2's linear_DE_offset).",
                   0, -1000, 1000, 0);
static const fr_param_desc bound =
    FR_FLOAT_PARAM("bound", "Bounding radius", "Iteration",
                   "Nothing is drawn outside this radius (the importer sets it from the formulas "
                   "and the view distance).",
                   2, 0.1, 1e6, FR_PARAM_LOG_SCALE);

static const fr_param_desc solid_interior = FR_BOOL_PARAM(
    "solid_interior", "Solid interior", "Iteration",
    "An orbit that never escapes is inside the surface (as Mandelbulber2 has it with limits); "
    "off, the estimate decides there too.",
    0, FR_PARAM_SPECIALIZE);
static const fr_param_desc limits =
    FR_BOOL_PARAM("limits", "Limits", "Iteration", "Cut the fractal to the box between the limits.",
                  0, FR_PARAM_SPECIALIZE);
static const fr_param_desc limit_min = FR_VEC3_PARAM(
    "limit_min", "Limit min", "Iteration", "The box's lower corner.", -10, -10, -10, -1e4, 1e4, 0);
static const fr_param_desc limit_max = FR_VEC3_PARAM(
    "limit_max", "Limit max", "Iteration", "The box's upper corner.", 10, 10, 10, -1e4, 1e4, 0);

static const fr_param_desc bulb_power = FR_FLOAT_PARAM(
    "bulb_power", "Power", "Mandelbulb", "The bulb's power (Mandelbulber2's default is 9).", 9, 1,
    64, FR_PARAM_ANIMATABLE);
static const fr_param_desc bulb_alpha =
    FR_FLOAT_PARAM("bulb_alpha", "Alpha offset (deg)", "Mandelbulb",
                   "Added to the longitude before the power.", 0, -360, 360, FR_PARAM_ANIMATABLE);
static const fr_param_desc bulb_beta =
    FR_FLOAT_PARAM("bulb_beta", "Beta offset (deg)", "Mandelbulb",
                   "Added to the latitude before the power.", 0, -360, 360, FR_PARAM_ANIMATABLE);

static const fr_param_desc box_scale =
    FR_FLOAT_PARAM("box_scale", "Scale", "Mandelbox", "z <- scale * fold(z) + c.", 2, -100, 100,
                   FR_PARAM_ANIMATABLE);
static const fr_param_desc box_fold_limit =
    FR_FLOAT_PARAM("box_fold_limit", "Folding limit", "Mandelbox",
                   "The box fold acts beyond +-limit.", 1, 0, 100, 0);
static const fr_param_desc box_fold_value =
    FR_FLOAT_PARAM("box_fold_value", "Folding value", "Mandelbox",
                   "Beyond the limit a coordinate a becomes "
                   "+-value - a.",
                   2, -100, 100, 0);
static const fr_param_desc box_min_radius =
    FR_FLOAT_PARAM("box_min_radius", "Min radius", "Mandelbox",
                   "Inside it the sphere fold scales by "
                   "(fixed / min)^2 (0: never).",
                   0.5, 0, 100, 0);
static const fr_param_desc box_fixed_radius =
    FR_FLOAT_PARAM("box_fixed_radius", "Fixed radius", "Mandelbox",
                   "Inside it the sphere fold inverts.", 1, 1e-4, 100, 0);
static const fr_param_desc box_offset =
    FR_VEC3_PARAM("box_offset", "Sphere fold offset", "Mandelbox",
                  "The sphere fold's centre is at minus this.", 0, 0, 0, -100, 100, 0);
static const fr_param_desc box_main_rotation =
    FR_BOOL_PARAM("box_main_rotation", "Main rotation", "Mandelbox", "Rotate after the folds.", 0,
                  FR_PARAM_SPECIALIZE);
static const fr_param_desc box_rotation =
    FR_VEC3_PARAM("box_rotation", "Main rotation (deg)", "Mandelbox", "About x, then y, then z.", 0,
                  0, 0, -360, 360, FR_PARAM_ANIMATABLE);
static const fr_param_desc box_fold_rotations =
    FR_BOOL_PARAM("box_fold_rotations", "Fold rotations", "Mandelbox",
                  "Fold each axis in a rotated frame.", 0, FR_PARAM_SPECIALIZE);
#define BOX_ROTATION(side, n, axis)                                                                \
  static const fr_param_desc box_rotation_##side##_##n = FR_VEC3_PARAM(                            \
      "box_rotation_" #side "_" #n, "Fold frame " #side " " #axis " (deg)", "Mandelbox",           \
      "The frame of the " #axis " fold (Mandelbulber2's mandelbox_rotation_" #side "_" #n ").", 0, \
      0, 0, -360, 360, 0);
BOX_ROTATION(neg, 1, x)
BOX_ROTATION(neg, 2, y)
BOX_ROTATION(neg, 3, z)
BOX_ROTATION(pos, 1, x)
BOX_ROTATION(pos, 2, y)
BOX_ROTATION(pos, 3, z)

static const fr_param_desc menger_scale =
    FR_FLOAT_PARAM("menger_scale", "Scale", "Menger sponge", "3 is the classic sponge.", 3, 0, 100,
                   FR_PARAM_ANIMATABLE);

static const fr_param_desc kifs_scale =
    FR_FLOAT_PARAM("kifs_scale", "Scale", "Kaleidoscopic IFS", "z <- scale z - offset (scale - 1).",
                   2, -100, 100, FR_PARAM_ANIMATABLE);
static const fr_param_desc kifs_offset =
    FR_VEC3_PARAM("kifs_offset", "Offset", "Kaleidoscopic IFS", "The scaling's fixed point.", 1, 0,
                  0, -100, 100, FR_PARAM_ANIMATABLE);
static const fr_param_desc kifs_rotation_enabled =
    FR_BOOL_PARAM("kifs_rotation_enabled", "Rotation", "Kaleidoscopic IFS",
                  "Rotate about the offset point after the planes.", 0, FR_PARAM_SPECIALIZE);
static const fr_param_desc kifs_rotation =
    FR_VEC3_PARAM("kifs_rotation", "Rotation (deg)", "Kaleidoscopic IFS",
                  "Mandelbulber2's IFS angles: z about x first, then y, then x about z.", 0, 0, 0,
                  -360, 360, FR_PARAM_ANIMATABLE);
static const fr_param_desc kifs_edge = FR_VEC3_PARAM(
    "kifs_edge", "Edge", "Kaleidoscopic IFS",
    "A positive component e folds that coordinate back from e.", 0, 0, 0, -100, 100, 0);
#define KIFS_ABS(a)                                                 \
  static const fr_param_desc kifs_abs_##a =                         \
      FR_BOOL_PARAM("kifs_abs_" #a, "abs " #a, "Kaleidoscopic IFS", \
                    "Fold " #a " to |" #a "| first.", 0, FR_PARAM_SPECIALIZE);
KIFS_ABS(x)
KIFS_ABS(y)
KIFS_ABS(z)
static const fr_param_desc kifs_menger_mode = FR_BOOL_PARAM(
    "kifs_menger_mode", "Menger mode", "Kaleidoscopic IFS",
    "Offset z only above half its offset, as the Menger sponge does.", 0, FR_PARAM_SPECIALIZE);
#define PLANE(i)                                                                                   \
  static const fr_param_desc kifs_plane##i =                                                       \
      FR_BOOL_PARAM("kifs_plane" #i, "Plane " #i, "IFS plane " #i,                                 \
                    "Mandelbulber2's IFS_enabled_" #i ".", 0, FR_PARAM_SPECIALIZE);                \
  static const fr_param_desc kifs_plane##i##_direction =                                           \
      FR_VEC3_PARAM("kifs_plane" #i "_direction", "Normal", "IFS plane " #i,                       \
                    "The plane's normal (made unit).", 1, 0, 0, -1000, 1000, FR_PARAM_ANIMATABLE); \
  static const fr_param_desc kifs_plane##i##_distance =                                            \
      FR_FLOAT_PARAM("kifs_plane" #i "_distance", "Distance", "IFS plane " #i,                     \
                     "Points below this distance along the normal are reflected.", 0, -100, 100,   \
                     FR_PARAM_ANIMATABLE);                                                         \
  static const fr_param_desc kifs_plane##i##_intensity =                                           \
      FR_FLOAT_PARAM("kifs_plane" #i "_intensity", "Intensity", "IFS plane " #i,                   \
                     "1 reflects; other values "                                                   \
                     "push by that multiple.",                                                     \
                     1, -100, 100, FR_PARAM_ANIMATABLE);                                           \
  static const fr_param_desc kifs_plane##i##_rotation =                                            \
      FR_VEC3_PARAM("kifs_plane" #i "_rotation", "Rotation (deg)", "IFS plane " #i,                \
                    "Applied before the plane's reflection (as kifs_rotation).", 0, 0, 0, -360,    \
                    360, FR_PARAM_ANIMATABLE);
PLANE(0)
PLANE(1)
PLANE(2)
PLANE(3)
PLANE(4)
PLANE(5)
PLANE(6)
PLANE(7)
PLANE(8)

static const fr_param_desc pk_box =
    FR_VEC3_PARAM("pk_box", "Box size", "Pseudo-Kleinian", "The clamp fold's half-sizes.", 0.7, 0.7,
                  0.7, 0, 100, FR_PARAM_ANIMATABLE);
static const fr_param_desc pk_min_r2 =
    FR_FLOAT_PARAM("pk_min_r2", "Min radius^2", "Pseudo-Kleinian",
                   "Inside |z|^2 < this the inversion scales by it / |z|^2.", 0.5, 0, 100, 0);
static const fr_param_desc pk_tweak =
    FR_FLOAT_PARAM("pk_tweak", "DE tweak", "Pseudo-Kleinian",
                   "Added to the inversion's factor in dr.", 0.05, -10, 10, 0);
static const fr_param_desc pk_de_offset = FR_FLOAT_PARAM(
    "pk_de_offset", "DE offset", "Pseudo-Kleinian",
    "The cylinder radius in the estimate (Mandelbulber2's analyticDE_scale_1).", 1, -100, 100, 0);
static const fr_param_desc pk_offset =
    FR_VEC3_PARAM("pk_offset", "Offset", "Pseudo-Kleinian", "Added after the inversion.", 0, 0, 0,
                  -100, 100, FR_PARAM_ANIMATABLE);

static const fr_param_desc color_near =
    FR_COLOR_PARAM("color_near", "Colour (deep orbits)", "Colour",
                   "Albedo where the orbit came close to the centre.", 0.9, 0.72, 0.45);
static const fr_param_desc color_far =
    FR_COLOR_PARAM("color_far", "Colour (outer orbits)", "Colour",
                   "Albedo where the orbit stayed far out.", 0.25, 0.35, 0.55);
static const fr_param_desc color_contrast =
    FR_FLOAT_PARAM("color_contrast", "Colour contrast", "Colour",
                   "Exponent of the orbit-trap blend.", 1, 0.25, 8, 0);

static const char* const colour_modes[] = {"trap", "palette", "surface"};
static const fr_param_desc colour_mode = FR_CHOICE_PARAM(
    "colour_mode", "Colouring", "Colour",
    "trap: Fractalis's orbit-trap blend; palette: Mandelbulber2's palette colouring; surface: "
    "one colour.",
    0, colour_modes, FR_PARAM_SPECIALIZE);
static const char* const colour_algorithms[] = {"standard", "z_dot_point", "sphere", "cross",
                                                "line"};
static const fr_param_desc colour_algorithm = FR_CHOICE_PARAM(
    "colour_algorithm", "Colouring algorithm", "Colour",
    "Mandelbulber2's trap (fractal_coloring_algorithm 0-4): |z|, |z.p|, ||z - p| - radius|, "
    "min |z_i|, |z.direction|.",
    0, colour_algorithms, FR_PARAM_SPECIALIZE);
static const fr_param_desc colour_sphere_radius =
    FR_FLOAT_PARAM("colour_sphere_radius", "Trap sphere radius", "Colour",
                   "The sphere algorithm's radius.", 1, 0, 1e6, 0);
static const fr_param_desc colour_line_direction =
    FR_VEC3_PARAM("colour_line_direction", "Trap line direction", "Colour",
                  "The line algorithm's direction.", 1, 0, 0, -1e6, 1e6, 0);
static const fr_param_desc colour_speed =
    FR_FLOAT_PARAM("colour_speed", "Palette speed", "Colour",
                   "Palette turns per 2560 of the colour index.", 1, 0, 1e6, FR_PARAM_ANIMATABLE);
static const fr_param_desc colour_offset = FR_FLOAT_PARAM(
    "colour_offset", "Palette offset", "Colour",
    "Added to the palette position (1 is a whole turn).", 0, -1e6, 1e6, FR_PARAM_ANIMATABLE);
static const fr_param_desc surface_colour =
    FR_COLOR_PARAM("surface_colour", "Surface colour", "Colour",
                   "The albedo in the surface mode (linear).", 0.55, 0.55, 0.55);
static const fr_param_desc box_colour =
    FR_VEC3_PARAM("box_colour", "Fold colour x, y, z", "Colour",
                  "Added to the fold colour per axis a Mandelbox step folds (mandelbox_color).",
                  0.03, 0.05, 0.07, -1e6, 1e6, 0);
static const fr_param_desc box_colour_sp1 =
    FR_FLOAT_PARAM("box_colour_sp1", "Fold colour, inner sphere", "Colour",
                   "Added when the sphere fold is within the minimum radius.", 0.2, -1e6, 1e6, 0);
static const fr_param_desc box_colour_sp2 =
    FR_FLOAT_PARAM("box_colour_sp2", "Fold colour, outer sphere", "Colour",
                   "Added when the sphere fold is within the fixed radius.", 0.2, -1e6, 1e6, 0);
static const fr_param_desc box_colour_r =
    FR_FLOAT_PARAM("box_colour_r", "Fold colour, radius", "Colour",
                   "The weight of r / 1e13 in a Mandelbox's colour index.", 0, -1e6, 1e6, 0);
/* The palette: 64 samples at positions j / 64 (linear colour); by default a ramp. */
#define PALETTE_ENTRY(j)                                                                        \
  static const fr_param_desc palette_##j = FR_COLOR_PARAM(                                      \
      "palette_" #j, "Palette " #j, "Palette", "The palette's colour at position " #j " / 64.", \
      (j) / 63.0, 0.45, 1 - (j) / 63.0);
#define PALETTE_ENTRIES8(a)                                                       \
  PALETTE_ENTRY(a##0)                                                             \
  PALETTE_ENTRY(a##1) PALETTE_ENTRY(a##2) PALETTE_ENTRY(a##3) PALETTE_ENTRY(a##4) \
      PALETTE_ENTRY(a##5) PALETTE_ENTRY(a##6) PALETTE_ENTRY(a##7)
PALETTE_ENTRY(0)
PALETTE_ENTRY(1) PALETTE_ENTRY(2) PALETTE_ENTRY(3) PALETTE_ENTRY(4) PALETTE_ENTRY(5)
    PALETTE_ENTRY(6) PALETTE_ENTRY(7) PALETTE_ENTRY(8) PALETTE_ENTRY(9) PALETTE_ENTRIES8(1)
        PALETTE_ENTRY(18) PALETTE_ENTRY(19) PALETTE_ENTRIES8(2) PALETTE_ENTRY(28) PALETTE_ENTRY(29)
            PALETTE_ENTRIES8(3) PALETTE_ENTRY(38) PALETTE_ENTRY(39) PALETTE_ENTRIES8(4)
                PALETTE_ENTRY(48) PALETTE_ENTRY(49) PALETTE_ENTRIES8(5) PALETTE_ENTRY(58)
                    PALETTE_ENTRY(59) PALETTE_ENTRY(60) PALETTE_ENTRY(61) PALETTE_ENTRY(62)
                        PALETTE_ENTRY(63)
#define PALETTE_LIST8(a)                                                               \
  &palette_##a##0, &palette_##a##1, &palette_##a##2, &palette_##a##3, &palette_##a##4, \
      &palette_##a##5, &palette_##a##6, &palette_##a##7
#define PALETTE_LIST                                                                              \
  &palette_0, &palette_1, &palette_2, &palette_3, &palette_4, &palette_5, &palette_6, &palette_7, \
      &palette_8, &palette_9, PALETTE_LIST8(1), &palette_18, &palette_19, PALETTE_LIST8(2),       \
      &palette_28, &palette_29, PALETTE_LIST8(3), &palette_38, &palette_39, PALETTE_LIST8(4),     \
      &palette_48, &palette_49, PALETTE_LIST8(5), &palette_58, &palette_59, &palette_60,          \
      &palette_61, &palette_62, &palette_63

#define SLOT_LIST(n) \
  &f##n, &f##n##_iterations, &f##n##_start, &f##n##_stop, &f##n##_add_c, &f##n##_check_bailout
#define PLANE_LIST(i)                                                    \
  &kifs_plane##i, &kifs_plane##i##_direction, &kifs_plane##i##_distance, \
      &kifs_plane##i##_intensity, &kifs_plane##i##_rotation
                            static const fr_param_desc* const params[] = {SLOT_LIST(1),
                                                                          SLOT_LIST(2),
                                                                          SLOT_LIST(3),
                                                                          SLOT_LIST(4),
                                                                          SLOT_LIST(5),
                                                                          SLOT_LIST(6),
                                                                          SLOT_LIST(7),
                                                                          SLOT_LIST(8),
                                                                          SLOT_LIST(9),
                                                                          &iterations,
                                                                          &hybrid,
                                                                          &repeat_from,
                                                                          &bailout,
                                                                          &julia,
                                                                          &julia_c,
                                                                          &constant_factor,
                                                                          &estimate,
                                                                          &linear_offset,
                                                                          &bound,
                                                                          &solid_interior,
                                                                          &limits,
                                                                          &limit_min,
                                                                          &limit_max,
                                                                          &bulb_power,
                                                                          &bulb_alpha,
                                                                          &bulb_beta,
                                                                          &box_scale,
                                                                          &box_fold_limit,
                                                                          &box_fold_value,
                                                                          &box_min_radius,
                                                                          &box_fixed_radius,
                                                                          &box_offset,
                                                                          &box_main_rotation,
                                                                          &box_rotation,
                                                                          &box_fold_rotations,
                                                                          &box_rotation_neg_1,
                                                                          &box_rotation_neg_2,
                                                                          &box_rotation_neg_3,
                                                                          &box_rotation_pos_1,
                                                                          &box_rotation_pos_2,
                                                                          &box_rotation_pos_3,
                                                                          &menger_scale,
                                                                          &kifs_scale,
                                                                          &kifs_offset,
                                                                          &kifs_rotation_enabled,
                                                                          &kifs_rotation,
                                                                          &kifs_edge,
                                                                          &kifs_abs_x,
                                                                          &kifs_abs_y,
                                                                          &kifs_abs_z,
                                                                          &kifs_menger_mode,
                                                                          PLANE_LIST(0),
                                                                          PLANE_LIST(1),
                                                                          PLANE_LIST(2),
                                                                          PLANE_LIST(3),
                                                                          PLANE_LIST(4),
                                                                          PLANE_LIST(5),
                                                                          PLANE_LIST(6),
                                                                          PLANE_LIST(7),
                                                                          PLANE_LIST(8),
                                                                          &pk_box,
                                                                          &pk_min_r2,
                                                                          &pk_tweak,
                                                                          &pk_de_offset,
                                                                          &pk_offset,
                                                                          &color_near,
                                                                          &color_far,
                                                                          &color_contrast,
                                                                          &colour_mode,
                                                                          &colour_algorithm,
                                                                          &colour_sphere_radius,
                                                                          &colour_line_direction,
                                                                          &colour_speed,
                                                                          &colour_offset,
                                                                          &surface_colour,
                                                                          &box_colour,
                                                                          &box_colour_sp1,
                                                                          &box_colour_sp2,
                                                                          &box_colour_r,
                                                                          PALETTE_LIST};
enum { P_BOUND = 9 * 6 + 9 };

/* Mandelbulber2's own start: the power-9 bulb seen from (3, -6, 2), z up. */
static const fr_camera camera = FR_CAMERA(3.0, -6.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 50.0);
static const fr_light key = FR_DIRECTIONAL_LIGHT(-0.45, 0.35, -0.85, 1.0, 0.95, 0.88, 1.3);
static const fr_light fill = FR_DIRECTIONAL_LIGHT(0.6, 0.5, -0.2, 0.4, 0.5, 0.7, 0.3);
/* Mandelbulber2's four auxiliary lights, off (intensity 0: the host marches no shadow rays for
 * them) until an imported preset's [[lights]] place and light them. */
static const fr_light aux1 = FR_POINT_LIGHT(3.0, -3.0, 3.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0);
static const fr_light aux2 = FR_POINT_LIGHT(-3.0, -3.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0);
static const fr_light aux3 = FR_POINT_LIGHT(-3.0, 3.0, -1.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0);
static const fr_light aux4 = FR_POINT_LIGHT(0.0, -1.0, -3.0, 1.0, 1.0, 1.0, 0.0, 1.0, 2.0);
static const fr_light* const lights[] = {&key, &fill, &aux1, &aux2, &aux3, &aux4};

static fr_result update(void* instance, const fr_host* host, fr_frame_state* state) {
  (void)instance;
  (void)host;
  state->bounding_radius = state->params[P_BOUND].v[0];
  return FR_OK;
}

static const fr_scene_desc scene = {
    .struct_size = sizeof(fr_scene_desc),
    .id = "mandelbulber",
    .name = "Mandelbulber2 formulas",
    .version = "1.0.0",
    .author = "The Fractalis developers",
    .license = "MIT",
    .description =
        "Mandelbulber2's bulb, box, sponge, IFS and Kleinian formulas in its hybrid order: "
        "what `fractalis import` opens .fract files into.",
    .tags = "hybrid import mandelbulber2 bulb box kifs kleinian",
    .credit =
        "Mandelbulber2 (Krzysztof Marczak and contributors); the formulas' own credits in "
        "fr/mandelbulber.cl",
    .de_source = fr_de_source,
    .de_source_name = "mandelbulber.cl",
    .surface_source = fr_surface_source,
    .surface_source_name = "mandelbulber_surface.cl",
    .params = params,
    .param_count = FR_ARRAY_COUNT(params),
    .light_count = FR_ARRAY_COUNT(lights),
    .features = FR_FEATURE_AO | FR_FEATURE_SHADOWS,
    .camera = &camera,
    .lights = lights,
    .bounding_radius = 2,
    .update = update,
};

FR_SCENE_ENTRY_V1_2(&scene);
