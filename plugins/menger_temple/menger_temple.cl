/* menger_temple.cl — a temple of Menger sponges: a great sponge on a stepped plinth, a pillar of
 * three small sponges at each corner, and a floor. Every shape comes from the DE library
 * (fr/staging.cl); the union of their lower bounds is one. World y is up. */
#include "fr/staging.cl"

/* The four pillars by folding x and z positive: each pillar stays in its own quadrant, so the
 * fold is exact. A pillar is three cubes stacked, by limited repetition along y (exact while a
 * cube fits its cell). */
inline real_t temple_pillars(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  const scalar_t cube_half = 0.32;
  vec3_t q = v3(fabs(p.x), p.y, fabs(p.z));
  q = p_translate(q, v3s(2.3, -1.5 + cube_half, 2.3));
  q.y = q.y - to_real(2 * cube_half) * clamp(rint(q.y / to_real(2 * cube_half)), to_real(0), to_real(2));
  return de_sponge_at(q, v3s(0, 0, 0), cube_half, PARAM(pillar_level), trap);
}

inline real_t temple_plinth(vec3_t p) {
  const real_t low = sd_box(p_translate(p, v3s(0, -1.35, 0)), v3s(1.9, 0.15, 1.9));
  const real_t high = sd_box(p_translate(p, v3s(0, -1.1, 0)), v3s(1.55, 0.1, 1.55));
  return op_union(low, high);
}

inline real_t temple_sponge(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  return de_sponge_at(p, v3s(0, 0.2, 0), 1.2, PARAM(sponge_level), trap);
}

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  real_t d = op_union(sd_floor_disc(p, -1.5, 6.5, 0.5), temple_plinth(p));
  d = op_union(d, temple_pillars(p, params, &trap));
  return op_union(d, temple_sponge(p, params, &trap));
}
