/* crystal_garden.cl — Knighty's kaleidoscopic crystals grown on a plain: an icosahedral one in
 * the middle, octahedral, tetrahedral and cube-cornered ones around it. Shapes from the DE
 * library (fr/staging.cl); world y is up. */
#include "fr/staging.cl"

#define GARDEN_TWIST (PARAM(twist_deg) * (scalar_t)(M_PI / 180))

inline real_t garden_crystals(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  const scalar_t phi = 1.6180339887498949;
  const int n = PARAM(iterations);
  real_t t;
  real_t d = de_kifs_at(p, v3s(0, 0.1, 0), 0.55, 1, n, 2, v3s(0, 1, phi), GARDEN_TWIST, 0, 0, trap);
  real_t e = de_kifs_at(p, v3s(2.3, -0.55, 0.9), 0.5, 0, n, 2, v3s(1, 0, 0), 0, GARDEN_TWIST, 0, &t);
  *trap = lane_select(e < d, t, *trap);
  d = fmin(d, e);
  e = de_kifs_at(p, v3s(-2.0, -0.5, 1.3), 0.55, 2, n, 1.85, v3s(1, 1, 1), 0, 18 * (scalar_t)(M_PI / 180), 0, &t);
  *trap = lane_select(e < d, t, *trap);
  d = fmin(d, e);
  e = de_kifs_at(p, v3s(0.6, -0.65, -2.3), 0.4, 0, n, 2, v3s(1, 1, 1), 25 * (scalar_t)(M_PI / 180), 10 * (scalar_t)(M_PI / 180), 0, &t);
  *trap = lane_select(e < d, t, *trap);
  return fmin(d, e);
}

inline real_t garden_ground(vec3_t p) { return sd_floor_disc(p, -1.1, 7.0, 0.5); }

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return op_union(garden_ground(p), garden_crystals(p, params, &trap));
}
