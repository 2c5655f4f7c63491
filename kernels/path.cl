/* path.cl — the path integrator (render.integrator = "path"), pasted instead of render.cl: one
 * sample of the light arriving through each pixel, by a random walk from surface to surface. The
 * kernel has render.cl's name and arguments, so the host runs either the same way, and the
 * samples accumulate in film.cl's running mean.
 *
 * At each hit the material (material.cl) decides what the light does, by lobes taken with their
 * odds, so that a lobe's throughput is its weight divided by its odds:
 *   metal (metalness): a GGX-rough mirror (roughness; 0 is a mirror) that reflects in its colour,
 *      with Schlick's Fresnel towards white at grazing angles;
 *   coat (specular, of the rest): the same mirror, untinted (surface_t.reflectivity);
 *   glass (transmission, of the rest): a rough dielectric: reflected with the exact unpolarised
 *      Fresnel reflectance, else refracted by Snell's law (total internal reflection beyond the
 *      critical angle) about a GGX microfacet normal; inside, the march follows the negated DE
 *      to where the solid ends, and the glass absorbs exp(-sigma t) on the way (Beer-Lambert,
 *      sigma = material absorption);
 *   subsurface (subsurface, of the rest): the light enters (diffuse transmission) and walks
 *      inside the DE volume: free flights of mean length mean_free_path (exponential), each
 *      ending in isotropic scattering that keeps the single-scattering albedo (material.cl maps
 *      subsurface_color to it), until the walk meets the surface and leaves it diffusely, or
 *      FR_WALK_MAX_STEPS scatterings end it;
 *   diffuse (the rest): Lambert, cosine-weighted, so its throughput is its albedo.
 * Next-event estimation towards every light (a shadow ray, hard: shadow.cl built with
 * FR_SHADOW_HARD) through the diffuse lobe, where a walk leaves the surface, and through the
 * rough metal, coat and glass (their GGX BRDF, the glass's reflection weighted by its Fresnel
 * reflectance, so a point light has a highlight on each); a light with a size is
 * also found by bounces, and the two estimates are weighted by multiple importance sampling
 * (area_lights.cl). A path that leaves the bounds sees the sky (FR_SKY, radiance): the
 * gradient is found only by bounces; a panorama (environment.cl) is also sampled by next-event
 * estimation in proportion to its light, weighted against the bounces the same way. Emission (material emission) is found
 * by the paths, as the sky is. From the third interaction on, Russian roulette: a path goes on
 * with probability q = max(throughput) and its throughput is divided by q, which keeps the mean.
 *
 * Units: a light's colour is what a white Lambertian surface facing it reflects (as in shade.cl),
 * so its irradiance is pi times that, and the diffuse BRDF albedo / pi turns it back into
 * albedo * cos * colour.
 *
 * Not here (the fast integrator's approximations of what this computes): ambient light and
 * occlusion, soft-shadow penumbrae, fog and glow. */

#ifndef FR_APPLY_LENS
#define FR_APPLY_LENS(ray, px, py)
#endif
#ifndef FR_CONE_START
#define FR_CONE_START(t, ao_steps)
#endif

/* pixel_random's streams: the lens takes 1 and 2; step k of the path takes these eight. */
#define FR_PATH_STREAM(k, i) (16U + 8U * (uint)(k) + (uint)(i))
/* The most scatterings in the subsurface walks of one path: a path that scatters more is ended
 * (its light lost). */
#define FR_WALK_MAX_STEPS 128

/* Roughness (GGX alpha) below which a glossy lobe is a mirror for next-event estimation: its
 * highlight of a light is then found by bounces alone. */
#define FR_GLOSSY_NEE_MIN_ALPHA 1e-3f

/* The exact unpolarised Fresnel reflectance of a dielectric for the cosine c_i (0 to 1) between
 * the ray and the (micro)normal, eta the index the ray leaves over the one it enters: 1 beyond
 * the critical angle. *cos_t: the refracted ray's cosine (Snell's law). */
