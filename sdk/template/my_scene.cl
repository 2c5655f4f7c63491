/* my_scene.cl — the distance estimator: a sphere with a ripple whose depth is a parameter.
 * Lane-generic: real_t and vec3_t are one ray (GPU) or a packet of 16 (CPU); see the guide.
 * A DE must never over-estimate the distance (`fractalis check` measures it): the ripple term's
 * slope is at most ripple * waves * sqrt(2), so dividing by 1 plus that keeps the DE's slope at
 * most 1. */
#include "fr/primitives.cl"

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  const real_t r = v3_length(p);
  const real_t ripple = PARAM(ripple) * sin(PARAM(waves) * p.y) * sin(PARAM(waves) * p.x);
  return (r - PARAM(radius) - ripple) / (1 + PARAM(ripple) * PARAM(waves) * to_real(1.4143));
}
