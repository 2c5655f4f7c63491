/* fr/mandelbulber.cl — the formulas of Mandelbulber2 (Krzysztof Marczak and contributors) that
 * the importer brings over, each one iteration step exactly as Mandelbulber2 2.20 defines it
 * (its formulas as facts; this code is written here). The scene `mandelbulber` chains them in
 * Mandelbulber2's hybrid order; docs/mandelbulber2.md says what maps to what.
 *
 * Conventions shared by every step, as Mandelbulber2 has them:
 *   - z is a 4-vector (x, y, z as a vec3_t, w apart); r is its 4D length at the start of the step.
 *   - dr is Mandelbulber2's running derivative (aux.DE), starting at 1.
 *   - No step adds c: the loop does, after the step, when the slot adds it.
 *   - Angles are degrees, turned into rotation matrices once per evaluation (mb2_rotation_*), in
 *     scalar_t: parameters are the same in every lane, so their trigonometry is done once, not
 *     per lane (mb2_lane0 takes a uniform value out of a lane vector).
 * Every step computes all lanes; the loop keeps the result only on the lanes still iterating. */

/* The steps and the loop are inlined into one body: each step's switches are then constants
 * there (the parameters that shape it are compiled in), and the nine-plane IFS or a rotated box
 * fold unrolls to what the file enables. As calls, they passed the setup and 16-lane vectors by
 * memory and tested every plane's flag at run time. */
#define FR_MB2_INLINE __attribute__((always_inline))

#include "fr/powers.cl"

#define MB2_NONE 0
#define MB2_MANDELBULB 1      /* id 2: White and Nylander's bulb, latitude by asin */
#define MB2_POWER2 2          /* id 3: the power-2 bulb's polynomial form */
#define MB2_HYPERCOMPLEX 3    /* id 4: hypercomplex square (4D) */
#define MB2_QUATERNION 4      /* id 5: quaternion square (x, y, z) */
#define MB2_MENGER 5          /* id 7: Menger's sponge as an IFS (Knighty's folds) */
#define MB2_MANDELBOX 6       /* id 8: Tom Lowe's Mandelbox with Mandelbulber's options */
#define MB2_KIFS 7            /* id 10: Knighty's kaleidoscopic IFS with up to nine planes */
#define MB2_PSEUDO_KLEINIAN 8 /* id 103: Theli-at's pseudo-Kleinian */

#define MB2_DE_LOGARITHMIC 0 /* 0.5 r ln r / dr */
#define MB2_DE_LINEAR 1      /* (r - offset) / dr */
#define MB2_DE_IFS 2         /* (r - 2) / dr */
#define MB2_DE_PSEUDO_KLEINIAN 3

/* A value that is the same in every lane (a parameter), as one scalar. */
#if FR_LANES == 1
#define mb2_lane0(x) ((scalar_t)(x))
#else
#define mb2_lane0(x) ((scalar_t)(x).s0)
#endif

/* A rotation as its matrix, row by row (uniform: the same for every lane). */
typedef struct mb2_rot_t {
  scalar_t m[9];
} mb2_rot_t;

FR_MB2_INLINE inline vec3_t mb2_rotate(mb2_rot_t r, vec3_t v) {
  return v3(r.m[0] * v.x + r.m[1] * v.y + r.m[2] * v.z, r.m[3] * v.x + r.m[4] * v.y + r.m[5] * v.z,
            r.m[6] * v.x + r.m[7] * v.y + r.m[8] * v.z);
}
/* The inverse (transpose) rotation. */
FR_MB2_INLINE inline vec3_t mb2_rotate_back(mb2_rot_t r, vec3_t v) {
  return v3(r.m[0] * v.x + r.m[3] * v.y + r.m[6] * v.z, r.m[1] * v.x + r.m[4] * v.y + r.m[7] * v.z,
            r.m[2] * v.x + r.m[5] * v.y + r.m[8] * v.z);
}