inline real_t dielectric_fresnel(real_t c_i, real_t eta, real_t* cos_t) {
  const real_t sin2_t = eta * eta * fmax((real_t)1 - c_i * c_i, (real_t)0);
  *cos_t = sqrt(fmax((real_t)1 - sin2_t, (real_t)0));
  const real_t r_s = (eta * c_i - *cos_t) / (eta * c_i + *cos_t);
  const real_t r_p = (c_i - eta * *cos_t) / (c_i + eta * *cos_t);
  return lane_select(sin2_t >= (real_t)1, 1, (real_t)0.5 * (r_s * r_s + r_p * r_p));
}

/* The glossy lobes at a hit, for next-event estimation: the metal's, the coat's and the glass's
 * weights (throughput times their odds; the glass's only where the ray meets it from outside),
 * the metal's colour, the glass's eta (dielectric_fresnel's), the roughness, the way back to the
 * eye, and the lanes where there is such a lobe rough enough to be estimated. */
typedef struct glossy_lobes_t {
  vec3_t metal_weight;
  vec3_t coat_weight;
  vec3_t glass_weight;
  vec3_t base_color;
  real_t glass_eta;
  real_t alpha;
  vec3_t to_eye;
  mask_t lanes;
} glossy_lobes_t;

/* What light sample s (lights.cl's unit: radiance per unit cos that a white Lambertian facing it
 * reflects) sends to the eye through the glossy lobes of normal n: pi f cos (f the GGX BRDF,
 * D G F / (4 cos_i cos_o); F Schlick's in the metal's colour, 1 for the coat, the dielectric's
 * for the glass), times `weight`, each lobe weighted against its own bounce by multiple
 * importance sampling where the light was drawn with density light_pdf (0: a point or a
 * direction, which no bounce finds). The bounce draws the metal's and the coat's direction with
 * the GGX density, the glass's reflection with that times F (it refracts otherwise). */
inline vec3_t glossy_light(light_sample_t s, vec3_t n, glossy_lobes_t g, real_t weight,
                           real_t light_pdf) {
  const vec3_t half_vec = v3_normalize(v3_add(g.to_eye, s.to_light));
  const real_t cos_h = v3_dot(n, half_vec), v_h = fmax(v3_dot(g.to_eye, half_vec), (real_t)0);
  const real_t cos_i = v3_dot(n, g.to_eye), cos_o = v3_dot(n, s.to_light);
  const real_t d = ggx_d(cos_h, g.alpha);
  const real_t pdf = ggx_reflection_pdf(cos_h, v_h, g.alpha);
  const real_t common = lane_select(
      (cos_i > (real_t)0) & (cos_o > (real_t)0),
      (real_t)M_PI_F * d * ggx_g1(cos_i, g.alpha) * ggx_g1(cos_o, g.alpha) /
          fmax(4 * cos_i, (real_t)FR_SCALAR_MIN) * weight,
      0);
  const real_t grazing = pow_nonneg((real_t)1 - fmin(v_h, (real_t)1), 5);
  const vec3_t metal_color =
      v3_add(g.base_color, v3_scale(v3_sub(v3s(1, 1, 1), g.base_color), grazing));
  real_t cos_t;
  const real_t fresnel = dielectric_fresnel(fmin(v_h, (real_t)1), g.glass_eta, &cos_t);
  const mask_t sized = light_pdf > (real_t)0;
  const real_t w_mirror = lane_select(sized, power_heuristic(light_pdf, pdf), 1);
  const real_t w_glass = lane_select(sized, power_heuristic(light_pdf, pdf * fresnel), 1);
  const vec3_t reflect =
      v3_add(v3_scale(v3_add(v3_mul(g.metal_weight, metal_color), g.coat_weight), w_mirror),
             v3_scale(g.glass_weight, fresnel * w_glass));
  return v3_mul(v3_scale(reflect, common), s.radiance);
}

/* What every light (and a panorama sky) sends to the eye from p past whatever is in the way, by
 * next-event estimation: through the diffuse lobe of normal n where `diffuse` is set, times
 * diffuse_weight (the throughput times the lobe's colour and odds), and through the glossy lobes
 * `g`. Lights with a size and the panorama are also found by bounces: each estimate is weighted
 * against the lobe's bounce by multiple importance sampling (area_lights.cl). */
