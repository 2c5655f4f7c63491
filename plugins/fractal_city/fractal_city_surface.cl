/* fractal_city_surface.cl — concrete towers shaded by orbit trap, dark streets; path traced, lit
 * windows. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t towers = city_towers(p, params, &trap);
  const surface_t t = surface_from_trap(trap / 3, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0);
  const real_t ground = city_ground(p);
  surface_t s;
  s.albedo = v3s(0.16, 0.16, 0.18);
  s.reflectivity = to_real(0.15);
  real_t nearest = ground;
  {
    const mask_t here = towers < nearest;
    s.albedo = v3_select(here, t.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0), s.reflectivity);
    nearest = fmin(nearest, towers);
  }
  return s;
}

/* Path tracing: the sponge's holes are windows, lit in some towers (the cell's hash picks how
 * brightly: a quarter of the towers are dark), glowing warm. */
material_t scene_material(vec3_t p, material_t m, __constant const scene_params_t* params) {
  real_t storeys;
  lane_uint_t hash;
  vec3_t in_cell;
  const vec3_t q = city_local(p, &storeys, &hash, &in_cell);
  /* Inside the cube, off its outer faces: the wall of a hole. */
  const real_t depth = to_real(CITY_HALF) - fmax(fabs(q.x), fmax(fabs(q.y), fabs(q.z)));
  const mask_t window = (storeys > 0) & (depth > to_real(0.02)) & (p.y > to_real(-0.98));
  const real_t lit = uint_to_real((hash >> 2) & 3u) / 3;
  m.emission = v3_select(window, v3_scale(PARAM(window_color), PARAM(window_glow) * lit),
                         m.emission);
  return m;
}