/* Rz(c) Ry(b) Rx(a), right-handed, angles in degrees: rotate about x first, then y, then z. */
inline mb2_rot_t mb2_rotation_zyx(scalar_t a_deg, scalar_t b_deg, scalar_t c_deg) {
  const scalar_t k = (scalar_t)(M_PI / 180);
  const scalar_t ca = cos(a_deg * k), sa = sin(a_deg * k);
  const scalar_t cb = cos(b_deg * k), sb = sin(b_deg * k);
  const scalar_t cc = cos(c_deg * k), sc = sin(c_deg * k);
  mb2_rot_t r;
  r.m[0] = cc * cb;
  r.m[1] = cc * sb * sa - sc * ca;
  r.m[2] = cc * sb * ca + sc * sa;
  r.m[3] = sc * cb;
  r.m[4] = sc * sb * sa + cc * ca;
  r.m[5] = sc * sb * ca - cc * sa;
  r.m[6] = -sb;
  r.m[7] = cb * sa;
  r.m[8] = cb * ca;
  return r;
}
/* Mandelbulber's "rotation 2" (the Mandelbox's, the pseudo-Kleinian's): Rz(v.z) Ry(v.y) Rx(v.x),
 * from a vec3 parameter (uniform). */
inline mb2_rot_t mb2_rotation2(vec3_t deg) {
  return mb2_rotation_zyx(mb2_lane0(deg.x), mb2_lane0(deg.y), mb2_lane0(deg.z));
}
/* Mandelbulber's "rotation 3" (the kaleidoscopic IFS's): Rz(v.x) Ry(v.y) Rx(v.z). */
inline mb2_rot_t mb2_rotation3(vec3_t deg) {
  return mb2_rotation_zyx(mb2_lane0(deg.z), mb2_lane0(deg.y), mb2_lane0(deg.x));
}
/* Whether a vec3 parameter of angles is not all zero (no rotation then). */
inline int mb2_turns(vec3_t deg) {
  return mb2_lane0(deg.x) != 0 || mb2_lane0(deg.y) != 0 || mb2_lane0(deg.z) != 0;
}

/* id 2's constants, once per evaluation: a whole power in [1, 64] takes no trigonometry. */
typedef struct mb2_bulb_t {
  scalar_t power, alpha_rad, beta_rad;
  int whole;
  scalar_t cos_alpha, sin_alpha, cos_beta, sin_beta;
} mb2_bulb_t;

inline mb2_bulb_t mb2_bulb_setup(scalar_t power, scalar_t alpha_deg, scalar_t beta_deg) {
  mb2_bulb_t b;
  b.power = power;
  b.alpha_rad = alpha_deg * (scalar_t)(M_PI / 180);
  b.beta_rad = beta_deg * (scalar_t)(M_PI / 180);
  b.whole = power == rint(power) && power >= 1 && power <= 64;
  b.cos_alpha = cos(b.alpha_rad);
  b.sin_alpha = sin(b.alpha_rad);
  b.cos_beta = cos(b.beta_rad);
  b.sin_beta = sin(b.beta_rad);
  return b;
}

/* id 2: theta = asin(z/r) + beta, phi = atan2(y, x) + alpha, both times the power;
 * dr <- p r^(p-1) dr + 1 (r the 4D length, w untouched).
 *
 * A whole power takes the angles without trigonometry, as fr/mandelbulb.cl's bulb does: the unit
 * vectors (cos, sin) of asin(z/r) and atan2(y, x) are read off z (cos asin(z/r) = |(x, y, w)| / r,
 * which w enters as it enters r), turned by beta and alpha, and raised to the power by de
 * Moivre's formula. On the z axis atan2 is taken as atan2(0, 0) = 0 (phi = alpha), as in the
 * trigonometric path for +0. */
