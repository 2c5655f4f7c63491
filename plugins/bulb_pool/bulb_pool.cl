/* bulb_pool.cl — a Mandelbulb hovering over a still pool in a stone rim: the pool mirrors it.
 * Shapes from the DE library (fr/staging.cl). World y is up. */
#include "fr/staging.cl"

inline real_t pool_bulb(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  return de_bulb_at(p, v3s(0, 0.35, 0), 1.0, PARAM(power), PARAM(iterations), trap);
}

/* The water: a disc just under y = -1.1. The rim: a torus around it. The ground: a wider disc
 * lower down. */
inline real_t pool_water(vec3_t p) { return sd_floor_disc(p, -1.1, 2.6, 0.2); }
inline real_t pool_rim(vec3_t p) {
  return sd_torus(p_translate(p, v3s(0, -1.1, 0)), to_real(2.75), to_real(0.18));
}
inline real_t pool_ground(vec3_t p) { return sd_floor_disc(p, -1.25, 7.0, 0.5); }

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  real_t d = op_union(pool_ground(p), op_union(pool_water(p), pool_rim(p)));
  return op_union(d, pool_bulb(p, params, &trap));
}
