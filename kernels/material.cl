/* material.cl — path tracing's materials (material_t, prelude.cl): the material at a surface
 * point, and the sampling of its glossy lobes and its scattering medium.
 *
 * Without a scene material function the material comes from the surface colour (the scene's
 * surface source, else render.albedo) and the render settings, so every scene path-traces
 * unchanged; a scene whose surface source defines scene_material (prelude.cl) changes it per
 * point (the host then defines FR_SCENE_MATERIAL). */

inline real_t unit_clamp(real_t x) { return fmin(fmax(x, (real_t)0), (real_t)1); }
inline vec3_t v3_unit_clamp(vec3_t v) { return v3(unit_clamp(v.x), unit_clamp(v.y), unit_clamp(v.z)); }
/* Non-negative and finite (NaN becomes 0: fmax returns the number). */
inline vec3_t v3_nonneg(vec3_t v) {
  const real_t most = (real_t)FR_SCALAR_MAX;
  return v3(fmin(fmax(v.x, (real_t)0), most), fmin(fmax(v.y, (real_t)0), most),
            fmin(fmax(v.z, (real_t)0), most));
}

inline material_t default_material(surface_t s, __constant const fr_frame_constants* fc) {
  const vec3_t albedo = v3_unit_clamp(s.albedo);
  material_t m;
  m.base_color = albedo;
  m.specular = s.reflectivity;
  m.roughness = (real_t)fc->specular_roughness;
  m.metalness = (real_t)fc->metalness;
  m.transmission = (real_t)fc->transmission;
  m.ior = (real_t)fc->ior;
  /* Tinted glass: light of the surface's colour passes. */
  m.absorption = v3_scale(v3_sub(v3s(1, 1, 1), albedo), (real_t)fc->absorption);
  m.subsurface = (real_t)fc->subsurface;
  m.subsurface_color = albedo;
  m.mean_free_path = (real_t)fc->mean_free_path;
  m.emission = v3_scale(albedo, (real_t)fc->emission);
  return m;
}

/* A material inside its ranges (prelude.cl); NaN goes to the range's low end. */
inline material_t material_clamped(material_t m, __constant const fr_frame_constants* fc) {
  m.base_color = v3_unit_clamp(m.base_color);
  m.specular = unit_clamp(m.specular);
  m.roughness = unit_clamp(m.roughness);
  m.metalness = unit_clamp(m.metalness);
  m.transmission = unit_clamp(m.transmission);
  m.ior = fmin(fmax(m.ior, (real_t)1), (real_t)4);
  m.absorption = v3_nonneg(m.absorption);
  m.subsurface = unit_clamp(m.subsurface);
  m.subsurface_color = v3_unit_clamp(m.subsurface_color);
  m.mean_free_path = fmax(m.mean_free_path, (real_t)(1e-6f * fc->bounding_radius));
  m.emission = v3_nonneg(m.emission);
  return m;
}

#if FR_SCENE_MATERIAL
#define scene_material_at(p, m) scene_material((p), (m), params)
#else
#define scene_material_at(p, m) (m)
#endif

/* The material at the surface point p. (surface_at, shade.cl, reads params or fc.) */
#define material_at(p) material_clamped(scene_material_at((p), default_material(surface_at(p), fc)), fc)

/* Two unit vectors that make a right-handed orthonormal basis with the unit n, without a branch
 * (Duff et al. 2017, "Building an orthonormal basis, revisited"). */
