/* benchmark_surface.cl — materials: a checkered reflective floor, mirror-like spheres, and orbit
 * trap colours on the two fractals. The nearest shape at p decides. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t bulb_trap, sponge_trap;
  real_t bulb = bench_bulb(p, params, &bulb_trap);
  real_t sponge = bench_sponge(p, params, &sponge_trap);
  real_t spheres = bench_spheres(p);
  real_t floor_d = bench_floor(p);

  /* Floor: a 0.5-unit checkerboard. */
  real_t checker = fabs(floor(p.x * 2) + floor(p.z * 2));
  checker = checker - 2 * floor(checker * to_real(0.5));
  surface_t s;
  s.albedo = v3_mix(v3s(0.75, 0.75, 0.72), v3s(0.18, 0.18, 0.2), checker);
  s.reflectivity = to_real(PARAM(floor_reflectivity));

  mask_t is_spheres = spheres < floor_d;
  s.albedo = v3_select(is_spheres, v3s(0.9, 0.85, 0.8), s.albedo);
  s.reflectivity = lane_select(is_spheres, to_real(PARAM(sphere_reflectivity)), s.reflectivity);
  real_t nearest = fmin(spheres, floor_d);

  surface_t sponge_s = surface_from_trap(log(fmax(sponge_trap, to_real(1))) / to_real(PARAM(sponge_level) * 2.2 + 1),
                                         v3s(0.85, 0.82, 0.76), v3s(0.7, 0.32, 0.16), 3, 0.05);
  mask_t is_sponge = sponge < nearest;
  s.albedo = v3_select(is_sponge, sponge_s.albedo, s.albedo);
  s.reflectivity = lane_select(is_sponge, sponge_s.reflectivity, s.reflectivity);
  nearest = fmin(nearest, sponge);

  surface_t bulb_s = surface_from_trap(bulb_trap, v3s(0.9, 0.42, 0.12), v3s(0.3, 0.42, 0.62), 4, 0.05);
  mask_t is_bulb = bulb < nearest;
  s.albedo = v3_select(is_bulb, bulb_s.albedo, s.albedo);
  s.reflectivity = lane_select(is_bulb, bulb_s.reflectivity, s.reflectivity);
  return s;
}
