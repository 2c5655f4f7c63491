/* sphereflake_surface.cl — colour by orbit trap: the level of the nearest sphere; path traced,
 * spheres that scatter light under a thin coat. */
#include "fr/palette.cl"

surface_t scene_surface(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  de_sphereflake(p, PARAM(levels), PARAM(child_scale), &trap);
  return surface_from_trap(trap, PARAM(color_near), PARAM(color_far),
                           PARAM(color_contrast), 0.25);
}

/* Path tracing: the colour comes from under the surface (a random walk of the given mean free
 * path), under a clear coat that mirrors a little, slightly rough. */
material_t scene_material(vec3_t p, material_t m, __constant const scene_params_t* params) {
  m.subsurface = to_real(PARAM(translucency));
  m.mean_free_path = to_real(PARAM(mean_free_path));
  m.specular = to_real(0.05);
  m.roughness = to_real(0.3);
  return m;
}
