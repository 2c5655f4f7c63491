/* benchmark.cl — the benchmark scene (`fractalis bench`'s default): a Mandelbulb and a Menger sponge
 * on a floor, with three spheres. World y is up. Every shape comes from the DE library. */
#include "fr/mandelbulb.cl"
#include "fr/menger.cl"

#define BULB_CENTRE v3s(-1.55, 0.12, 0.0)
#define SPONGE_CENTRE v3s(1.55, -0.1, 0.0)
#define SPONGE_SIZE 0.9
#define FLOOR_HEIGHT -1.0

/* The bulb's polar axis (its z) stands along world y: swapping y and z is an isometry. The
 * escape-time DE over-estimates far from the bulb (by up to 1.4x across this scene, which
 * `fractalis check` flagged), so beyond the bulb's own bounding sphere (|q| <= 2^(1/(n-1)))
 * the distance to that sphere is used: an exact lower bound there. */
inline real_t bench_bulb(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  vec3_t q = p_translate(p, BULB_CENTRE);
  /* 2^(1/(n-1)) through exp2: PoCL's pow, once per evaluation, cost more than the bulb. */
  const scalar_t bound = exp2(1 / ((scalar_t)PARAM(bulb_power) - 1));
  const real_t to_bound = v3_length(q) - to_real(bound);
  /* The same value as the select below gives, without the iterations, when no lane is near. */
  if (all_lanes(to_bound > to_real(0.25))) {
    *trap = to_real(1);
    return to_bound;
  }
  const real_t de = de_mandelbulb(v3(q.x, q.z, q.y), PARAM(bulb_power), to_real(2),
                                  PARAM(bulb_iterations), trap);
  return lane_select(to_bound > to_real(0.25), to_bound, de);
}

inline real_t bench_sponge(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  vec3_t q = p_rotate_y(p_translate(p, SPONGE_CENTRE), 0.5);
  /* The sponge fills part of its cube: more than 0.25 from the cube, the distance to the cube
   * (exact for the cube, a lower bound for the sponge) serves, and where that holds for every
   * lane the folds are skipped. Per lane, so the value does not depend on the packet. */
  const real_t to_cube = sd_box(q, v3s(SPONGE_SIZE, SPONGE_SIZE, SPONGE_SIZE));
  if (all_lanes(to_cube > to_real(0.25))) {
    *trap = to_real(1);
    return to_cube;
  }
  const real_t de = op_rescale(
      de_menger(p_scale(q, SPONGE_SIZE), PARAM(sponge_level), 3, v3s(1, 1, 1), 0, trap),
      SPONGE_SIZE);
  return lane_select(to_cube > to_real(0.25), to_cube, de);
}

inline real_t bench_spheres(vec3_t p) {
  real_t a = sd_sphere(p_translate(p, v3s(0.1, -0.62, 1.7)), to_real(0.38));
  real_t b = sd_sphere(p_translate(p, v3s(-0.4, -0.72, -1.8)), to_real(0.28));
  real_t c = sd_sphere(p_translate(p, v3s(3.3, -0.7, 1.4)), to_real(0.3));
  return op_union(a, op_union(b, c));
}

/* A slab 0.5 thick under y = FLOOR_HEIGHT, cut to a disc of radius FLOOR_RADIUS: the whole
 * scene then lies inside its bounding radius (9), as the host requires (an endless plane was cut
 * off at the bounding sphere, which `fractalis check` reports as surface outside the bound). */
#define FLOOR_RADIUS 8.8
inline real_t bench_floor(vec3_t p) {
  const real_t slab = fabs(p.y - to_real(FLOOR_HEIGHT - 0.25)) - to_real(0.25);
  const real_t disc = sqrt(p.x * p.x + p.z * p.z) - to_real(FLOOR_RADIUS);
  return op_intersect(slab, disc);
}

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  real_t d = op_union(bench_floor(p), bench_spheres(p));
  d = op_union(d, bench_sponge(p, params, &trap));
  return op_union(d, bench_bulb(p, params, &trap));
}
