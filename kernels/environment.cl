/* environment.cl — the sky as an equirectangular HDR panorama (render.environment), pasted in
 * only when one is set. Both integrators see it where a ray leaves the scene (FR_SKY); the path
 * tracer also samples it by next-event estimation, in proportion to its brightness, so that a
 * small bright sun in the image lights the scene without the noise of finding it by chance.
 *
 * The panorama's frame (frame_constants.h, env_axes): y is its zenith (the camera's up vector),
 * x and z span its horizon, turned by render.environment_rotation_deg. A direction at polar angle
 * theta from y and azimuth phi = atan2(z, x) is the image point (u, v) = (phi / 2 pi, theta / pi)
 * of [0, 1)^2: the top row is the zenith, u wraps around.
 *
 * The buffer `environment` (renderer.cpp; host/render/environment_map.hpp): the image's RGB (3
 * floats a pixel, rows top to bottom); then a distribution over the bilinear patches between
 * pixel centres (width of them a row, height + 1 rows: the first and last are half patches up to
 * the poles): the patch rows' cumulative distribution (height + 2 floats, 0 to 1) and each patch
 * row's over its patches (height + 1 rows of width + 1 floats). A patch's weight is the light it
 * sends (its mean luminance times its solid angle). Inside the chosen patch the direction is drawn
 * in proportion to the bilinear luminance itself (the lookup is bilinear between pixel centres),
 * so the density follows what the eye sees: a sun a few pixels wide is found at nearly every
 * draw, with little noise from the interpolation around it. Multiple importance sampling covers
 * the rest (a patch of four black corners is never drawn, and sends nothing). */

#define FR_ENV_RGB(x, y) (environment + 3 * ((y) * fc->env_width + (x)))
#define FR_ENV_ROWS (environment + 3 * fc->env_width * fc->env_height)
#define FR_ENV_ROW(y) (FR_ENV_ROWS + fc->env_height + 2 + (y) * (fc->env_width + 1))

/* Where direction d falls in the panorama, in [0, 1)^2 (v: 0 at the zenith). */
inline void environment_uv(vec3_t d, __constant const fr_frame_constants* fc, real_t* u,
                           real_t* v) {
  const real_t x = v3_dot(d, v3_from_float4(fc->env_axes[0]));
  const real_t y = v3_dot(d, v3_from_float4(fc->env_axes[1]));
  const real_t z = v3_dot(d, v3_from_float4(fc->env_axes[2]));
  const real_t phi = atan2(z, x); /* (-pi, pi] */
  *u = phi * (real_t)(0.5 * M_1_PI_F) + lane_select(phi < (real_t)0, 1, 0);
  *v = acos(clamp(y, (real_t)-1, (real_t)1)) * (real_t)M_1_PI_F;
}

/* One pixel's radiance (its row clamped, its column wrapped) scaled by the intensity. */
inline void environment_texel(__global const float* environment,
                              __constant const fr_frame_constants* fc, int x, int y, float w,
                              float* rgb) {
  const int width = fc->env_width, height = fc->env_height;
  x = x < 0 ? x + width : (x >= width ? x - width : x);
  y = clamp(y, 0, height - 1);
  __global const float* t = FR_ENV_RGB(x, y);
  rgb[0] += w * t[0];
  rgb[1] += w * t[1];
  rgb[2] += w * t[2];
}

/* The panorama's radiance towards unit direction d, bilinear between pixel centres. */
vec3_t environment_radiance(vec3_t d, __constant const fr_frame_constants* fc,
                            __global const float* environment) {
  real_t u, v;
  environment_uv(d, fc, &u, &v);
  float us[FR_LANES], vs[FR_LANES], r[FR_LANES], g[FR_LANES], b[FR_LANES];
  store_lanes(u, us);
  store_lanes(v, vs);
  for (int i = 0; i < FR_LANES; ++i) {
    const float fx = us[i] * (float)fc->env_width - 0.5f, fy = vs[i] * (float)fc->env_height - 0.5f;
    const float x0 = floor(fx), y0 = floor(fy);
    const float ax = fx - x0, ay = fy - y0;
    float rgb[3] = {0.0f, 0.0f, 0.0f};
    environment_texel(environment, fc, (int)x0, (int)y0, (1 - ax) * (1 - ay), rgb);
    environment_texel(environment, fc, (int)x0 + 1, (int)y0, ax * (1 - ay), rgb);
    environment_texel(environment, fc, (int)x0, (int)y0 + 1, (1 - ax) * ay, rgb);
    environment_texel(environment, fc, (int)x0 + 1, (int)y0 + 1, ax * ay, rgb);
    r[i] = rgb[0] * fc->env_intensity;
    g[i] = rgb[1] * fc->env_intensity;
    b[i] = rgb[2] * fc->env_intensity;
  }
  return v3(load_lanes(r), load_lanes(g), load_lanes(b));
}