FR_MB2_INLINE inline void mb2_mandelbulb(vec3_t* z, real_t w, real_t r, real_t* dr,
                                         const mb2_bulb_t* b) {
  const real_t safe_r = fmax(r, to_real(FR_SCALAR_MIN));
  if (b->whole) {
    const int n = (int)b->power;
    const real_t inv_r = to_real(1) / safe_r;
    const real_t rho2 = z->x * z->x + z->y * z->y;
    /* (cos, sin) of the latitude, then of latitude + beta. */
    const real_t c0 = fmin(sqrt(rho2 + w * w) * inv_r, to_real(1));
    const real_t s0 = clamp(z->z * inv_r, to_real(-1), to_real(1));
    real_t ct = c0 * to_real(b->cos_beta) - s0 * to_real(b->sin_beta);
    real_t st = c0 * to_real(b->sin_beta) + s0 * to_real(b->cos_beta);
    /* (cos, sin) of the longitude, then of longitude + alpha. */
    const real_t rho = sqrt(rho2);
    const mask_t on_axis = rho <= to_real(FR_SCALAR_MIN);
    const real_t inv_rho = to_real(1) / fmax(rho, to_real(FR_SCALAR_MIN));
    const real_t cp0 = lane_select(on_axis, to_real(1), z->x * inv_rho);
    const real_t sp0 = lane_select(on_axis, to_real(0), z->y * inv_rho);
    real_t cp = cp0 * to_real(b->cos_alpha) - sp0 * to_real(b->sin_alpha);
    real_t sp = cp0 * to_real(b->sin_alpha) + sp0 * to_real(b->cos_alpha);
    unit_complex_pow_int(&ct, &st, n);
    unit_complex_pow_int(&cp, &sp, n);
    const real_t rp1 = pow_int(r, n - 1);
    *dr = rp1 * to_real(b->power) * *dr + to_real(1);
    const real_t rp = rp1 * r;
    *z = v3(rp * ct * cp, rp * ct * sp, rp * st);
    return;
  }
  const real_t th = (asin(clamp(z->z / safe_r, to_real(-1), to_real(1))) + to_real(b->beta_rad)) *
                    to_real(b->power);
  const real_t ph = (atan2(z->y, z->x) + to_real(b->alpha_rad)) * to_real(b->power);
  const real_t rp1 = pow_nonneg(r, to_real(b->power - 1));
  *dr = rp1 * to_real(b->power) * *dr + to_real(1);
  const real_t rp = rp1 * r;
  const real_t cth = cos(th);
  *z = v3(rp * cth * cos(ph), rp * cth * sin(ph), rp * sin(th));
}

/* id 3: x' = (x^2 - y^2) t, y' = 2 x y t, z' = -2 z sqrt(x^2 + y^2), t = 1 - z^2 / (x^2 + y^2);
 * dr <- 2 r dr. */
FR_MB2_INLINE inline void mb2_power2(vec3_t* z, real_t r, real_t* dr) {
  const real_t s = fmax(z->x * z->x + z->y * z->y, to_real(FR_SCALAR_MIN));
  const real_t t = to_real(1) - z->z * z->z / s;
  *dr = 2 * r * *dr;
  *z = v3((z->x * z->x - z->y * z->y) * t, 2 * z->x * z->y * t, -2 * z->z * sqrt(s));
}

/* id 4: the hypercomplex square on (x, y, z, w); dr <- 2 r dr. */
FR_MB2_INLINE inline void mb2_hypercomplex(vec3_t* z, real_t* w, real_t r, real_t* dr) {
  const vec3_t q = *z;
  const real_t qw = *w;
  *dr = 2 * r * *dr;
  *z = v3(q.x * q.x - q.y * q.y - q.z * q.z - qw * qw, 2 * q.x * q.y - 2 * qw * q.z,
          2 * q.x * q.z - 2 * q.y * qw);
  *w = 2 * q.x * qw - 2 * q.y * q.z;
}

