/* prelude.cl — lane-generic types and helpers that every scene DE and renderer stage uses.
 *
 * The host defines, before this file:
 *   FR_LANES   1, 4, 8, 16, 32 or 64: rays evaluated together by one work-item (a tile of
 *              pixels); 32 and 64 from wide_lanes.cl, which the host appends before this file
 *   FR_DOUBLE  0 or 1: scalar precision
 * Code written with these types builds at every width. Rules (sdk/docs/writing-a-scene.md):
 *   - real_t is one value per lane; scalar_t is one value shared by all lanes.
 *   - a comparison of real_t gives mask_t; combine masks with & | ! only.
 *   - a branch on a per-lane value becomes lane_select(mask, if_true, if_false);
 *     a loop exit tests any_lane(mask) or all_lanes(mask).
 *   - math built-ins (sqrt, log, pow, atan2, ...) take real_t; pass to_real(x) for constants. */

/* The DE helper library's version (kernels/de/, #include "fr/..."): 10000 major + 100 minor +
 * patch. A scene may test it: #if FR_DE_LIBRARY_VERSION < 10000 ... #endif. */
#define FR_DE_LIBRARY_VERSION 10000

#if FR_DOUBLE
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double scalar_t;
#define FR_SCALAR_EPSILON DBL_EPSILON
#define FR_SCALAR_MAX DBL_MAX
#define FR_SCALAR_MIN DBL_MIN
#else
typedef float scalar_t;
#define FR_SCALAR_EPSILON FLT_EPSILON
#define FR_SCALAR_MAX FLT_MAX
#define FR_SCALAR_MIN FLT_MIN
#endif
/* How finely the estimate tells positions apart, relative to |p|: a scalar's ulp, or a pair's
 * (2^-104) in a double-double kernel (FR_DD: render.precision "dd", dd_relative.cl). */
#if FR_DD
#define FR_POSITION_EPSILON 4.930380657631324e-32
#else
#define FR_POSITION_EPSILON FR_SCALAR_EPSILON
#endif

#define FR_CAT_(a, b) a##b
#define FR_CAT(a, b) FR_CAT_(a, b)

#if FR_LANES == 1
typedef scalar_t real_t;
typedef int mask_t; /* scalar comparisons give 0 or 1 */
#define FR_TILE_W 1
#define FR_TILE_H 1
#define FR_LANE_X ((real_t)0)
#define FR_LANE_Y ((real_t)0)
#define any_lane(m) ((m) != 0)
#define all_lanes(m) ((m) != 0)
#define lane_select(m, if_true, if_false) ((m) ? (real_t)(if_true) : (real_t)(if_false))
#define FR_MASK_TRUE 1
#else
#if FR_LANES >= 32
typedef fr_wide_real_t real_t; /* wide_lanes.cl */
typedef fr_wide_mask_t mask_t;
#elif FR_DOUBLE
typedef FR_CAT(double, FR_LANES) real_t;
typedef FR_CAT(long, FR_LANES) mask_t; /* vector comparisons give -1 (true) or 0 */
#else
typedef FR_CAT(float, FR_LANES) real_t;
typedef FR_CAT(int, FR_LANES) mask_t;
#endif
#define any_lane(m) any(m)
#define all_lanes(m) all(m)
#define lane_select(m, if_true, if_false) select((real_t)(if_false), (real_t)(if_true), (m))
#define FR_MASK_TRUE ((mask_t)(-1))
#if FR_LANES == 4
#define FR_TILE_W 2
#define FR_TILE_H 2
#define FR_LANE_X ((real_t)(0, 1, 0, 1))
#define FR_LANE_Y ((real_t)(0, 0, 1, 1))
#elif FR_LANES == 8
#define FR_TILE_W 4
#define FR_TILE_H 2
#define FR_LANE_X ((real_t)(0, 1, 2, 3, 0, 1, 2, 3))
#define FR_LANE_Y ((real_t)(0, 0, 0, 0, 1, 1, 1, 1))
#elif FR_LANES == 16
#define FR_TILE_W 4
#define FR_TILE_H 4
#define FR_LANE_X ((real_t)(0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3))
#define FR_LANE_Y ((real_t)(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3))
#elif FR_LANES == 32
#define FR_TILE_W 8
#define FR_TILE_H 4
#define FR_LANE_X \
  ((real_t)(0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7,  \
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7))
#define FR_LANE_Y \
  ((real_t)(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1,  \
    2, 2, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 3))
#elif FR_LANES == 64
#define FR_TILE_W 8
#define FR_TILE_H 8
#define FR_LANE_X \
  ((real_t)(0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7,  \
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7,  \
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7,  \
    0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7))
