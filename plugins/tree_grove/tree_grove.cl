/* tree_grove.cl — Pythagoras trees on a grassy knoll: five of them, each turned and sized its
 * own way. Shapes from the DE library (fr/staging.cl); world y is up. */
#include "fr/staging.cl"

inline real_t grove_trees(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  const int n = PARAM(levels);
  const scalar_t k = PARAM(child_scale), tilt = PARAM(tilt_deg) * (scalar_t)(M_PI / 180), w = 0.07;
  real_t t;
  real_t d = de_tree_at(p, v3s(0, -0.62, 0), 0.9, 0.3, n, k, tilt, w, trap);
  real_t e = de_tree_at(p, v3s(2.2, -0.85, 1.0), 0.65, 1.1, n, k, tilt, w, &t);
  *trap = lane_select(e < d, t, *trap);
  d = fmin(d, e);
  e = de_tree_at(p, v3s(-2.0, -0.85, 1.3), 0.7, 2.0, n, k, tilt, w, &t);
  *trap = lane_select(e < d, t, *trap);
  d = fmin(d, e);
  e = de_tree_at(p, v3s(-1.1, -0.8, -2.1), 0.6, 0.7, n, k, tilt, w, &t);
  *trap = lane_select(e < d, t, *trap);
  d = fmin(d, e);
  e = de_tree_at(p, v3s(1.6, -0.85, -1.8), 0.55, 2.6, n, k, tilt, w, &t);
  *trap = lane_select(e < d, t, *trap);
  return fmin(d, e);
}

/* The knoll: the cap of a wide sphere above y = -1.5, inside the ground disc's radius (so all of
 * it lies inside the bounding radius), on the ground slab. */
inline real_t grove_ground(vec3_t p) {
  real_t knoll = sd_sphere(p_translate(p, v3s(0, -13.6, 0)), to_real(13.0));
  knoll = op_intersect(knoll, to_real(-1.5) - p.y);
  knoll = op_intersect(knoll, sqrt(p.x * p.x + p.z * p.z) - to_real(7.0));
  return op_union(knoll, sd_floor_disc(p, -1.0, 7.0, 0.5));
}

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return op_union(grove_ground(p), grove_trees(p, params, &trap));
}
