/* area_lights.cl — path tracing's lights with a size (fr_light.radius): a point light is a sphere
 * that glows evenly, a directional light a disc in the sky (the sun). Each is seen from a point p
 * as a cone of directions of half-angle theta_max, with sin^2(theta_max) = r^2 / d^2 for a sphere
 * of radius r at distance d, and theta_max = the angular radius for a disc.
 *
 * Radiance: a light means what it means to the fast integrator (lights.cl): what a white
 * Lambertian surface facing it reflects, its colour times its falloff, C. A uniformly bright cone
 * of radiance L gives such a surface the irradiance L pi sin^2(theta_max), which reflects
 * L sin^2(theta_max); so L = C / sin^2(theta_max), and a light's size changes its shadows and
 * highlights, not how bright it makes what it lights.
 *
 * Next-event estimation samples the cone uniformly (density 1 / (2 pi (1 - cos theta_max)) per
 * solid angle); a bounce that happens to hit the light finds it too, and the two are weighted by
 * the power heuristic (Veach and Guibas 1995) so that nothing is counted twice. A light of size
 * 0 keeps lights.cl's point or direction, found only by the estimation. */

typedef struct light_cone_t {
  vec3_t axis;          /* unit, from p to the light's centre (or towards the sun) */
  real_t centre_t;      /* distance to the centre; FR_SCALAR_MAX for a directional light */
  real_t one_minus_cos; /* 1 - cos(theta_max); 0 where p is inside the light */
  vec3_t radiance;      /* L */
} light_cone_t;

/* 1 - sqrt(1 - s2) without cancellation for small s2. */
inline real_t one_minus_sqrt_one_minus(real_t s2) {
  return s2 / ((real_t)1 + sqrt(fmax((real_t)1 - s2, (real_t)0)));
}

/* Light i (of radius > 0) as seen from p. */
inline light_cone_t light_cone(int i, vec3_t p, __constant const fr_frame_constants* fc) {
  const light_sample_t centre = sample_light(i, p, fc);
  const scalar_t radius = (scalar_t)fc->light_radius[i];
  light_cone_t c;
  c.axis = centre.to_light;
  c.centre_t = centre.distance;
  real_t sin2;
  if (fc->light_kind[i] == FR_KERNEL_LIGHT_DIRECTIONAL) {
    sin2 = (real_t)(sin(radius) * sin(radius));
  } else {
    sin2 = (real_t)(radius * radius) / fmax(centre.distance * centre.distance, (real_t)FR_SCALAR_MIN);
    /* Inside the sphere: it is not seen as a light (and lights nothing). */
    sin2 = lane_select(sin2 < (real_t)1, sin2, 0);
  }
  c.one_minus_cos = one_minus_sqrt_one_minus(sin2);
  c.radiance = v3_scale(centre.radiance,
                        lane_select(sin2 > (real_t)0, (real_t)1 / fmax(sin2, (real_t)FR_SCALAR_MIN), 0));
  return c;
}

/* Density per solid angle of light_cone_sample's directions (0 where the light is not seen). */
inline real_t light_cone_pdf(light_cone_t c) {
  return lane_select(c.one_minus_cos > (real_t)0,
                     (real_t)(0.5 * M_1_PI_F) / fmax(c.one_minus_cos, (real_t)FR_SCALAR_MIN), 0);
}

/* A direction uniform in the cone, as a light_sample_t: its radiance field is L / (pi pdf), what
 * a white Lambertian facing the direction reflects per cos (lights.cl's unit), and its distance
 * is where the direction meets the sphere (FR_SCALAR_MAX for a sun). */
inline light_sample_t light_cone_sample(light_cone_t c, scalar_t radius, int directional,
                                        real_t u1, real_t u2) {
  const real_t one_minus_cos = u1 * c.one_minus_cos;
  const real_t cos_theta = (real_t)1 - one_minus_cos;
  const real_t sin_theta = sqrt(fmax(one_minus_cos * ((real_t)2 - one_minus_cos), (real_t)0));
  light_sample_t s;
  s.to_light = around(c.axis, cos_theta, sin_theta, (real_t)(2 * M_PI_F) * u2);
  if (directional) {
    s.distance = (real_t)FR_SCALAR_MAX;
  } else {
    const real_t b = c.centre_t * cos_theta;
    const real_t disc = b * b - (c.centre_t * c.centre_t - (real_t)(radius * radius));
    s.distance = fmax(b - sqrt(fmax(disc, (real_t)0)), (real_t)0);
  }
  s.radiance = v3_scale(c.radiance, 2 * c.one_minus_cos);
  return s;
}

/* Where the ray from o along the unit d meets light i's sphere (FR_SCALAR_MAX where it does not;
 * a sun is met by every ray that escapes within its disc, at FR_SCALAR_MAX). */
inline mask_t light_hit(light_cone_t c, vec3_t d, int directional, scalar_t radius,
                        real_t* t_hit) {
  const real_t cos_d = v3_dot(d, c.axis);
  const real_t cos_max = (real_t)1 - c.one_minus_cos;
  const mask_t within = (c.one_minus_cos > (real_t)0) & (cos_d >= cos_max);
  if (directional) {
    *t_hit = (real_t)FR_SCALAR_MAX;
    return within;
  }
  const real_t b = c.centre_t * cos_d;
  const real_t disc = b * b - (c.centre_t * c.centre_t - (real_t)(radius * radius));
  *t_hit = b - sqrt(fmax(disc, (real_t)0));
  return within & (b > (real_t)0);
}

/* The power heuristic's weight of a strategy of density a against one of density b. */
inline real_t power_heuristic(real_t a, real_t b) {
  const real_t a2 = a * a, b2 = b * b;
  return lane_select(a2 + b2 > (real_t)0, a2 / fmax(a2 + b2, (real_t)FR_SCALAR_MIN), 0);
}