vec3_t direct_light(vec3_t p, vec3_t n, real_t h, mask_t diffuse, vec3_t diffuse_weight,
                    glossy_lobes_t g, int shadow_steps, lane_uint_t ix, lane_uint_t iy, int k,
                    __constant const fr_frame_constants* fc,
                    __constant const scene_params_t* params,
                    __global const float* environment FR_COUNTS_PARAM) {
  light_sample_t lights[FR_MAX_LIGHTS];
  mask_t facing[FR_MAX_LIGHTS];
  real_t visible[FR_MAX_LIGHTS], light_pdf[FR_MAX_LIGHTS];
  const mask_t lanes = diffuse | g.lanes;
  const int count = min(fc->light_count, FR_MAX_LIGHTS);
  for (int i = 0; i < count; ++i) {
    lights[i] = sample_light(i, p, fc);
    light_pdf[i] = (real_t)0; /* a point or a direction: found by the estimation alone */
    if (fc->light_radius[i] > 0.0f) {
      /* Each light its own pair of numbers: streams 5..7 and then the high ones, past any step's. */
      const light_cone_t c = light_cone(i, p, fc);
      const uint stream = FR_PATH_STREAM(k, 5) + (uint)i * 0x10000U;
      lights[i] = light_cone_sample(c, (scalar_t)fc->light_radius[i],
                                    fc->light_kind[i] == FR_KERNEL_LIGHT_DIRECTIONAL,
                                    pixel_random(fc, ix, iy, stream),
                                    pixel_random(fc, ix, iy, stream + 0x8000U));
      light_pdf[i] = light_cone_pdf(c);
    }
    facing[i] = lanes & (v3_dot(n, lights[i].to_light) > (real_t)0);
    visible[i] = (real_t)1;
  }
  FR_APPLY_SHADOWS(visible, p, n, h, lights, facing, count, shadow_steps);
  vec3_t direct = v3s(0, 0, 0);
  for (int i = 0; i < count; ++i) {
    if (!any_lane(facing[i])) continue;
    const real_t cos_l = v3_dot(n, lights[i].to_light);
    const real_t sized = light_pdf[i];
    const real_t w_diffuse = lane_select(sized > (real_t)0,
                                         power_heuristic(sized, cos_l * (real_t)M_1_PI_F), 1);
    direct = v3_add(direct, v3_mul(diffuse_weight,
                                   v3_scale(lights[i].radiance,
                                            lane_select(facing[i] & diffuse,
                                                        visible[i] * cos_l * w_diffuse, 0))));
    if (any_lane(facing[i] & g.lanes))
      direct = v3_add(direct, v3_select(facing[i] & g.lanes,
                                        glossy_light(lights[i], n, g, visible[i], sized),
                                        v3s(0, 0, 0)));
  }
#ifdef FR_SKY_SAMPLED
  /* The panorama: one direction drawn in proportion to its light, its own shadow ray (counted
   * with the first light's), weighted against the bounces that might find it too. */
  {
    real_t pdf;
    light_sample_t sky[1];
    sky[0] = environment_sample(pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 6)),
                                pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 6) + 0x8000U), fc,
                                environment, &pdf);
    const real_t cos_l = v3_dot(n, sky[0].to_light);
    mask_t sky_facing[1];
    sky_facing[0] = lanes & (cos_l > (real_t)0) & (pdf > (real_t)0);
    real_t sky_visible[1];
    sky_visible[0] = (real_t)1;
    if (any_lane(sky_facing[0])) {
      FR_APPLY_SHADOWS(sky_visible, p, n, h, sky, sky_facing, 1, shadow_steps);
      const real_t w = power_heuristic(pdf, cos_l * (real_t)M_1_PI_F);
      direct = v3_add(direct,
                      v3_mul(diffuse_weight,
                             v3_scale(sky[0].radiance,
                                      lane_select(sky_facing[0] & diffuse,
                                                  sky_visible[0] * cos_l * w, 0))));
      if (any_lane(sky_facing[0] & g.lanes))
        direct = v3_add(direct, v3_select(sky_facing[0] & g.lanes,
                                          glossy_light(sky[0], n, g, sky_visible[0], pdf),
                                          v3s(0, 0, 0)));
    }
  }
