/* path.cl — the path integrator (render.integrator = "path"), pasted instead of render.cl: one
 * sample of the light arriving through each pixel, by a random walk from surface to surface. The
 * kernel has render.cl's name and arguments, so the host runs either the same way, and the
 * samples accumulate in film.cl's running mean.
 *
 * At each hit: next-event estimation towards every light (a shadow ray, hard: shadow.cl built
 * with FR_SHADOW_HARD), then the next direction: the mirror one with the surface's reflectivity as
 * its probability, else a diffuse one, cosine-weighted, so that a Lambertian surface's throughput
 * is its albedo. A path that leaves the bounds sees the sky (shade.cl's sky_color, radiance): the
 * environment is found only by bounces, and the lights (points and directions, which no bounce
 * can hit) only by the estimation, so no light is counted twice. From the third interaction on,
 * Russian roulette: a path goes on with probability q = max(throughput) and its throughput is
 * divided by q, which keeps the mean.
 *
 * Units: a light's colour is what a white Lambertian surface facing it reflects (as in shade.cl),
 * so its irradiance is pi times that, and the diffuse BRDF albedo / pi turns it back into
 * albedo * cos * colour.
 *
 * Glass (render.transmission of the light not mirrored): at its surface the ray is reflected with
 * the Fresnel reflectance or refracted by Snell's law (index render.ior); inside, it marches the
 * negated DE to where the solid ends, and the glass absorbs exp(-sigma t) of it on the way
 * (Beer-Lambert; sigma = render.absorption per bounding radius times 1 - the surface's colour, so
 * light of that colour passes). No light is estimated through glass: a caustic comes only from
 * the sky, by bounces.
 *
 * Emission (render.emission times the surface's colour) is found by the paths, as the sky is.
 *
 * Not here (the fast integrator's approximations of what this computes): ambient light and
 * occlusion, soft-shadow penumbrae, fog and glow. */

#ifndef FR_APPLY_LENS
#define FR_APPLY_LENS(ray, px, py)
#endif
#ifndef FR_CONE_START
#define FR_CONE_START(t, ao_steps)
#endif

/* pixel_random's streams: the lens takes 1 and 2; interaction k takes these eight. */
#define FR_PATH_STREAM(k, i) (16U + 8U * (uint)(k) + (uint)(i))

/* A unit vector around the unit n with density cos(theta) / pi, from two uniform numbers: a
 * uniform point of the unit disc lifted onto the hemisphere (Malley's method), in the basis of
 * Duff et al. 2017 ("Building an orthonormal basis, revisited"), which has no branch. */
