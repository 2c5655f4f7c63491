/* mandelbulber_surface.cl — the surface colour: Fractalis's orbit-trap blend, Mandelbulber2's
 * palette colouring, or one colour (`colour_mode`).
 *
 * The palette as Mandelbulber2 2.20 colours a fractal (its rules as facts; the code is written
 * here): a colouring pass over the hit point's orbit (mb2_iterate) gives a colour index, the
 * index a position in the palette, position = fract((|index| mod 248 * 256) / 2560 * speed +
 * offset), and the palette a colour by linear interpolation. The index:
 *   - hybrid: 1000 min(trap, 100) + 100 fold colour + 5000 min(r / dr, 20);
 *   - a Mandelbox: 100 fold colour + r colour_r / 1e13 (+ 1000 trap outside the standard
 *     algorithm);
 *   - the IFS and the Menger sponge: 1000 trap;
 *   - the bulbs, the squares and the pseudo-Kleinian: 5000 trap.
 * The importer samples Mandelbulber2's gradient at 64 even positions (palette_0..63); between
 * them it is linear here too, and palette_63 runs on to palette_0 (the gradient wraps). */
#include "fr/palette.cl"

#define MB2_MODE_TRAP 0
#define MB2_MODE_PALETTE 1
#define MB2_MODE_SURFACE 2
#define MB2_PALETTE_SIZE 64

#if FR_CHOICE_colour_mode_palette != MB2_MODE_PALETTE ||                \
    FR_CHOICE_colour_mode_surface != MB2_MODE_SURFACE ||                \
    FR_CHOICE_colour_algorithm_standard != MB2_COLOUR_STANDARD ||       \
    FR_CHOICE_colour_algorithm_z_dot_point != MB2_COLOUR_Z_DOT_POINT || \
    FR_CHOICE_colour_algorithm_line != MB2_COLOUR_LINE
#error "mandelbulber.c's colour choices are out of step with mandelbulber_surface.cl"
#endif

FR_MB2_INLINE inline real_t mb2_colour_index(const mb2_orbit_t* o,
                                             __constant const scene_params_t* params) {
  if (PARAM(hybrid))
    return fmin(o->colour_min, to_real(100)) * 1000 + o->aux_colour * 100 +
           fmin(o->r / fmax(fabs(o->dr), to_real(FR_SCALAR_MIN)), to_real(20)) * 5000;
  switch (PARAM(f1)) {
    case MB2_MANDELBOX:
      return o->aux_colour * 100 + o->r * to_real(PARAM(box_colour_r) / 1e13) +
             (PARAM(colour_algorithm) != MB2_COLOUR_STANDARD ? o->colour_min * 1000 : to_real(0));
    case MB2_KIFS:
    case MB2_MENGER:
      return o->colour_min * 1000;
    default:
      return o->colour_min * 5000;
  }
}

/* Linear interpolation through the 64 samples as a sum of tents: sample j weighs
 * max(0, 1 - |x - j|) at x = 64 position; sample 64 is sample 0 again. */
#define MB2_TENT(j)                                                                 \
  {                                                                                 \
    const real_t weight = fmax(to_real(0), to_real(1) - fabs(x - to_real(j)));      \
    colour = v3_add(colour, v3_scale(PARAM(palette_##j), weight));                  \
  }
#define MB2_TENTS8(a)                                                                           \
  MB2_TENT(a##0) MB2_TENT(a##1) MB2_TENT(a##2) MB2_TENT(a##3) MB2_TENT(a##4) MB2_TENT(a##5)    \
  MB2_TENT(a##6) MB2_TENT(a##7)

inline vec3_t mb2_palette(real_t position, __constant const scene_params_t* params) {
  const real_t x = position * MB2_PALETTE_SIZE;
  vec3_t colour = v3(to_real(0), to_real(0), to_real(0));
  MB2_TENT(0) MB2_TENT(1) MB2_TENT(2) MB2_TENT(3) MB2_TENT(4) MB2_TENT(5) MB2_TENT(6) MB2_TENT(7)
  MB2_TENT(8) MB2_TENT(9)
  MB2_TENTS8(1) MB2_TENT(18) MB2_TENT(19)
  MB2_TENTS8(2) MB2_TENT(28) MB2_TENT(29)
  MB2_TENTS8(3) MB2_TENT(38) MB2_TENT(39)
  MB2_TENTS8(4) MB2_TENT(48) MB2_TENT(49)
  MB2_TENTS8(5) MB2_TENT(58) MB2_TENT(59)
  MB2_TENT(60) MB2_TENT(61) MB2_TENT(62) MB2_TENT(63)
  {
    const real_t weight = fmax(to_real(0), x - to_real(MB2_PALETTE_SIZE - 1));
    colour = v3_add(colour, v3_scale(PARAM(palette_0), weight));
  }
  return colour;
}

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  if (PARAM(colour_mode) == MB2_MODE_SURFACE) {
    surface_t s;
    s.albedo = PARAM(surface_colour);
    s.reflectivity = to_real(0);
    return s;
  }
  real_t trap;
  if (PARAM(colour_mode) == MB2_MODE_PALETTE) {
    mb2_orbit_t orbit;
    mb2_iterate(p, params, 1, &trap, &orbit);
    const real_t index = fmod(fabs(mb2_colour_index(&orbit, params)), to_real(248 * 256));
    real_t position = index / 2560 * to_real(PARAM(colour_speed)) + to_real(PARAM(colour_offset));
    position = position - floor(position);
    surface_t s;
    s.albedo = mb2_palette(position, params);
    s.reflectivity = to_real(0);
    return s;
  }
  mb2_de(p, params, &trap);
  return surface_from_trap(trap / 4, PARAM(color_near), PARAM(color_far), PARAM(color_contrast),
                           0);
}