#endif
  return direct;
}

/* The lights with a size that the ray from o along d meets before t_end: their radiance, each
 * weighted against next-event estimation where the ray left a lobe that the estimation covers,
 * drawn with density lobe_pdf (0: another lobe, which the estimation did not see). */
vec3_t lights_met(vec3_t o, vec3_t d, real_t t_end, mask_t lanes, real_t lobe_pdf,
                  __constant const fr_frame_constants* fc) {
  vec3_t sum = v3s(0, 0, 0);
  const int count = min(fc->light_count, FR_MAX_LIGHTS);
  for (int i = 0; i < count; ++i) {
    if (!(fc->light_radius[i] > 0.0f)) continue;
    const int directional = fc->light_kind[i] == FR_KERNEL_LIGHT_DIRECTIONAL;
    const light_cone_t c = light_cone(i, o, fc);
    real_t t_hit;
    const mask_t met = lanes & light_hit(c, d, directional, (scalar_t)fc->light_radius[i], &t_hit) &
                       (directional ? t_end >= (real_t)FR_SCALAR_MAX : t_hit < t_end);
    if (!any_lane(met)) continue;
    const real_t w = lane_select(lobe_pdf > (real_t)0,
                                 power_heuristic(lobe_pdf, light_cone_pdf(c)), 1);
    sum = v3_add(sum, v3_select(met, v3_scale(c.radiance, w), v3s(0, 0, 0)));
  }
  return sum;
}

