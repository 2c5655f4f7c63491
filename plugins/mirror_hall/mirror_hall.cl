/* mirror_hall.cl — a sphereflake between mirrors: a mirror floor and two mirror walls repeat it
 * into a hall of flakes. Shapes from the DE library; world y is up. */
#include "fr/staging.cl"

inline real_t hall_flake(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  const vec3_t q = p_scale(p_translate(p, v3s(0, 0.35, 0)), 0.85);
  return op_rescale(de_sphereflake(q, PARAM(levels), PARAM(child_scale), trap), 0.85);
}

inline real_t hall_floor(vec3_t p) { return sd_floor_disc(p, -1.5, 7.0, 0.5); }
/* Two walls, x = +-3.2, 0.2 thick, 4 high, 9 long. */
inline real_t hall_walls(vec3_t p) {
  return sd_box(p_translate(v3(fabs(p.x), p.y, p.z), v3s(3.3, 0.5, 0)), v3s(0.1, 2.0, 4.5));
}

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return op_union(op_union(hall_floor(p), hall_walls(p)), hall_flake(p, params, &trap));
}