/* The luminance of pixel (x, y), its column wrapped and its row clamped. */
inline float environment_luminance(__global const float* environment,
                                   __constant const fr_frame_constants* fc, int x, int y) {
  const int width = fc->env_width, height = fc->env_height;
  x = x < 0 ? x + width : (x >= width ? x - width : x);
  y = clamp(y, 0, height - 1);
  __global const float* t = FR_ENV_RGB(x, y);
  return 0.2126f * t[0] + 0.7152f * t[1] + 0.0722f * t[2];
}

/* Patch (column pc, row pr)'s corner luminances: c[0] (pc, top), c[1] (pc + 1, top), c[2] (pc,
 * bottom), c[3] (pc + 1, bottom). Patch row pr lies between pixel rows pr - 1 and pr. */
inline void environment_corners(__global const float* environment,
                                __constant const fr_frame_constants* fc, int pc, int pr,
                                float* c) {
  c[0] = environment_luminance(environment, fc, pc, pr - 1);
  c[1] = environment_luminance(environment, fc, pc + 1, pr - 1);
  c[2] = environment_luminance(environment, fc, pc, pr);
  c[3] = environment_luminance(environment, fc, pc + 1, pr);
}

/* The bilinear density on the unit square with corner values c (uniform where all four are 0:
 * a black panorama is drawn by solid angle, and sends nothing wherever it is drawn), at (s, t). */
inline float bilinear_density(const float* c, float s, float t) {
  const float mean = 0.25f * (c[0] + c[1] + c[2] + c[3]);
  const float value = (1 - t) * ((1 - s) * c[0] + s * c[1]) + t * ((1 - s) * c[2] + s * c[3]);
  return mean > 0.0f ? value / mean : 1.0f;
}

/* u uniform in [0, 1) to x in [0, 1] with density proportional to (1 - x) a + x b (a, b >= 0). */
inline float sample_linear(float u, float a, float b) {
  if (!(a + b > 0.0f) || fabs(a - b) <= 1e-6f * (a + b)) return u;
  const float x = u * (a + b) / (a + sqrt(fmax((1 - u) * a * a + u * b * b, 0.0f)));
  return clamp(x, 0.0f, 0.99999994f);
}

/* The density per solid angle of drawing the image point (u, v) from patch (pc, pr) at (s, t). */
inline float environment_density(__global const float* environment,
                                 __constant const fr_frame_constants* fc, int pc, int pr, float s,
                                 float t, float v) {
  const int width = fc->env_width, height = fc->env_height;
  const float row = FR_ENV_ROWS[pr + 1] - FR_ENV_ROWS[pr];
  const float column = FR_ENV_ROW(pr)[pc + 1] - FR_ENV_ROW(pr)[pc];
  float c[4];
  environment_corners(environment, fc, pc, pr, c);
  /* The patch's share of the image: a whole pixel's, or half of one at the poles. */
  const float area = (pr == 0 || pr == height ? 0.5f : 1.0f) / (float)(width * height);
  const float sin_theta = sin(v * M_PI_F);
  return sin_theta > 0.0f
             ? row * column * bilinear_density(c, s, t) / (area * 2.0f * M_PI_F * M_PI_F * sin_theta)
             : 0.0f;
}

/* The density per solid angle with which environment_sample draws direction d. */
real_t environment_pdf(vec3_t d, __constant const fr_frame_constants* fc,
                       __global const float* environment) {
  real_t u, v;
  environment_uv(d, fc, &u, &v);
  float us[FR_LANES], vs[FR_LANES], p[FR_LANES];
  store_lanes(u, us);
  store_lanes(v, vs);
  const int width = fc->env_width, height = fc->env_height;
  for (int i = 0; i < FR_LANES; ++i) {
    const float fx = us[i] * (float)width - 0.5f, fy = vs[i] * (float)height - 0.5f;
    const float x0 = floor(fx);
    int pc = (int)x0;
    pc = pc < 0 ? pc + width : (pc >= width ? pc - width : pc);
    const float s = clamp(fx - x0, 0.0f, 1.0f);
    int pr;
    float t;
    if (fy < 0.0f) {
      pr = 0;
      t = clamp(2.0f * vs[i] * (float)height, 0.0f, 1.0f);
    } else if (fy >= (float)(height - 1)) {
      pr = height;
      t = clamp(2.0f * (fy - (float)(height - 1)), 0.0f, 1.0f);
    } else {
      const float y0 = floor(fy);
      pr = (int)y0 + 1;
      t = fy - y0;
    }
    p[i] = environment_density(environment, fc, pc, pr, s, t, vs[i]);
  }
  return load_lanes(p);
}

