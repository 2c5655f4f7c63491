/* normals.cl — surface normal from the DE by the tetrahedron technique: four DE evaluations at
 * p + h * k_i with k_i the corners of a tetrahedron; h follows the hit threshold, so it grows
 * with distance like the detail the pixel can resolve. */

vec3_t calc_normal(vec3_t p, real_t h, __constant const scene_params_t* params) {
  const vec3_t k0 = v3s(1, -1, -1), k1 = v3s(-1, -1, 1), k2 = v3s(-1, 1, -1), k3 = v3s(1, 1, 1);
  real_t d0 = scene_de(v3_mad(p, k0, h), params);
  real_t d1 = scene_de(v3_mad(p, k1, h), params);
  real_t d2 = scene_de(v3_mad(p, k2, h), params);
  real_t d3 = scene_de(v3_mad(p, k3, h), params);
  vec3_t n = v3_scale(k0, d0);
  n = v3_mad(n, k1, d1);
  n = v3_mad(n, k2, d2);
  n = v3_mad(n, k3, d3);
  return v3_normalize(n);
}
