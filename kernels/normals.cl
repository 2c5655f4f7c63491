/* normals.cl — surface normal from the DE's gradient, with a step h that follows the hit
 * threshold (so it grows with distance like the detail a pixel can resolve). FR_NORMALS picks:
 *   FR_NORMALS_TETRAHEDRON  tetrahedron: four DE evaluations at p + h k_i, k_i the corners of a tetrahedron
 *   FR_NORMALS_CENTRAL      central differences: six evaluations, p +- h along each axis */

#if FR_NORMALS == FR_NORMALS_CENTRAL
#define FR_NORMAL_EVALS 6
#else
#define FR_NORMAL_EVALS 4
#endif

vec3_t calc_normal(vec3_t p, real_t h, __constant const scene_params_t* params) {
#if FR_NORMALS == FR_NORMALS_CENTRAL
  vec3_t n = v3(scene_de(v3(p.x + h, p.y, p.z), params) - scene_de(v3(p.x - h, p.y, p.z), params),
                scene_de(v3(p.x, p.y + h, p.z), params) - scene_de(v3(p.x, p.y - h, p.z), params),
                scene_de(v3(p.x, p.y, p.z + h), params) - scene_de(v3(p.x, p.y, p.z - h), params));
#else
  const vec3_t k0 = v3s(1, -1, -1), k1 = v3s(-1, -1, 1), k2 = v3s(-1, 1, -1), k3 = v3s(1, 1, 1);
  vec3_t n = v3_scale(k0, scene_de(v3_mad(p, k0, h), params));
  n = v3_mad(n, k1, scene_de(v3_mad(p, k1, h), params));
  n = v3_mad(n, k2, scene_de(v3_mad(p, k2, h), params));
  n = v3_mad(n, k3, scene_de(v3_mad(p, k3, h), params));
#endif
  return v3_normalize(n);
}
