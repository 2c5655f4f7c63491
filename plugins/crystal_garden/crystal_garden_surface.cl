/* crystal_garden_surface.cl — orbit-trap colours on the crystals, sand below; path traced, the
 * crystals are tinted glass. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  const real_t crystals = garden_crystals(p, params, &trap);
  const surface_t c = surface_from_trap(trap / 2, PARAM(color_near), PARAM(color_far), PARAM(color_contrast), 0.1);
  const real_t ground = garden_ground(p);
  surface_t s;
  s.albedo = v3s(0.72, 0.66, 0.55);
  s.reflectivity = to_real(0);
  real_t nearest = ground;
  {
    const mask_t here = crystals < nearest;
    s.albedo = v3_select(here, c.albedo, s.albedo);
    s.reflectivity = lane_select(here, to_real(0.1), s.reflectivity);
    nearest = fmin(nearest, crystals);
  }
  return s;
}

/* Path tracing: glass crystals tinted by their colour (light of that colour passes), the sand as
 * the surface colour says. */
material_t scene_material(vec3_t p, material_t m, __constant const scene_params_t* params) {
  real_t trap;
  const mask_t crystal = garden_crystals(p, params, &trap) < garden_ground(p);
  m.transmission = lane_select(crystal, PARAM(glass), m.transmission);
  m.specular = lane_select(crystal, to_real(0), m.specular); /* the glass's Fresnel reflects */
  m.ior = lane_select(crystal, PARAM(ior), m.ior);
  m.absorption = v3_select(crystal, v3_scale(v3_sub(v3s(1, 1, 1), m.base_color), PARAM(tint)),
                           m.absorption);
  return m;
}