/* The first index i in [0, n) with cdf[i + 1] > u (cdf[0] = 0 <= u < 1 = cdf[n]). */
inline int environment_find(__global const float* cdf, int n, float u) {
  int lo = 0, hi = n - 1;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (cdf[mid + 1] > u)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

/* A direction drawn in proportion to the panorama's light (u1, u2 uniform in [0, 1)), as a
 * light_sample_t in lights.cl's unit (radiance / (pi pdf): what a white Lambertian surface facing
 * it reflects per cos), and its density per solid angle in *pdf. */
light_sample_t environment_sample(real_t u1, real_t u2, __constant const fr_frame_constants* fc,
                                  __global const float* environment, real_t* pdf) {
  float a[FR_LANES], b[FR_LANES], us[FR_LANES], vs[FR_LANES], p[FR_LANES];
  store_lanes(u1, a);
  store_lanes(u2, b);
  const int width = fc->env_width, height = fc->env_height;
  for (int i = 0; i < FR_LANES; ++i) {
    const int pr = environment_find(FR_ENV_ROWS, height + 1, a[i]);
    const float row_lo = FR_ENV_ROWS[pr], row = FR_ENV_ROWS[pr + 1] - row_lo;
    const int pc = environment_find(FR_ENV_ROW(pr), width, b[i]);
    const float col_lo = FR_ENV_ROW(pr)[pc], column = FR_ENV_ROW(pr)[pc + 1] - col_lo;
    /* What is left of each number, rescaled to [0, 1), places the point in the patch: t down by
     * the top and bottom edges' sums, then s across by the row t's ends. */
    const float ut = row > 0.0f ? clamp((a[i] - row_lo) / row, 0.0f, 0.99999994f) : 0.5f;
    const float uc = column > 0.0f ? clamp((b[i] - col_lo) / column, 0.0f, 0.99999994f) : 0.5f;
    float c[4];
    environment_corners(environment, fc, pc, pr, c);
    const float t = sample_linear(ut, c[0] + c[1], c[2] + c[3]);
    const float s = sample_linear(uc, (1 - t) * c[0] + t * c[2], (1 - t) * c[1] + t * c[3]);
    float x = (float)pc + 0.5f + s;
    if (x >= (float)width) x -= (float)width;
    const float y = pr == 0 ? 0.5f * t
                            : (pr == height ? (float)height - 0.5f + 0.5f * t
                                            : (float)pr - 0.5f + t);
    us[i] = x / (float)width;
    vs[i] = y / (float)height;
    p[i] = environment_density(environment, fc, pc, pr, s, t, vs[i]);
  }
  const real_t u = load_lanes(us), v = load_lanes(vs);
  const real_t theta = v * (real_t)M_PI_F, phi = u * (real_t)(2 * M_PI_F);
  const real_t sin_theta = sin(theta);
  const real_t lx = sin_theta * cos(phi), ly = cos(theta), lz = sin_theta * sin(phi);
  light_sample_t s;
  s.to_light = v3_add(v3_add(v3_scale(v3_from_float4(fc->env_axes[0]), lx),
                             v3_scale(v3_from_float4(fc->env_axes[1]), ly)),
                      v3_scale(v3_from_float4(fc->env_axes[2]), lz));
  s.distance = (real_t)FR_SCALAR_MAX;
  *pdf = load_lanes(p);
  const vec3_t radiance = environment_radiance(s.to_light, fc, environment);
  s.radiance = v3_scale(radiance, lane_select(*pdf > (real_t)0,
                                              (real_t)M_1_PI_F / fmax(*pdf, (real_t)FR_SCALAR_MIN),
                                              0));
  return s;
}

/* The renderer's hooks (render.cl, path.cl): the sky a ray sees when it leaves the scene, and
 * that it can be sampled. */
#define FR_SKY(dir) environment_radiance(dir, fc, environment)
#define FR_SKY_SAMPLED 1