#define FR_LANE_Y \
  ((real_t)(0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1,  \
    2, 2, 2, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, 3,  \
    4, 4, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5, 5, 5,  \
    6, 6, 6, 6, 6, 6, 6, 6, 7, 7, 7, 7, 7, 7, 7, 7))
#else
#error "FR_LANES must be 1, 4, 8, 16, 32 or 64"
#endif
#endif

#define FR_MASK_FALSE ((mask_t)0)

/* Per-lane unsigned integers, for hashing pixels into random numbers. */
#if FR_LANES == 1
typedef uint lane_uint_t;
#define FR_LANE_SUFFIX
#elif FR_LANES >= 32
typedef fr_wide_uint_t lane_uint_t;
#else
typedef FR_CAT(uint, FR_LANES) lane_uint_t;
#define FR_LANE_SUFFIX FR_LANES
#endif
#if FR_LANES >= 32
#define real_to_uint(x) fr_wide_to_uint(x)
#define uint_to_real(x) fr_wide_from_uint(x)
#else
#define real_to_uint(x) FR_CAT(convert_uint, FR_LANE_SUFFIX)(x)
#if FR_DOUBLE
#define uint_to_real(x) FR_CAT(convert_double, FR_LANE_SUFFIX)(x)
#else
#define uint_to_real(x) FR_CAT(convert_float, FR_LANE_SUFFIX)(x)
#endif
#endif
#define to_real(x) ((real_t)(x))
#define mask_to_real(m) lane_select((m), 1, 0)

/* Moving lanes to and from private float arrays of FR_LANES elements (one per lane), for
 * gathering inputs and scattering results to pixels. */
#if FR_LANES == 1
inline void store_lanes(real_t v, float* out) { out[0] = (float)v; }
inline real_t load_lanes(const float* in) { return (real_t)in[0]; }
#elif FR_LANES >= 32
inline void store_lanes(real_t v, float* out) { fr_wide_store(v, out); }
inline real_t load_lanes(const float* in) { return fr_wide_load(in); }
#elif FR_DOUBLE
inline void store_lanes(real_t v, float* out) {
  FR_CAT(vstore, FR_LANES)(FR_CAT(convert_float, FR_LANES)(v), 0, out);
}
inline real_t load_lanes(const float* in) {
  return FR_CAT(convert_double, FR_LANES)(FR_CAT(vload, FR_LANES)(0, in));
}
#else
inline void store_lanes(real_t v, float* out) { FR_CAT(vstore, FR_LANES)(v, 0, out); }
inline real_t load_lanes(const float* in) { return FR_CAT(vload, FR_LANES)(0, in); }
#endif

/* Three real_t: one 3-vector per lane. */
typedef struct vec3_t {
  real_t x, y, z;
} vec3_t;