/* id 5: the quaternion square on (x, y, z) (w untouched in 2.20); dr <- 2 r dr. */
FR_MB2_INLINE inline void mb2_quaternion(vec3_t* z, real_t r, real_t* dr) {
  const vec3_t q = *z;
  *dr = 2 * r * *dr;
  *z = v3(q.x * q.x - q.y * q.y - q.z * q.z, 2 * q.x * q.y, 2 * q.x * q.z);
}

/* id 7: abs, sort descending, scale, then the fixed offsets x, y -= 2 and z -= 2 when z > 1;
 * dr <- s dr. */
FR_MB2_INLINE inline void mb2_menger(vec3_t* z, real_t* dr, scalar_t scale) {
  vec3_t q = v3_abs(*z);
  real_t t;
  mask_t m = q.x < q.y;
  t = q.x;
  q.x = lane_select(m, q.y, q.x);
  q.y = lane_select(m, t, q.y);
  m = q.x < q.z;
  t = q.x;
  q.x = lane_select(m, q.z, q.x);
  q.z = lane_select(m, t, q.z);
  m = q.y < q.z;
  t = q.y;
  q.y = lane_select(m, q.z, q.y);
  q.z = lane_select(m, t, q.z);
  q = v3_scale(q, to_real(scale));
  q.x -= 2;
  q.y -= 2;
  q.z = lane_select(q.z > to_real(1), q.z - 2, q.z);
  *z = q;
  *dr = *dr * to_real(scale);
}

/* Box fold of one coordinate: beyond +-limit it becomes +-value minus itself. */
inline real_t mb2_fold(real_t a, real_t limit, real_t value) {
  return lane_select(a > limit, value - a, lane_select(a < -limit, -value - a, a));
}

typedef struct mb2_mandelbox_t {
  scalar_t scale, limit, value, min_r2, fixed_r2;
  vec3_t offset;
  /* Mandelbulber2's colouring counts of the folds (mandelbox_color, _Sp1, _Sp2): per axis
   * folded, and for the inner or the outer sphere fold. */
  scalar_t colour_x, colour_y, colour_z, colour_sp1, colour_sp2;
  int main_rotation, fold_rotations;
  mb2_rot_t main;
  mb2_rot_t neg[3], pos[3]; /* per-axis fold rotations */
} mb2_mandelbox_t;