inline void tangent_basis(vec3_t n, vec3_t* t, vec3_t* s) {
  const real_t sign = lane_select(n.z >= (real_t)0, 1, -1);
  const real_t a = (real_t)-1 / (sign + n.z);
  const real_t b = n.x * n.y * a;
  *t = v3((real_t)1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  *s = v3(b, sign + n.y * n.y * a, -n.y);
}

/* The unit vector at polar angle theta (given as its cosine and sine) and azimuth phi around n. */
inline vec3_t around(vec3_t n, real_t cos_theta, real_t sin_theta, real_t phi) {
  vec3_t t, s;
  tangent_basis(n, &t, &s);
  return v3_add(v3_add(v3_scale(t, sin_theta * cos(phi)), v3_scale(s, sin_theta * sin(phi))),
                v3_scale(n, cos_theta));
}

/* A unit vector around the unit n with density cos(theta) / pi, from two uniform numbers: a
 * uniform point of the unit disc lifted onto the hemisphere (Malley's method). */
inline vec3_t cosine_direction(vec3_t n, real_t u1, real_t u2) {
  return around(n, sqrt(fmax((real_t)1 - u1, (real_t)0)), sqrt(u1), (real_t)(2 * M_PI_F) * u2);
}

/* A unit vector with uniform density over the sphere (the medium's isotropic scattering). */
inline vec3_t sphere_direction(real_t u1, real_t u2) {
  const real_t z = (real_t)1 - 2 * u1;
  const real_t r = sqrt(fmax((real_t)1 - z * z, (real_t)0));
  const real_t phi = (real_t)(2 * M_PI_F) * u2;
  return v3(r * cos(phi), r * sin(phi), z);
}

/* GGX microfacets (Walter, Marschner, Li and Torrance 2007, "Microfacet models for refraction
 * through rough surfaces"): a microfacet normal around n with density D(m) (m.n), alpha the GGX
 * roughness (0: m = n, a mirror). With the lobe's direction o reflected or refracted about m,
 * the sample's weight is |i.m| G(i, o) / (|i.n| |m.n|) for reflection and refraction alike (their
 * eq. 41), G Smith's shadowing, G1(i) G1(o). */
inline vec3_t ggx_normal(vec3_t n, real_t alpha, real_t u1, real_t u2) {
  const real_t tan2 = alpha * alpha * u1 / fmax((real_t)1 - u1, (real_t)FR_SCALAR_EPSILON);
  const real_t cos_m = rsqrt((real_t)1 + tan2);
  const real_t sin_m = sqrt(fmax((real_t)1 - cos_m * cos_m, (real_t)0));
  return around(n, cos_m, sin_m, (real_t)(2 * M_PI_F) * u2);
}

/* GGX's distribution of microfacet normals D(m), at a normal whose cosine with n is cos_m. */
inline real_t ggx_d(real_t cos_m, real_t alpha) {
  const real_t a2 = alpha * alpha;
  const real_t k = cos_m * cos_m * (a2 - (real_t)1) + (real_t)1;
  return lane_select(cos_m > (real_t)0, a2 / fmax((real_t)M_PI_F * k * k, (real_t)FR_SCALAR_MIN), 0);
}

/* The density per solid angle of a direction reflected about a microfacet normal m drawn by
 * ggx_normal: D(m) (m.n) / (4 |i.m|) (the reflection's Jacobian, Walter et al.'s eq. 14). */
inline real_t ggx_reflection_pdf(real_t m_dot_n, real_t i_dot_m, real_t alpha) {
  return ggx_d(m_dot_n, alpha) * m_dot_n / fmax(4 * fabs(i_dot_m), (real_t)FR_SCALAR_MIN);
}

/* Smith's G1 for GGX at a direction whose cosine with the normal is cos_v. */
inline real_t ggx_g1(real_t cos_v, real_t alpha) {
  const real_t cos2 = fmax(cos_v * cos_v, (real_t)FR_SCALAR_MIN);
  const real_t tan2 = fmax((real_t)1 - cos2, (real_t)0) / cos2;
  return (real_t)2 / ((real_t)1 + sqrt((real_t)1 + alpha * alpha * tan2));
}

inline real_t ggx_weight(real_t i_dot_m, real_t i_dot_n, real_t o_dot_n, real_t m_dot_n,
                         real_t alpha) {
  return fabs(i_dot_m) * ggx_g1(i_dot_n, alpha) * ggx_g1(o_dot_n, alpha) /
         fmax(fabs(i_dot_n) * fabs(m_dot_n), (real_t)FR_SCALAR_MIN);
}

/* The single-scattering albedo whose multiple scattering under a surface reflects the colour A
 * overall, so that subsurface_color is the colour one sees (Chiang, Kutz and Burley 2016,
 * "Practical and controllable subsurface scattering for production path tracing": their fit
 * for a half-space; 0 and 1 map to themselves). */
inline real_t single_scattering_albedo(real_t a) {
  const real_t s = (real_t)4.09712 + (real_t)4.20863 * a -
                   sqrt((real_t)9.59217 + (real_t)41.6808 * a + (real_t)17.7126 * a * a);
  return unit_clamp((real_t)1 - s * s);
}
inline vec3_t single_scattering_albedos(vec3_t color) {
  return v3(single_scattering_albedo(color.x), single_scattering_albedo(color.y),
            single_scattering_albedo(color.z));
}