inline vec3_t v3(real_t x, real_t y, real_t z) {
  vec3_t r;
  r.x = x;
  r.y = y;
  r.z = z;
  return r;
}
/* The same vector in every lane. */
inline vec3_t v3s(scalar_t x, scalar_t y, scalar_t z) { return v3((real_t)x, (real_t)y, (real_t)z); }
inline vec3_t v3_from_float4(__constant const float* f) { return v3s(f[0], f[1], f[2]); }
inline vec3_t v3_add(vec3_t a, vec3_t b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3_t v3_sub(vec3_t a, vec3_t b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline vec3_t v3_mul(vec3_t a, vec3_t b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
inline vec3_t v3_scale(vec3_t a, real_t s) { return v3(a.x * s, a.y * s, a.z * s); }
inline vec3_t v3_neg(vec3_t a) { return v3(-a.x, -a.y, -a.z); }
inline vec3_t v3_abs(vec3_t a) { return v3(fabs(a.x), fabs(a.y), fabs(a.z)); }
inline vec3_t v3_min(vec3_t a, vec3_t b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
inline vec3_t v3_max(vec3_t a, vec3_t b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }
inline real_t v3_dot(vec3_t a, vec3_t b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline real_t v3_length2(vec3_t a) { return v3_dot(a, a); }
inline real_t v3_length(vec3_t a) { return sqrt(v3_dot(a, a)); }
inline vec3_t v3_cross(vec3_t a, vec3_t b) {
  return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* Unit vector; a zero vector stays zero instead of becoming NaN. */
inline vec3_t v3_normalize(vec3_t a) {
  real_t len = v3_length(a);
  real_t inv = lane_select(len > (real_t)0, (real_t)1 / len, (real_t)0);
  return v3_scale(a, inv);
}
/* Per lane: if_true where m is set, else if_false. */
inline vec3_t v3_select(mask_t m, vec3_t if_true, vec3_t if_false) {
  return v3(lane_select(m, if_true.x, if_false.x), lane_select(m, if_true.y, if_false.y),
            lane_select(m, if_true.z, if_false.z));
}
/* a + b * s: a ray point, a blend step. */
inline vec3_t v3_mad(vec3_t a, vec3_t b, real_t s) {
  return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}

/* Sine and cosine for DE inner loops. In float: the device's native_sin/native_cos after reducing
 * the angle to [-pi, pi], the range where native accuracy is meant (on PoCL this is about 1.4x
 * faster per Mandelbulb frame than the correctly rounded built-ins). In double: the full-precision
 * built-ins, since the double build is the reference the float build is measured against. */
#if FR_DOUBLE
#define fast_sin(x) sin(x)
#define fast_cos(x) cos(x)
#else
inline real_t wrap_angle(real_t a) {
  return a - (real_t)(2.0f * M_PI_F) * rint(a * (real_t)(0.5f * M_1_PI_F));
}
inline real_t fast_sin(real_t a) { return native_sin(wrap_angle(a)); }
inline real_t fast_cos(real_t a) { return native_cos(wrap_angle(a)); }
#endif

/* x^y for x >= 0, as exp2(y log2 x) with x kept above the smallest normal (so 0^y is tiny, not
 * NaN, and x^0 is 1). Use it instead of pow: on PoCL pow's extra-precise path cost half of a
 * Mandelbulb frame, and PoCL 3.1's double16 pow returned +inf for some bases in (0, 1). */
inline real_t pow_nonneg(real_t x, real_t y) {
  return exp2(y * log2(fmax(x, (real_t)FR_SCALAR_MIN)));
}

/* x^n for a whole n >= 0 and one value for all lanes, by repeated squaring (within a few ulp of
 * the exact power). Use it instead of pown for per-evaluation scale factors such as a fold's
 * scale^-iterations: PoCL's pown and pow take an extra-precise path that, called once per DE
 * evaluation, was 40% of the benchmark scene's frame. */
inline scalar_t pown_scalar(scalar_t x, int n) {
  scalar_t result = 1;
  for (; n > 0; n >>= 1) {
    if (n & 1) result *= x;
    x *= x;
  }
  return result;
}

/* What a scene's surface source returns for a surface point: linear albedo and the fraction of
 * light mirrored (used when reflections are on). */
typedef struct surface_t {
  vec3_t albedo;
  real_t reflectivity;
} surface_t;

/* What a scene's material function may return for a surface point (path tracing; path.cl and
 * material.cl say what each field does). A scene's surface source may define
 *   material_t scene_material(vec3_t p, material_t m, __constant const scene_params_t* params);
 * which receives the default material at p (from its surface colour and the render settings)
 * and returns it changed. Values outside the ranges below are clamped to them. */
typedef struct material_t {
  vec3_t base_color;       /* [0, 1]: the diffuse albedo, a metal's reflectance, glass's tint */
  real_t specular;         /* [0, 1]: the share mirrored by a clear coat (surface_t.reflectivity) */
  real_t roughness;        /* [0, 1]: of the coat, metal and glass; 0 polished (GGX alpha: its square) */
  real_t metalness;        /* [0, 1]: the share that is metal */
  real_t transmission;     /* [0, 1]: of the light neither mirrored nor metal, the share entering glass */
  real_t ior;              /* [1, 4]: the glass's index of refraction */
  vec3_t absorption;       /* >= 0: the glass's absorption per world unit, per channel */
  real_t subsurface;       /* [0, 1]: of the diffuse light, the share that scatters under the surface */
  vec3_t subsurface_color; /* [0, 1]: what the scattering medium reflects overall */
  real_t mean_free_path;   /* > 0: world units between scatterings in it */
  vec3_t emission;         /* >= 0: radiance the surface gives off */
} material_t;

/* A well-mixed 32-bit hash (Wellons' lowbias32). */
inline lane_uint_t hash_uint(lane_uint_t h) {
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

/* Uniform in [0, 1), different for every pixel, sample and stream. */
inline real_t random_unit(lane_uint_t x, lane_uint_t y, uint sample, uint stream) {
  lane_uint_t h = hash_uint(x * 1973U + hash_uint(y * 9277U + hash_uint(sample * 26699U + stream)));
  return uint_to_real(h >> 8) * (real_t)(1.0 / 16777216.0);
}

/* a + (b - a) t, per lane. */
inline vec3_t v3_mix(vec3_t a, vec3_t b, real_t t) { return v3_mad(a, v3_sub(b, a), t); }
