/* wide_lanes.cl — 32 and 64 lanes: two or four 16-lane packets in flight per work-item.
 *
 * Why: on a CPU one ray's DE is a long chain of dependent operations (each fold waits for the one
 * before it), so a packet of 16 floats, one AVX-512 register a value, leaves the vector units
 * waiting on latency; double16, two registers a value, costs only 1.3x float16's time. A wider
 * real_t hands the core independent chains to run side by side, at the price of more lanes
 * idling while a packet's slowest ray finishes (docs/performance.md, "Four packets in flight").
 *
 * How: real_t is then Clang's ext_vector_type of FR_LANES elements. Its operators work as
 * float16's do, and LLVM splits each into 16-lane instructions. OpenCL's built-ins stop at 16
 * elements, so each built-in a scene may call on real_t is overloaded here to run on the 16-lane
 * parts and join the results. A scene calling one that is missing fails to build wide; the host
 * then builds it at 16 lanes (renderer.cpp), so a wide build never changes what a scene computes.
 * The host appends this file before prelude.cl; below 32 lanes it is empty. */
#if FR_LANES >= 32

#if FR_DOUBLE
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double fr_wide_real_t __attribute__((ext_vector_type(FR_LANES)));
typedef long fr_wide_mask_t __attribute__((ext_vector_type(FR_LANES)));
typedef double fr_wide_scalar_t;
#define fr_part_from_uint convert_double16
#define fr_part_from_float convert_double16
#define fr_part_to_float convert_float16
#define fr_part_to_int convert_int16
#define FR_WIDE_ONE_BELOW 0x1.fffffffffffffp-1
#else
typedef float fr_wide_real_t __attribute__((ext_vector_type(FR_LANES)));
typedef int fr_wide_mask_t __attribute__((ext_vector_type(FR_LANES)));
typedef float fr_wide_scalar_t;
#define fr_part_from_uint convert_float16
#define fr_part_from_float
#define fr_part_to_float
#define fr_part_to_int
#define FR_WIDE_ONE_BELOW 0x1.fffffep-1f
#endif
typedef uint fr_wide_uint_t __attribute__((ext_vector_type(FR_LANES)));

/* FR_PARTk(v): lanes 16k to 16k + 15 of v. FR_JOINn(a, b): two n-lane vectors as one. */
#define FR_PART0(v) __builtin_shufflevector((v), (v), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, \
                                            14, 15)
#define FR_PART1(v)                                                                            \
  __builtin_shufflevector((v), (v), 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, \
                          31)
#define FR_PART2(v)                                                                            \
  __builtin_shufflevector((v), (v), 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, \
                          47)
#define FR_PART3(v)                                                                            \
  __builtin_shufflevector((v), (v), 48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, \
                          63)
