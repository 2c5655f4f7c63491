/* fr/palette.cl — surface colour from an orbit trap (the smallest |z|^2 an orbit reached, which
 * the fractal DEs in this library report): a smooth blend from `near` (orbits that came close to
 * the origin) to `far`. */

inline surface_t surface_from_trap(real_t trap, vec3_t near, vec3_t far, scalar_t contrast,
                                   scalar_t reflectivity) {
  real_t t = clamp(pow_nonneg(sqrt(fmax(trap, to_real(0))), to_real(contrast)), to_real(0), to_real(1));
  t = t * t * (to_real(3) - 2 * t); /* smoothstep */
  surface_t s;
  s.albedo = v3_mix(near, far, t);
  s.reflectivity = to_real(reflectivity);
  return s;
}