__kernel void fr_render(FR_RENDER_KERNEL_PARAMS) {
  FR_COUNTS_BEGIN;
  FR_RENDER_TILE;
  const lane_uint_t ix = image_pixel_x(fc, px), iy = image_pixel_y(fc, py);

  real_t path_t;
  ray_t ray = camera_ray(fc, px, py, (real_t)fc->jitter_x, (real_t)fc->jitter_y, &path_t);
  FR_APPLY_LENS(ray, px, py);

  vec3_t radiance = v3s(0, 0, 0);
  vec3_t throughput = v3s(1, 1, 1);
  mask_t active = FR_MASK_TRUE;
  /* Where the ray is: inside glass, with its absorption per unit length; inside a scattering
   * medium, with its single-scattering albedo and mean free path. */
  mask_t in_glass = FR_MASK_FALSE, in_medium = FR_MASK_FALSE;
  vec3_t sigma = v3s(0, 0, 0), medium_albedo = v3s(0, 0, 0);
  real_t mean_free_path = (real_t)1;
  /* The last crossing of the surface: into or out of glass, or of a medium; none since the
   * last reflection outside. */
  mask_t crossed_glass = FR_MASK_FALSE, crossed_medium = FR_MASK_FALSE;
  /* Surface interactions and scatterings so far, per lane. */
  real_t bounces = (real_t)0, scatterings = (real_t)0;
  /* The density with which the lobe that chose this ray's direction drew it, where next-event
   * estimation covers that lobe too (diffuse, rough metal and coat); 0 otherwise. */
  real_t lobe_pdf = (real_t)0;
  pixel_passes_t out;
  out.depth = (real_t)INFINITY;
  out.steps = (real_t)0;
  out.status = (real_t)0;
  out.ao = (real_t)1;
  out.shadow = (real_t)1;
  out.normal = v3s(0, 0, 0);
  out.albedo = v3s(0, 0, 0);
  /* Where the cone pre-pass (cone.cl) lets the primary ray start. */
  real_t cone_from = (real_t)0, cone_ao = (real_t)0;
  FR_CONE_START(cone_from, cone_ao);
  const int steps_most = fc->path_max_bounces + 1 + FR_WALK_MAX_STEPS;
  for (int k = 0; k < steps_most; ++k) {
    FR_COUNT_BOUNCE(k);
    /* Rays after the first march with the mirror bounces' budget (frame_constants.h); every
     * shadow ray with the primary hits' (the bounces' may be 0, which in the fast integrator
     * means reflections without shadows, and here would let light through walls). */
    const int max_steps = k == 0 ? fc->max_steps : fc->bounce_max_steps;
    const int shadow_steps = fc->shadow_max_steps;
    /* In a medium the ray flies an exponential distance before it scatters. */
    const real_t u_flight = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 7));
    const real_t flight = -log(fmax((real_t)1 - u_flight, (real_t)FR_SCALAR_MIN)) * mean_free_path;
    /* Inside glass or a medium the march looks for where the solid ends: its DE negated. */
    const mask_t inner = in_glass | in_medium;
    march_result_t m = march(ray, path_t, k == 0 ? cone_from : (real_t)0,
                             lane_select(in_medium, flight, FR_SCALAR_MAX), max_steps,
                             lane_select(inner, -1, 1), fc, params FR_COUNTS_ARG);
    /* What the glass absorbed on the way (Beer-Lambert), of whatever the ray reaches. */
    const mask_t absorbing = active & in_glass;
    if (any_lane(absorbing))
      throughput = v3_select(absorbing,
                             v3_mul(throughput, v3(exp(-sigma.x * m.t), exp(-sigma.y * m.t),
                                                   exp(-sigma.z * m.t))),
                             throughput);
    const mask_t hit = active & m.hit;
    const mask_t miss = active & !m.hit & !m.inside & !in_medium;
    if (any_lane(miss)) {
      vec3_t sky = FR_SKY(ray.dir);
#ifdef FR_SKY_SAMPLED
      /* Found by a bounce that next-event estimation covers: weighted against its draw. */
      sky = v3_scale(sky, lane_select(lobe_pdf > (real_t)0,
                                      power_heuristic(lobe_pdf,
                                                      environment_pdf(ray.dir, fc, environment)),
                                      1));
#endif
      radiance = v3_add(radiance, v3_select(miss, v3_mul(throughput, sky), v3s(0, 0, 0)));
    }
    /* Lights with a size on the way (outside the solid only). */
    const mask_t outside = active & !inner & !m.inside;
    if (any_lane(outside))
      radiance = v3_add(radiance,
                        v3_mul(throughput, lights_met(ray.origin, ray.dir,
                                                      lane_select(hit, m.t, FR_SCALAR_MAX),
                                                      outside, lobe_pdf, fc)));
    if (k == 0) {
      out.depth = lane_select(m.hit | m.inside, path_t + m.t, INFINITY);
      out.steps = m.steps;
      out.status = lane_select(m.inside, FR_RAY_INSIDE,
                               lane_select(m.out_of_steps, FR_RAY_OUT_OF_STEPS,
                                           lane_select(m.hit, FR_RAY_HIT, FR_RAY_MISS)));
    }
    /* A ray that starts on the wrong side of the surface for its march (a crossing's origin
     * pushed through a thin wall, or off a normal estimated at the pixel's scale) marches again
     * in the other mode. Inside glass or a medium, it is outside; outside, it is inside what it
     * last crossed, or else inside what the solid there is made of: glass where it transmits,
     * a medium where it scatters under its surface; an opaque solid, where no light reaches. */
    const mask_t leaving = active & m.inside & inner;
    const mask_t stray = active & m.inside & !inner;
    mask_t into_glass = stray & crossed_glass, into_medium = stray & crossed_medium;
    const mask_t unknown = stray & !crossed_glass & !crossed_medium;
    if (any_lane(unknown)) {
      const material_t solid = material_at(ray.origin);
      const mask_t glassy = unknown & (solid.transmission > (real_t)0) &
                            (solid.metalness < (real_t)1) & (solid.specular < (real_t)1);
      const mask_t milky = unknown & !glassy & (solid.subsurface > (real_t)0) &
                           (solid.metalness < (real_t)1) & (solid.specular < (real_t)1);
      sigma = v3_select(glassy, solid.absorption, sigma);
      medium_albedo = v3_select(milky, single_scattering_albedos(solid.subsurface_color),
                                medium_albedo);
      mean_free_path = lane_select(milky, solid.mean_free_path, mean_free_path);
      into_glass |= glassy;
      into_medium |= milky;
    }
    in_glass = (in_glass & !leaving) | into_glass;
    in_medium = (in_medium & !leaving) | into_medium;
    const mask_t wrong_side = leaving | into_glass | into_medium;
    /* A flight that ended inside the medium: it scatters there, in a uniform direction, keeping
     * the single-scattering albedo. */
    const mask_t scatter = active & in_medium & !m.hit & !m.inside;
    if (any_lane(scatter)) {
      const vec3_t q = v3_mad(ray.origin, ray.dir, flight);
      const vec3_t d = sphere_direction(pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 1)),
                                        pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 2)));
      ray.origin = v3_select(scatter, q, ray.origin);
      ray.dir = v3_select(scatter, d, ray.dir);
      throughput = v3_select(scatter, v3_mul(throughput, medium_albedo), throughput);
      scatterings += mask_to_real(scatter);
      path_t += lane_select(scatter, flight, 0);
    }
    active = (hit | wrong_side | scatter) & (scatterings <= (real_t)FR_WALK_MAX_STEPS);
    if (!any_lane(active)) break;

    if (any_lane(hit)) {
      const vec3_t p = v3_mad(ray.origin, ray.dir, m.t);
      const real_t h = hit_threshold(fc, path_t + m.t, p);
      /* Normals at the scale of the pixel's footprint, as render.cl takes them. */
      const real_t normal_h = fmax(h, (real_t)(0.5f * fc->pixel_angle_rad) * (path_t + m.t));
      const vec3_t gradient = calc_normal(p, normal_h, params);
      FR_COUNT(FR_COUNT_NORMALS, hit, FR_NORMAL_EVALS);
      vec3_t n = v3_select(v3_length2(gradient) > (real_t)0, v3_normalize(gradient),
                           v3_neg(ray.dir));
      /* A normal that faces away from the ray (estimated across a thin feature, or seen from
       * inside): the side the ray came from, so that bounces and lights stay on it. */
      n = v3_select(v3_dot(n, ray.dir) > (real_t)0, v3_neg(n), n);
      const material_t mat = material_at(p);
      FR_COUNT(FR_COUNT_SURFACE, hit, FR_HAS_SURFACE);
      /* Where the ray meets the surface from outside, the material's lobes, with their odds. */
      const mask_t from_outside = hit & !in_glass & !in_medium;
      const real_t metal_odds = lane_select(from_outside, mat.metalness, 0);
      const real_t rest = (real_t)1 - mat.metalness;
      const real_t coat_odds = lane_select(from_outside, rest * mat.specular, 0);
      const real_t glass_odds = lane_select(
          in_glass, 1,
          lane_select(from_outside, rest * ((real_t)1 - mat.specular) * mat.transmission, 0));
      const real_t diffuse_rest =
          rest * ((real_t)1 - mat.specular) * ((real_t)1 - mat.transmission);
      /* A medium whose mean free path is below the surface's scale here (the hit threshold,
       * which the walk's entry and exit are resolved to) scatters within the pixel's footprint:
       * there it is the diffuse reflection of its overall colour, which is what subsurface_color
       * is (a walk would start 2 thresholds deep, many free paths, and seldom come back). */
      const mask_t resolved = mat.mean_free_path > h;
      const real_t subsurface_share = diffuse_rest * mat.subsurface;
      const real_t subsurface_odds = lane_select(from_outside & resolved, subsurface_share, 0);
      const real_t diffuse_odds = lane_select(
          from_outside, diffuse_rest - lane_select(resolved, subsurface_share, 0), 0);
      /* The diffuse lobe's colour: the base colour's, mixed with the unresolved medium's. */
      const vec3_t diffuse_color = v3_select(
          resolved, mat.base_color,
          v3_scale(v3_add(v3_scale(mat.base_color, diffuse_rest - subsurface_share),
                          v3_scale(mat.subsurface_color, subsurface_share)),
                   (real_t)1 / fmax(diffuse_rest, (real_t)FR_SCALAR_MIN)));
      /* A walk that reached the surface leaves it: a diffuse lobe on the outer side. */
      const mask_t leaving_medium = hit & in_medium;
      /* Light the surface gives off (seen from outside), found by the path like the sky. */
      radiance = v3_add(radiance,
                        v3_select(from_outside, v3_mul(throughput, mat.emission), v3s(0, 0, 0)));
      if (k == 0) {
        out.normal = v3_select(hit, n, out.normal);
        out.albedo = v3_select(hit, mat.base_color, out.albedo);
      }
      bounces += mask_to_real(hit);
      const mask_t last = hit & (bounces > (real_t)fc->path_max_bounces);

      /* Next-event estimation through the diffuse lobe (of the outer side where a walk leaves)
       * and the rough metal, coat and glass (its reflection, met from outside). */
      const real_t alpha = mat.roughness * mat.roughness;
      const vec3_t lit_normal = v3_select(leaving_medium, v3_neg(n), n);
      const vec3_t lit_weight =
          v3_select(leaving_medium, throughput,
                    v3_scale(v3_mul(throughput, diffuse_color), diffuse_odds));
      const mask_t lit = (leaving_medium | (diffuse_odds > (real_t)0)) & hit;
      glossy_lobes_t lobes;
      lobes.metal_weight = v3_scale(throughput, metal_odds);
      lobes.coat_weight = v3_scale(throughput, coat_odds);
      const real_t glass_nee_odds = lane_select(from_outside, glass_odds, 0);
      lobes.glass_weight = v3_scale(throughput, glass_nee_odds);
      lobes.glass_eta = (real_t)1 / mat.ior;
      lobes.base_color = mat.base_color;
      lobes.alpha = alpha;
      lobes.to_eye = v3_neg(ray.dir);
      lobes.lanes = hit & (metal_odds + coat_odds + glass_nee_odds > (real_t)0) &
                    (alpha >= (real_t)FR_GLOSSY_NEE_MIN_ALPHA);
      if (any_lane(lit | lobes.lanes))
        radiance = v3_add(radiance, direct_light(p, lit_normal, h, lit, lit_weight, lobes,
                                                 shadow_steps, ix, iy, k, fc, params,
                                                 environment FR_COUNTS_ARG));

      /* The next direction, with the lobes' odds. */
      const real_t u_lobe = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 0));
      const real_t u1 = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 1));
      const real_t u2 = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 2));
      const real_t u_fresnel = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 3));
      const mask_t choosing = hit & !leaving_medium;
      const mask_t metal = choosing & (u_lobe < metal_odds);
      const mask_t coat = choosing & !metal & (u_lobe < metal_odds + coat_odds);
      const mask_t glass =
          choosing & !metal & !coat & (u_lobe < metal_odds + coat_odds + glass_odds);
      const mask_t enter_medium = choosing & !metal & !coat & !glass &
                                  (u_lobe < metal_odds + coat_odds + glass_odds + subsurface_odds);
      const mask_t diffuse = hit & (leaving_medium | (!metal & !coat & !glass & !enter_medium));
      const mask_t glossy = hit & (metal | coat | glass);
      /* The glossy lobes' microfacet normal m (m = n for a polished surface). */
      const vec3_t micro = ggx_normal(n, alpha, u1, u2);
      const vec3_t to_eye = v3_neg(ray.dir);
      const real_t cos_i = v3_dot(to_eye, n);
      const real_t cos_im = v3_dot(to_eye, micro);
      /* Glass: reflected with the Fresnel reflectance F (unpolarised, exact; 1 beyond the
       * critical angle), else refracted by Snell's law. n faces the ray, so eta is the index the
       * ray leaves over the one it enters. */
      const real_t eta = lane_select(in_glass, mat.ior, (real_t)1 / mat.ior);
      const real_t c_i = fmin(fabs(cos_im), (real_t)1);
      real_t cos_t;
      const real_t fresnel = dielectric_fresnel(c_i, eta, &cos_t);
      const mask_t refract = hit & glass & (u_fresnel >= fresnel);
      const vec3_t mirrored = v3_mad(ray.dir, micro, -2 * v3_dot(ray.dir, micro));
      const vec3_t refracted =
          v3_normalize(v3_mad(v3_scale(ray.dir, eta), micro, eta * c_i - cos_t));
      const vec3_t diffuse_dir = cosine_direction(lit_normal, u1, u2);
      const vec3_t inward_dir = cosine_direction(v3_neg(n), u1, u2);
      const vec3_t next_dir = v3_select(
          refract, refracted,
          v3_select(glossy, mirrored, v3_select(enter_medium, inward_dir, diffuse_dir)));
      /* The glossy sample's weight (material.cl); lost where the microfacet faces away or the
       * direction leaves on the wrong side of the surface. */
      const real_t cos_o = v3_dot(next_dir, n);
      const mask_t right_side =
          (cos_im > (real_t)0) & ((refract & (cos_o < (real_t)0)) | (!refract & (cos_o > (real_t)0)));
      const real_t glossy_weight =
          lane_select(right_side, ggx_weight(cos_im, cos_i, cos_o, v3_dot(micro, n), alpha), 0);
      /* A metal reflects its colour, whiter towards grazing angles (Schlick). */
      const real_t grazing = pow_nonneg((real_t)1 - fmin(fmax(cos_im, (real_t)0), (real_t)1), 5);
      const vec3_t metal_color =
          v3_add(mat.base_color, v3_scale(v3_sub(v3s(1, 1, 1), mat.base_color), grazing));
      const vec3_t weight = v3_select(
          glossy, v3_scale(v3_select(metal, metal_color, v3s(1, 1, 1)), glossy_weight),
          v3_select(diffuse & !leaving_medium, diffuse_color, v3s(1, 1, 1)));
      throughput = v3_select(hit, v3_mul(throughput, weight), throughput);
      /* Off the surface on the side the ray goes: through it where it crosses. */
      const vec3_t side = v3_select(leaving_medium, v3_neg(n), n);
      ray.origin = v3_select(
          hit, v3_mad(p, side, lane_select(refract | enter_medium, -2 * h, 2 * h)), ray.origin);
      ray.dir = v3_select(hit, next_dir, ray.dir);
      /* What next-event estimation weighs the light this ray finds against (direct_light). */
      const real_t diffuse_pdf = fmax(v3_dot(next_dir, lit_normal), (real_t)0) * (real_t)M_1_PI_F;
      const real_t glossy_pdf = ggx_reflection_pdf(v3_dot(micro, n), cos_im, alpha);
      lobe_pdf = lane_select(
          hit,
          lane_select(diffuse, diffuse_pdf,
                      lane_select((metal | coat) & (alpha >= (real_t)FR_GLOSSY_NEE_MIN_ALPHA),
                                  glossy_pdf,
                                  /* the glass's reflection, met from outside (next-event
                                   * estimation covers it); not its refraction */
                                  lane_select(glass & !refract & from_outside &
                                                  (alpha >= (real_t)FR_GLOSSY_NEE_MIN_ALPHA),
                                              glossy_pdf * fresnel, 0))),
          lobe_pdf);
      /* Entering glass: its absorption; entering a medium: its albedo and mean free path. */
      sigma = v3_select(refract & !in_glass, mat.absorption, sigma);
      in_glass ^= refract;
      medium_albedo =
          v3_select(enter_medium, single_scattering_albedos(mat.subsurface_color), medium_albedo);
      mean_free_path = lane_select(enter_medium, mat.mean_free_path, mean_free_path);
      in_medium = (in_medium & !leaving_medium) | enter_medium;
      crossed_glass = (hit & (refract | (crossed_glass & in_glass))) | (!hit & crossed_glass);
      crossed_medium = (hit & (enter_medium | leaving_medium)) | (!hit & crossed_medium);
      path_t += lane_select(hit, m.t, 0);
      active &= !last;
    }
    if (k >= 2) {
      const real_t q = clamp(fmax(throughput.x, fmax(throughput.y, throughput.z)), (real_t)0.05,
                             (real_t)1);
      active &= pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 4)) < q;
      throughput = v3_scale(throughput, (real_t)1 / q);
    }
    if (!any_lane(active)) break;
  }

  FR_COUNTS_END(counts_out);
  out.color = radiance;
  film_write(tile_x, tile_y, out, fc, hdr_rgba, depth, steps_out, factors_out, status_out,
             normal_out, albedo_out);
}