#define FR_JOIN16(a, b)                                                                          \
  __builtin_shufflevector((a), (b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, \
                          18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31)
#define FR_JOIN32(a, b)                                                                          \
  __builtin_shufflevector((a), (b), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, \
                          18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, \
                          36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, \
                          54, 55, 56, 57, 58, 59, 60, 61, 62, 63)

/* FR_SPLIT(f, ARGS): f on each part, the results joined; ARGS(P) is f's argument list with P
 * applied to the per-lane arguments. FR_EACH_PART(S): S(P, k) for every part k.
 * FR_JOIN_PARTS(E): the parts E(0), E(1), ... joined. */
#if FR_LANES == 32
#define FR_SPLIT(f, ARGS) FR_JOIN16(f(ARGS(FR_PART0)), f(ARGS(FR_PART1)))
#define FR_EACH_PART(S) S(FR_PART0, 0) S(FR_PART1, 1)
#define FR_JOIN_PARTS(E) FR_JOIN16(E(0), E(1))
#elif FR_LANES == 64
#define FR_SPLIT(f, ARGS)                                       \
  FR_JOIN32(FR_JOIN16(f(ARGS(FR_PART0)), f(ARGS(FR_PART1))), \
            FR_JOIN16(f(ARGS(FR_PART2)), f(ARGS(FR_PART3))))
#define FR_EACH_PART(S) S(FR_PART0, 0) S(FR_PART1, 1) S(FR_PART2, 2) S(FR_PART3, 3)
#define FR_JOIN_PARTS(E) FR_JOIN32(FR_JOIN16(E(0), E(1)), FR_JOIN16(E(2), E(3)))
#else
#error "wide lanes are 32 or 64"
#endif

#define FR_ARGS_V(P) P(x)
#define FR_ARGS_VV(P) P(x), P(y)
#define FR_ARGS_VS(P) P(x), y
#define FR_ARGS_SV(P) x, P(y)
#define FR_ARGS_VVV(P) P(x), P(y), P(z)
#define FR_ARGS_VVS(P) P(x), P(y), z
#define FR_ARGS_VSS(P) P(x), y, z
#define FR_ARGS_SSV(P) x, y, P(z)

#define FR_WIDE __attribute__((overloadable, always_inline)) inline
#define FR_WIDE_V(f) \
  FR_WIDE fr_wide_real_t f(fr_wide_real_t x) { return FR_SPLIT(f, FR_ARGS_V); }
#define FR_WIDE_VV(f) \
  FR_WIDE fr_wide_real_t f(fr_wide_real_t x, fr_wide_real_t y) { return FR_SPLIT(f, FR_ARGS_VV); }
#define FR_WIDE_VS(f)                                                 \
  FR_WIDE fr_wide_real_t f(fr_wide_real_t x, fr_wide_scalar_t y) { \
    return FR_SPLIT(f, FR_ARGS_VS);                                   \
  }
#define FR_WIDE_VVV(f)                                                                 \
  FR_WIDE fr_wide_real_t f(fr_wide_real_t x, fr_wide_real_t y, fr_wide_real_t z) { \
    return FR_SPLIT(f, FR_ARGS_VVV);                                                   \
  }
#define FR_WIDE_TEST(f) \
  FR_WIDE fr_wide_mask_t f(fr_wide_real_t x) { return FR_SPLIT(f, FR_ARGS_V); }
#define FR_WIDE_TEST2(f) \
  FR_WIDE fr_wide_mask_t f(fr_wide_real_t x, fr_wide_real_t y) { return FR_SPLIT(f, FR_ARGS_VV); }

/* OpenCL 1.2's math (6.12.2), common (6.12.4) and relational (6.12.6) built-ins on gentype that
 * take and give per-lane values only. Not here: those with an int vector argument or result
 * (frexp, ilogb, ldexp, lgamma_r, nan, pown, remquo, rootn) and the integer built-ins. */
FR_WIDE_V(acos) FR_WIDE_V(acosh) FR_WIDE_V(acospi) FR_WIDE_V(asin) FR_WIDE_V(asinh)
FR_WIDE_V(asinpi) FR_WIDE_V(atan) FR_WIDE_V(atanh) FR_WIDE_V(atanpi) FR_WIDE_V(cbrt)
FR_WIDE_V(ceil) FR_WIDE_V(cos) FR_WIDE_V(cosh) FR_WIDE_V(cospi) FR_WIDE_V(erf) FR_WIDE_V(erfc)
FR_WIDE_V(exp) FR_WIDE_V(exp2) FR_WIDE_V(exp10) FR_WIDE_V(expm1) FR_WIDE_V(fabs)
FR_WIDE_V(floor) FR_WIDE_V(lgamma) FR_WIDE_V(log) FR_WIDE_V(log2) FR_WIDE_V(log10)
FR_WIDE_V(log1p) FR_WIDE_V(logb) FR_WIDE_V(rint) FR_WIDE_V(round) FR_WIDE_V(rsqrt) FR_WIDE_V(sin)
FR_WIDE_V(sinh) FR_WIDE_V(sinpi) FR_WIDE_V(sqrt) FR_WIDE_V(tan) FR_WIDE_V(tanh) FR_WIDE_V(tanpi)
FR_WIDE_V(tgamma) FR_WIDE_V(trunc) FR_WIDE_V(degrees) FR_WIDE_V(radians) FR_WIDE_V(sign)
FR_WIDE_VV(atan2) FR_WIDE_VV(atan2pi) FR_WIDE_VV(copysign) FR_WIDE_VV(fdim) FR_WIDE_VV(fmax)
FR_WIDE_VV(fmin) FR_WIDE_VV(fmod) FR_WIDE_VV(hypot) FR_WIDE_VV(maxmag) FR_WIDE_VV(minmag)
FR_WIDE_VV(nextafter) FR_WIDE_VV(pow) FR_WIDE_VV(powr) FR_WIDE_VV(remainder) FR_WIDE_VV(max)
FR_WIDE_VV(min) FR_WIDE_VV(step)
FR_WIDE_VS(fmax) FR_WIDE_VS(fmin) FR_WIDE_VS(max) FR_WIDE_VS(min)
FR_WIDE_VVV(fma) FR_WIDE_VVV(mad) FR_WIDE_VVV(clamp) FR_WIDE_VVV(mix) FR_WIDE_VVV(smoothstep)
FR_WIDE_TEST(isfinite) FR_WIDE_TEST(isinf) FR_WIDE_TEST(isnan) FR_WIDE_TEST(isnormal)
FR_WIDE_TEST(signbit) FR_WIDE_TEST2(isequal) FR_WIDE_TEST2(isnotequal) FR_WIDE_TEST2(isgreater)
FR_WIDE_TEST2(isgreaterequal) FR_WIDE_TEST2(isless) FR_WIDE_TEST2(islessequal)
FR_WIDE_TEST2(islessgreater) FR_WIDE_TEST2(isordered) FR_WIDE_TEST2(isunordered)
FR_WIDE_VVV(bitselect)
#if !FR_DOUBLE /* the native_ and half_ built-ins are float only */
FR_WIDE_V(native_cos) FR_WIDE_V(native_exp) FR_WIDE_V(native_exp2) FR_WIDE_V(native_exp10)
FR_WIDE_V(native_log) FR_WIDE_V(native_log2) FR_WIDE_V(native_log10) FR_WIDE_V(native_recip)
FR_WIDE_V(native_rsqrt) FR_WIDE_V(native_sin) FR_WIDE_V(native_sqrt) FR_WIDE_V(native_tan)
FR_WIDE_VV(native_divide) FR_WIDE_VV(native_powr)
FR_WIDE_V(half_cos) FR_WIDE_V(half_exp) FR_WIDE_V(half_exp2) FR_WIDE_V(half_exp10)
FR_WIDE_V(half_log) FR_WIDE_V(half_log2) FR_WIDE_V(half_log10) FR_WIDE_V(half_recip)
FR_WIDE_V(half_rsqrt) FR_WIDE_V(half_sin) FR_WIDE_V(half_sqrt) FR_WIDE_V(half_tan)
FR_WIDE_VV(half_divide) FR_WIDE_VV(half_powr)
#endif

FR_WIDE fr_wide_real_t step(fr_wide_scalar_t x, fr_wide_real_t y) {
  return FR_SPLIT(step, FR_ARGS_SV);
}
FR_WIDE fr_wide_real_t clamp(fr_wide_real_t x, fr_wide_scalar_t y, fr_wide_scalar_t z) {
  return FR_SPLIT(clamp, FR_ARGS_VSS);
}
FR_WIDE fr_wide_real_t mix(fr_wide_real_t x, fr_wide_real_t y, fr_wide_scalar_t z) {
  return FR_SPLIT(mix, FR_ARGS_VVS);
}
FR_WIDE fr_wide_real_t smoothstep(fr_wide_scalar_t x, fr_wide_scalar_t y, fr_wide_real_t z) {
  return FR_SPLIT(smoothstep, FR_ARGS_SSV);
}
FR_WIDE fr_wide_real_t select(fr_wide_real_t x, fr_wide_real_t y, fr_wide_mask_t z) {
  return FR_SPLIT(select, FR_ARGS_VVV);
}
FR_WIDE fr_wide_mask_t select(fr_wide_mask_t x, fr_wide_mask_t y, fr_wide_mask_t z) {
  return FR_SPLIT(select, FR_ARGS_VVV);
}
/* The built-ins that give a second result through a pointer, from the ones above. */
FR_WIDE fr_wide_real_t fract(fr_wide_real_t x, fr_wide_real_t* whole) {
  *whole = floor(x);
  return fmin(x - *whole, (fr_wide_scalar_t)FR_WIDE_ONE_BELOW);
}
FR_WIDE fr_wide_real_t modf(fr_wide_real_t x, fr_wide_real_t* whole) {
  *whole = trunc(x);
  return copysign(select(x - *whole, (fr_wide_real_t)0, isinf(x)), x);
}
FR_WIDE fr_wide_real_t sincos(fr_wide_real_t x, fr_wide_real_t* cosine) {
  *cosine = cos(x);
  return sin(x);
}

/* A mask's parts combined, then tested as one 16-lane mask. */
#define FR_OR_PART(P, k) | P(m)
#define FR_AND_PART(P, k) & P(m)
FR_WIDE int any(fr_wide_mask_t m) { return any(FR_PART0(m) FR_EACH_PART(FR_OR_PART)); }
FR_WIDE int all(fr_wide_mask_t m) { return all(FR_PART0(m) FR_EACH_PART(FR_AND_PART)); }

/* What prelude.cl's lane helpers need: conversions, and lanes to and from float arrays. */
inline fr_wide_uint_t fr_wide_to_uint(fr_wide_real_t x) { return FR_SPLIT(convert_uint16, FR_ARGS_V); }
inline fr_wide_real_t fr_wide_from_uint(fr_wide_uint_t x) {
  return FR_SPLIT(fr_part_from_uint, FR_ARGS_V);
}
#define FR_STORE_PART(P, k) vstore16(fr_part_to_float(P(v)), k, out);
inline void fr_wide_store(fr_wide_real_t v, float* out) { FR_EACH_PART(FR_STORE_PART) }
#define FR_LOAD_PART(k) fr_part_from_float(vload16(k, in))
inline fr_wide_real_t fr_wide_load(const float* in) { return FR_JOIN_PARTS(FR_LOAD_PART); }
/* A mask's lanes as 0 or 1 in ints (for counting). */
#define FR_STORE_BIT(P, k) vstore16(fr_part_to_int(P(m) & 1), k, out);
inline void fr_wide_store_bits(fr_wide_mask_t m, int* out) { FR_EACH_PART(FR_STORE_BIT) }

#endif