inline real_t mb2_component(vec3_t v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
inline vec3_t mb2_with_component(vec3_t v, int axis, real_t a) {
  if (axis == 0) v.x = a;
  else if (axis == 1) v.y = a;
  else v.z = a;
  return v;
}

/* id 8: box fold (optionally in rotated frames per axis), sphere fold about -offset, the main
 * rotation, scale; dr <- dr |s| (times the sphere fold's factor) + 1. w takes the scalings.
 * `colour` is Mandelbulber2's aux.color: each fold adds its colour factor (the estimate does not
 * read it, and inlined, its sums are dropped there). */
FR_MB2_INLINE inline void mb2_mandelbox(vec3_t* z, real_t* w, real_t* dr, real_t* colour,
                                        const mb2_mandelbox_t* b) {
  vec3_t q = *z;
  const real_t limit = to_real(b->limit), value = to_real(b->value);
  const scalar_t axis_colour[3] = {b->colour_x, b->colour_y, b->colour_z};
  if (b->fold_rotations) {
    for (int axis = 0; axis < 3; ++axis) {
      /* Mandelbulber's naming: the "neg" rotation frames the fold on the positive side. */
      vec3_t a = mb2_rotate(b->neg[axis], q);
      const real_t ad = mb2_component(a, axis);
      const mask_t high = ad > limit;
      const vec3_t from_high = mb2_rotate_back(b->neg[axis], mb2_with_component(a, axis, value - ad));
      vec3_t c = mb2_rotate(b->pos[axis], q);
      const real_t cd = mb2_component(c, axis);
      const mask_t low = cd < -limit;
      const vec3_t from_low = mb2_rotate_back(b->pos[axis], mb2_with_component(c, axis, -value - cd));
      q = v3_select(high, from_high, v3_select(low, from_low, q));
      *colour += lane_select(high | low, to_real(axis_colour[axis]), to_real(0));
    }
  } else {
    *colour += lane_select(fabs(q.x) > limit, to_real(axis_colour[0]), to_real(0)) +
               lane_select(fabs(q.y) > limit, to_real(axis_colour[1]), to_real(0)) +
               lane_select(fabs(q.z) > limit, to_real(axis_colour[2]), to_real(0));
    q = v3(mb2_fold(q.x, limit, value), mb2_fold(q.y, limit, value), mb2_fold(q.z, limit, value));
  }
  const real_t r2 = v3_length2(q) + *w * *w;
  q = v3_add(q, b->offset);
  const real_t factor =
      lane_select(r2 < to_real(b->min_r2), to_real(b->fixed_r2 / fmax(b->min_r2, FR_SCALAR_MIN)),
                  lane_select(r2 < to_real(b->fixed_r2),
                              to_real(b->fixed_r2) / fmax(r2, to_real(FR_SCALAR_MIN)), to_real(1)));
  *colour += lane_select(r2 < to_real(b->min_r2), to_real(b->colour_sp1),
                         lane_select(r2 < to_real(b->fixed_r2), to_real(b->colour_sp2), to_real(0)));
  q = v3_sub(v3_scale(q, factor), b->offset);
  if (b->main_rotation) q = mb2_rotate(b->main, q);
  *z = v3_scale(q, to_real(b->scale));
  *w = *w * factor * to_real(b->scale);
  *dr = *dr * factor * to_real(fabs(b->scale)) + to_real(1);
}

#define MB2_KIFS_PLANES 9

typedef struct mb2_kifs_t {
  scalar_t scale;
  vec3_t offset, edge;
  int abs_x, abs_y, abs_z, menger_mode, rotation_enabled;
  mb2_rot_t rotation;
  int enabled[MB2_KIFS_PLANES];
  int rotated[MB2_KIFS_PLANES]; /* the plane's rotation is not the identity */
  scalar_t direction[MB2_KIFS_PLANES][3]; /* unit */
  scalar_t distance[MB2_KIFS_PLANES], intensity[MB2_KIFS_PLANES];
  mb2_rot_t plane_rotation[MB2_KIFS_PLANES];
} mb2_kifs_t;

/* id 10: abs per axis; each enabled plane rotates, then reflects what lies below its distance;
 * the main rotation about the offset point; the edge fold; scale about the offset (Menger mode:
 * z only above half its offset); dr <- dr |s|. */
FR_MB2_INLINE inline void mb2_kifs(vec3_t* z, real_t* w, real_t* dr, const mb2_kifs_t* k) {
  vec3_t q = *z;
  if (k->abs_x) q.x = fabs(q.x);
  if (k->abs_y) q.y = fabs(q.y);
  if (k->abs_z) q.z = fabs(q.z);
  /* Unrolled: with the loop inlined, each plane's flag is a constant and a disabled plane
   * leaves no code (as a loop its values were read back from memory by index). */
#pragma unroll
  for (int i = 0; i < MB2_KIFS_PLANES; ++i) {
    if (!k->enabled[i]) continue;
    if (k->rotated[i]) q = mb2_rotate(k->plane_rotation[i], q);
    const scalar_t nx = k->direction[i][0], ny = k->direction[i][1], nz = k->direction[i][2];
    const real_t l = q.x * nx + q.y * ny + q.z * nz;
    const real_t d = to_real(k->distance[i]);
    const real_t push = lane_select(l < d, 2 * (l - d) * to_real(k->intensity[i]), to_real(0));
    q = v3(q.x - nx * push, q.y - ny * push, q.z - nz * push);
  }
  if (k->rotation_enabled)
    q = v3_add(mb2_rotate(k->rotation, v3_sub(q, k->offset)), k->offset);
  /* The edge: a component whose edge value is positive folds back from it. */
  q.x = lane_select(k->edge.x > 0, k->edge.x - fabs(k->edge.x - q.x), q.x);
  q.y = lane_select(k->edge.y > 0, k->edge.y - fabs(k->edge.y - q.y), q.y);
  q.z = lane_select(k->edge.z > 0, k->edge.z - fabs(k->edge.z - q.z), q.z);
  const real_t s = to_real(k->scale);
  q = v3_scale(q, s);
  const vec3_t shift = v3_scale(k->offset, s - 1);
  q.x -= shift.x;
  q.y -= shift.y;
  if (k->menger_mode)
    q.z = lane_select(q.z > to_real(0.5) * shift.z, q.z - shift.z, q.z);
  else
    q.z -= shift.z;
  *z = q;
  *w = *w * s;
  *dr = *dr * fabs(s);
}

/* id 103: the box's clamp fold, then the inversion k = max(K / |z|^2, 1) (K a squared radius);
 * dr <- dr (k + tweak); then the offset. */
FR_MB2_INLINE inline void mb2_pseudo_kleinian(vec3_t* z, real_t* w, real_t* dr, vec3_t box,
                                              scalar_t min_r2, scalar_t tweak, vec3_t offset) {
  vec3_t q = *z;
  q = v3(2 * clamp(q.x, -box.x, box.x) - q.x, 2 * clamp(q.y, -box.y, box.y) - q.y,
         2 * clamp(q.z, -box.z, box.z) - q.z);
  const real_t k =
      fmax(to_real(min_r2) / fmax(v3_length2(q) + *w * *w, to_real(FR_SCALAR_MIN)), to_real(1));
  q = v3_scale(q, k);
  *w = *w * k;
  *dr = *dr * (k + to_real(tweak));
  *z = v3_add(q, offset);
}

/* |(z, w)| without overflowing where its square would (an orbit past 1e19 in float). */
FR_MB2_INLINE inline real_t mb2_length4(vec3_t z, real_t w) {
  const real_t m = fmax(fmax(fabs(z.x), fabs(z.y)), fmax(fabs(z.z), fabs(w)));
  const real_t inv = to_real(1) / fmax(m, to_real(FR_SCALAR_MIN));
  const vec3_t u = v3_scale(z, inv);
  const real_t uw = w * inv;
  return lane_select(isinf(m), m, m * sqrt(v3_length2(u) + uw * uw));
}

/* The distance from the last z (4D length r) and dr, by the chosen estimate; Mandelbulber2 keeps
 * it within [0, 10] and falls back to r when dr is not positive. */
inline real_t mb2_distance(int estimate, vec3_t z, real_t r, real_t dr, scalar_t linear_offset,
                           scalar_t pk_offset) {
  real_t d;
  const real_t safe_dr = fmax(dr, to_real(FR_SCALAR_MIN));
  if (estimate == MB2_DE_LOGARITHMIC) {
    d = to_real(0.5) * r * log(fmax(r, to_real(FR_SCALAR_MIN))) / safe_dr;
  } else if (estimate == MB2_DE_IFS) {
    d = (r - 2) / safe_dr;
  } else if (estimate == MB2_DE_PSEUDO_KLEINIAN) {
    const real_t rxy = sqrt(z.x * z.x + z.y * z.y);
    d = fmax(rxy - to_real(pk_offset), fabs(rxy * z.z) / fmax(r, to_real(FR_SCALAR_MIN))) / safe_dr;
  } else {
    d = (r - to_real(linear_offset)) / safe_dr;
  }
  d = lane_select(dr > 0, d, r);
  return clamp(d, to_real(0), to_real(10));
}