vec3_t cosine_direction(vec3_t n, real_t u1, real_t u2) {
  const real_t sign = lane_select(n.z >= (real_t)0, 1, -1);
  const real_t a = (real_t)-1 / (sign + n.z);
  const real_t b = n.x * n.y * a;
  const vec3_t t = v3((real_t)1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const vec3_t s = v3(b, sign + n.y * n.y * a, -n.y);
  const real_t r = sqrt(u1), phi = (real_t)(2 * M_PI_F) * u2;
  const real_t z = sqrt(fmax((real_t)1 - u1, (real_t)0));
  return v3_add(v3_add(v3_scale(t, r * cos(phi)), v3_scale(s, r * sin(phi))), v3_scale(n, z));
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
  /* Inside the glass (render.transmission), and its absorption there per unit length. */
  mask_t in_glass = FR_MASK_FALSE;
  vec3_t sigma = v3s(0, 0, 0);
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
  for (int k = 0; k <= fc->path_max_bounces; ++k) {
    FR_COUNT_BOUNCE(k);
    /* Rays after the first march with the mirror bounces' budget (frame_constants.h); every
     * shadow ray with the primary hits' (the bounces' may be 0, which in the fast integrator
     * means reflections without shadows, and here would let light through walls). */
    const int max_steps = k == 0 ? fc->max_steps : fc->bounce_max_steps;
    const int shadow_steps = fc->shadow_max_steps;
    /* Inside the glass the march looks for where the solid ends: its DE negated. */
    march_result_t m = march(ray, path_t, k == 0 ? cone_from : (real_t)0, max_steps,
                             lane_select(in_glass, -1, 1), fc, params FR_COUNTS_ARG);
    /* What the glass absorbed on the way (Beer-Lambert), of whatever the ray reaches. */
    const mask_t absorbing = active & in_glass;
    if (any_lane(absorbing))
      throughput = v3_select(absorbing,
                             v3_mul(throughput, v3(exp(-sigma.x * m.t), exp(-sigma.y * m.t),
                                                   exp(-sigma.z * m.t))),
                             throughput);
    const mask_t hit = active & m.hit;
    const mask_t miss = active & !m.hit & !m.inside;
    radiance = v3_add(radiance, v3_select(miss, v3_mul(throughput, sky_color(ray.dir, fc)),
                                          v3s(0, 0, 0)));
    if (k == 0) {
      out.depth = lane_select(m.hit | m.inside, path_t + m.t, INFINITY);
      out.steps = m.steps;
      out.status = lane_select(m.inside, FR_RAY_INSIDE,
                               lane_select(m.out_of_steps, FR_RAY_OUT_OF_STEPS,
                                           lane_select(m.hit, FR_RAY_HIT, FR_RAY_MISS)));
    }
    /* A ray that starts on the wrong side of the surface for its march (a refraction's or a
     * reflection's origin pushed through a thin wall, or off a normal estimated at the pixel's
     * scale): with glass, it is on the other side of the glass's surface, and marches again from
     * there in the other mode; without, it is inside an opaque solid, where no light reaches. */
    const mask_t wrong_side = fc->transmission > 0.0f ? active & m.inside : FR_MASK_FALSE;
    in_glass ^= wrong_side;
    active = hit | wrong_side;
    if (!any_lane(active)) break;
    if (!any_lane(hit)) continue;

    const vec3_t p = v3_mad(ray.origin, ray.dir, m.t);
    const real_t h = hit_threshold(fc, path_t + m.t, p);
    /* Normals at the scale of the pixel's footprint, as render.cl takes them. */
    const real_t normal_h = fmax(h, (real_t)(0.5f * fc->pixel_angle_rad) * (path_t + m.t));
    const vec3_t gradient = calc_normal(p, normal_h, params);
    FR_COUNT(FR_COUNT_NORMALS, hit, FR_NORMAL_EVALS);
    vec3_t n = v3_select(v3_length2(gradient) > (real_t)0, v3_normalize(gradient),
                         v3_neg(ray.dir));
    /* A normal that faces away from the ray (estimated across a thin feature): the side the ray
     * came from, so that bounces and lights stay on it. */
    n = v3_select(v3_dot(n, ray.dir) > (real_t)0, v3_neg(n), n);
    const surface_t surface = surface_at(p);
    FR_COUNT(FR_COUNT_SURFACE, hit, FR_HAS_SURFACE);
    /* Energy-conserving: an albedo above 1 would create light. */
    const vec3_t albedo = v3_min(v3_max(surface.albedo, v3s(0, 0, 0)), v3s(1, 1, 1));
    /* The lobes' odds at a hit from outside: mirror (the reflectivity), glass (that much of the
     * rest, render.transmission), diffuse (what is left). From inside the glass: its surface. */
    const real_t mirror_chance =
        lane_select(in_glass, 0, clamp(surface.reflectivity, (real_t)0, (real_t)1));
    const real_t glass_chance =
        lane_select(in_glass, 1, ((real_t)1 - mirror_chance) * (real_t)fc->transmission);
    const real_t diffuse_share = (real_t)1 - mirror_chance - glass_chance;
    /* Light the surface gives off (seen from outside), found by the path like the sky. */
    if (fc->emission > 0.0f)
      radiance = v3_add(radiance, v3_select(hit & !in_glass,
                                            v3_scale(v3_mul(throughput, albedo),
                                                     (real_t)fc->emission),
                                            v3s(0, 0, 0)));
    if (k == 0) {
      out.normal = v3_select(hit, n, out.normal);
      out.albedo = v3_select(hit, albedo, out.albedo);
    }

    /* Next-event estimation through the diffuse part: each light, if nothing is in the way. */
    light_sample_t lights[FR_MAX_LIGHTS];
    mask_t facing[FR_MAX_LIGHTS];
    real_t visible[FR_MAX_LIGHTS];
    const int count = min(fc->light_count, FR_MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
      lights[i] = sample_light(i, p, fc);
      facing[i] = hit & (diffuse_share > (real_t)0) & (v3_dot(n, lights[i].to_light) > (real_t)0);
      visible[i] = (real_t)1;
    }
    FR_APPLY_SHADOWS(visible, p, n, h, lights, facing, count, shadow_steps);
    vec3_t direct = v3s(0, 0, 0);
    for (int i = 0; i < count; ++i) {
      if (!any_lane(facing[i])) continue;
      const real_t cos_l = v3_dot(n, lights[i].to_light);
      direct = v3_add(direct,
                      v3_scale(lights[i].radiance, lane_select(facing[i], visible[i] * cos_l, 0)));
    }
    const vec3_t diffuse_weight = v3_scale(v3_mul(throughput, albedo), diffuse_share);
    radiance = v3_add(radiance, v3_select(hit, v3_mul(diffuse_weight, direct), v3s(0, 0, 0)));
    if (k == fc->path_max_bounces) break;

    /* The next interaction, chosen with the lobes' odds. */
    const real_t u_lobe = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 0));
    const real_t u1 = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 1));
    const real_t u2 = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 2));
    const real_t u_fresnel = pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 3));
    const mask_t mirror = u_lobe < mirror_chance;
    const mask_t glass = !mirror & (u_lobe < mirror_chance + glass_chance);
    /* The glass's surface (a dielectric): reflected with the Fresnel reflectance F (unpolarised,
     * exact; 1 beyond the critical angle), else refracted by Snell's law. n faces the ray, so
     * eta is the index the ray leaves over the one it enters. */
    const real_t eta = lane_select(in_glass, (real_t)fc->ior, (real_t)1 / (real_t)fc->ior);
    const real_t cos_i = fmin(-v3_dot(ray.dir, n), (real_t)1);
    const real_t sin2_t = eta * eta * fmax((real_t)1 - cos_i * cos_i, (real_t)0);
    const real_t cos_t = sqrt(fmax((real_t)1 - sin2_t, (real_t)0));
    const real_t r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const real_t r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const real_t fresnel = lane_select(sin2_t >= (real_t)1, 1, (real_t)0.5 * (r_s * r_s + r_p * r_p));
    const mask_t refract = hit & glass & (u_fresnel >= fresnel);
    const vec3_t mirrored = v3_mad(ray.dir, n, -2 * v3_dot(ray.dir, n));
    const vec3_t refracted = v3_normalize(v3_mad(v3_scale(ray.dir, eta), n, eta * cos_i - cos_t));
    const vec3_t next_dir = v3_select(
        refract, refracted, v3_select(mirror | glass, mirrored, cosine_direction(n, u1, u2)));
    /* Off the surface on the side the ray goes: through it when refracted. (Only where the ray
     * hit: one on the wrong side keeps its ray for the other march.) */
    ray.origin = v3_select(hit, v3_mad(p, n, lane_select(refract, -2 * h, 2 * h)), ray.origin);
    ray.dir = v3_select(hit, next_dir, ray.dir);
    /* Entering: the glass absorbs the complement of the surface's colour. */
    const mask_t entering = refract & !in_glass;
    sigma = v3_select(entering, v3_scale(v3_sub(v3s(1, 1, 1), albedo), (real_t)fc->absorption),
                      sigma);
    in_glass ^= refract;
    /* Diffuse: the albedo (cosine-weighted sampling); mirror and glass: the lobe's odds equal its
     * weight, nothing changes. */
    throughput = v3_select(mirror | glass | !hit, throughput, v3_mul(throughput, albedo));
    if (k >= 2) {
      const real_t q = clamp(fmax(throughput.x, fmax(throughput.y, throughput.z)), (real_t)0.05,
                             (real_t)1);
      active &= pixel_random(fc, ix, iy, FR_PATH_STREAM(k, 4)) < q;
      throughput = v3_scale(throughput, (real_t)1 / q);
    }
    path_t += m.t;
  }

  FR_COUNTS_END(counts_out);
  out.color = radiance;
  film_write(tile_x, tile_y, out, fc, hdr_rgba, depth, steps_out, factors_out, status_out,
             normal_out, albedo_out);
}
