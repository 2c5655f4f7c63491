/* mandelbulber.cl — Mandelbulber2's iteration loop over the nine slots of fr/mandelbulber.cl.
 *
 * Per iteration i (Mandelbulber2 2.20's order): choose the slot (hybrid: the sequence below;
 * otherwise slot 1), run its formula, add c when the slot adds it, then r = |z| (4D) and stop the
 * lane once r passes the bailout (when the slot checks it), when z turns NaN (keeping the last
 * finite z) or, after a pseudo-Kleinian step, when the orbit has converged. The estimate comes
 * from the last z, r and dr.
 *
 * The hybrid sequence: a counter counts iterations; a slot that is empty or outside its
 * [start, stop] iterations is passed over (at most nine times); once the counter reaches the
 * slot's iterations-in-a-row the counter restarts and the next slot follows, slot 9 being followed
 * by repeat_from. The same for every lane, so it is scalar work. */
#include "fr/mandelbulber.cl"
#include "fr/primitives.cl"

#if FR_CHOICE_f1_mandelbulb != MB2_MANDELBULB || FR_CHOICE_f1_menger != MB2_MENGER || \
    FR_CHOICE_f1_pseudo_kleinian != MB2_PSEUDO_KLEINIAN ||                            \
    FR_CHOICE_estimate_pseudo_kleinian != MB2_DE_PSEUDO_KLEINIAN
#error "mandelbulber.c's kinds are out of step with fr/mandelbulber.cl"
#endif

/* What the formulas need, gathered once per evaluation (rotations as matrices). */
typedef struct mb2_setup_t {
  mb2_bulb_t bulb;
  mb2_mandelbox_t box;
  mb2_kifs_t kifs;
} mb2_setup_t;

#define MB2_PLANE(i)                                                                            \
  s.kifs.enabled[i] = PARAM(kifs_plane##i);                                                     \
  if (s.kifs.enabled[i]) {                                                                      \
    const vec3_t n = PARAM(kifs_plane##i##_direction);                                          \
    const scalar_t nx = mb2_lane0(n.x), ny = mb2_lane0(n.y), nz = mb2_lane0(n.z);               \
    const scalar_t length = fmax(sqrt(nx * nx + ny * ny + nz * nz), (scalar_t)FR_SCALAR_MIN);   \
    s.kifs.direction[i][0] = nx / length;                                                       \
    s.kifs.direction[i][1] = ny / length;                                                       \
    s.kifs.direction[i][2] = nz / length;                                                       \
    s.kifs.distance[i] = PARAM(kifs_plane##i##_distance);                                       \
    s.kifs.intensity[i] = PARAM(kifs_plane##i##_intensity);                                     \
    s.kifs.rotated[i] = mb2_turns(PARAM(kifs_plane##i##_rotation));                             \
    if (s.kifs.rotated[i]) s.kifs.plane_rotation[i] = mb2_rotation3(PARAM(kifs_plane##i##_rotation)); \
  }

#define MB2_USES(kind)                                                                        \
  (PARAM(f1) == (kind) || PARAM(f2) == (kind) || PARAM(f3) == (kind) || PARAM(f4) == (kind) || \
   PARAM(f5) == (kind) || PARAM(f6) == (kind) || PARAM(f7) == (kind) || PARAM(f8) == (kind) || \
   PARAM(f9) == (kind))

FR_MB2_INLINE inline mb2_setup_t mb2_setup(__constant const scene_params_t* params) {
  mb2_setup_t s;
  if (MB2_USES(MB2_MANDELBULB))
    s.bulb = mb2_bulb_setup(PARAM(bulb_power), PARAM(bulb_alpha), PARAM(bulb_beta));
  if (MB2_USES(MB2_MANDELBOX)) {
    s.box.scale = PARAM(box_scale);
    s.box.limit = PARAM(box_fold_limit);
    s.box.value = PARAM(box_fold_value);
    s.box.min_r2 = PARAM(box_min_radius) * PARAM(box_min_radius);
    s.box.fixed_r2 = PARAM(box_fixed_radius) * PARAM(box_fixed_radius);
    s.box.offset = PARAM(box_offset);
    {
      const vec3_t fold_colour = PARAM(box_colour);
      s.box.colour_x = mb2_lane0(fold_colour.x);
      s.box.colour_y = mb2_lane0(fold_colour.y);
      s.box.colour_z = mb2_lane0(fold_colour.z);
    }
    s.box.colour_sp1 = PARAM(box_colour_sp1);
    s.box.colour_sp2 = PARAM(box_colour_sp2);
    s.box.main_rotation = PARAM(box_main_rotation) && mb2_turns(PARAM(box_rotation));
    if (s.box.main_rotation) s.box.main = mb2_rotation2(PARAM(box_rotation));
    s.box.fold_rotations = PARAM(box_fold_rotations);
    if (s.box.fold_rotations) {
      s.box.neg[0] = mb2_rotation2(PARAM(box_rotation_neg_1));
      s.box.neg[1] = mb2_rotation2(PARAM(box_rotation_neg_2));
      s.box.neg[2] = mb2_rotation2(PARAM(box_rotation_neg_3));
      s.box.pos[0] = mb2_rotation2(PARAM(box_rotation_pos_1));
      s.box.pos[1] = mb2_rotation2(PARAM(box_rotation_pos_2));
      s.box.pos[2] = mb2_rotation2(PARAM(box_rotation_pos_3));
    }
  }
  if (MB2_USES(MB2_KIFS)) {
    s.kifs.scale = PARAM(kifs_scale);
    s.kifs.offset = PARAM(kifs_offset);
    s.kifs.edge = PARAM(kifs_edge);
    s.kifs.abs_x = PARAM(kifs_abs_x);
    s.kifs.abs_y = PARAM(kifs_abs_y);
    s.kifs.abs_z = PARAM(kifs_abs_z);
    s.kifs.menger_mode = PARAM(kifs_menger_mode);
    /* (A rotation by zero angles is skipped: files from 2.06 and before have it on.) */
    s.kifs.rotation_enabled = PARAM(kifs_rotation_enabled) && mb2_turns(PARAM(kifs_rotation));
    if (s.kifs.rotation_enabled) s.kifs.rotation = mb2_rotation3(PARAM(kifs_rotation));
    MB2_PLANE(0)
    MB2_PLANE(1)
    MB2_PLANE(2)
    MB2_PLANE(3)
    MB2_PLANE(4)
    MB2_PLANE(5)
    MB2_PLANE(6)
    MB2_PLANE(7)
    MB2_PLANE(8)
  }
  return s;
}

/* One formula step of kind `kind` (a compile-time constant at each call). */
FR_MB2_INLINE inline void mb2_step(int kind, vec3_t* z, real_t* w, real_t r2, real_t* dr,
                                  real_t* colour, const mb2_setup_t* s,
                                  __constant const scene_params_t* params) {
  /* Only the squares' steps need r itself: its square root is taken there, not per iteration. */
  switch (kind) {
    case MB2_MANDELBULB:
      mb2_mandelbulb(z, *w, sqrt(r2), dr, &s->bulb);
      break;
    case MB2_POWER2:
      mb2_power2(z, sqrt(r2), dr);
      break;
    case MB2_HYPERCOMPLEX:
      mb2_hypercomplex(z, w, sqrt(r2), dr);
      break;
    case MB2_QUATERNION:
      mb2_quaternion(z, sqrt(r2), dr);
      break;
    case MB2_MENGER:
      mb2_menger(z, dr, PARAM(menger_scale));
      break;
    case MB2_MANDELBOX:
      mb2_mandelbox(z, w, dr, colour, &s->box);
      break;
    case MB2_KIFS:
      mb2_kifs(z, w, dr, &s->kifs);
      break;
    case MB2_PSEUDO_KLEINIAN:
      mb2_pseudo_kleinian(z, w, dr, PARAM(pk_box), PARAM(pk_min_r2), PARAM(pk_tweak),
                          PARAM(pk_offset));
      break;
    default:
      break;
  }
}

/* The slot's parameters by index 0..8 (uniform, so every lane takes the same branch). */
#define MB2_SLOT_FIELD(slot, field)                                                         \
  ((slot) == 0   ? PARAM(f1##field)                                                         \
   : (slot) == 1 ? PARAM(f2##field)                                                         \
   : (slot) == 2 ? PARAM(f3##field)                                                         \
   : (slot) == 3 ? PARAM(f4##field)                                                         \
   : (slot) == 4 ? PARAM(f5##field)                                                         \
   : (slot) == 5 ? PARAM(f6##field)                                                         \
   : (slot) == 6 ? PARAM(f7##field)                                                         \
   : (slot) == 7 ? PARAM(f8##field)                                                         \
                 : PARAM(f9##field))

inline int mb2_next_slot(int slot, __constant const scene_params_t* params) {
  return slot < 8 ? slot + 1 : clamp(PARAM(repeat_from), 1, 9) - 1;
}

/* Whether the slot runs at iteration i: it has a formula and i lies in its window. */
inline int mb2_slot_runs(int slot, int i, __constant const scene_params_t* params) {
  return MB2_SLOT_FIELD(slot, ) != MB2_NONE && i >= MB2_SLOT_FIELD(slot, _start) &&
         i <= MB2_SLOT_FIELD(slot, _stop);
}

#define MB2_RUN_SLOT(n)                                                  \
  case n - 1:                                                            \
    kind = PARAM(f##n);                                                  \
    mb2_step(PARAM(f##n), &nz, &nw, r2, &ndr, &ncolour, &setup, params); \
    add_c = PARAM(f##n##_add_c);                                         \
    check = PARAM(f##n##_check_bailout);                                 \
    break;

/* Mandelbulber2's colouring algorithms (mat1_fractal_coloring_algorithm 0-4): the value whose
 * smallest over the orbit is the orbit trap. */
#define MB2_COLOUR_STANDARD 0    /* |z| */
#define MB2_COLOUR_Z_DOT_POINT 1 /* |z . p| */
#define MB2_COLOUR_SPHERE 2      /* ||z - p| - radius| */
#define MB2_COLOUR_CROSS 3       /* min(|x|, |y|, |z|) */
#define MB2_COLOUR_LINE 4        /* |z . direction| */

/* What a colouring pass keeps of an orbit, as Mandelbulber2's colouring mode does. */
typedef struct mb2_orbit_t {
  real_t colour_min; /* the trap's smallest value (1000 if never taken) */
  real_t aux_colour; /* the folds' colour sum, from 1 */
  real_t r, dr;      /* at the end */
} mb2_orbit_t;

FR_MB2_INLINE inline real_t mb2_trap_value(vec3_t z, vec3_t p,
                                           __constant const scene_params_t* params) {
  switch (PARAM(colour_algorithm)) {
    case MB2_COLOUR_Z_DOT_POINT:
      return fabs(v3_dot(z, p));
    case MB2_COLOUR_SPHERE:
      return fabs(v3_length(v3_sub(z, p)) - to_real(PARAM(colour_sphere_radius)));
    case MB2_COLOUR_CROSS:
      return fmin(fmin(fabs(z.x), fabs(z.y)), fabs(z.z));
    case MB2_COLOUR_LINE:
      return fabs(v3_dot(z, PARAM(colour_line_direction)));
    default:
      return v3_length(z);
  }
}

/* The orbit of p: the distance estimate (colouring = 0), or Mandelbulber2's colouring pass
 * (colouring = 1, a constant at each call: the pass's extra sums and tests vanish from the
 * estimate). The colouring pass differs as Mandelbulber2's does: where a slot checks the bailout
 * it takes the trap value first (not after a Mandelbox step in the standard algorithm), and a
 * Mandelbox step in the standard algorithm runs on until |z| passes 1e15 (its fold count is the
 * colour); a step that no longer moves z (|dz| / r < 1e-15) ends a Mandelbox or Kleinian orbit. */
FR_MB2_INLINE inline real_t mb2_iterate(vec3_t p, __constant const scene_params_t* params,
                                        const int colouring, real_t* trap, mb2_orbit_t* orbit) {
  const mb2_setup_t setup = mb2_setup(params);
  const vec3_t c = v3_mul(PARAM(julia) ? PARAM(julia_c) : p, PARAM(constant_factor));
  vec3_t z = p, z_prev = p, z_prev2 = p;
  real_t w = to_real(0);
  real_t dr = to_real(1);
  real_t aux_colour = to_real(1), colour_min = to_real(1000);
  /* |z|^2 (4D): the bailout test compares squares (a square root per iteration cost a sixth of
   * an IFS evaluation); r itself is taken once, for the estimate. */
  real_t r2 = v3_length2(z);
  real_t orbit_min = r2;
  const real_t bailout = to_real(PARAM(bailout));
  const real_t bailout2 = to_real(PARAM(bailout) * PARAM(bailout));
  mask_t live = FR_MASK_TRUE;
  mask_t escaped = FR_MASK_FALSE; /* by the bailout or the Kleinian convergence test */
  mask_t no_formula = FR_MASK_FALSE; /* reached a slot without a formula */
  int slot = 0, counter = 0;
  for (int i = 0; i < PARAM(iterations); ++i) {
    if (!any_lane(live)) break;
    if (PARAM(hybrid)) {
      ++counter;
      for (int tries = 0; tries < 9 && !mb2_slot_runs(slot, i, params); ++tries)
        slot = mb2_next_slot(slot, params);
    }
    const int seq = slot;
    if (MB2_SLOT_FIELD(seq, ) == MB2_NONE) {
      /* Mandelbulber2 leaves such a point outside (distance 10). */
      no_formula = live;
      break;
    }
    vec3_t nz = z;
    real_t nw = w, ndr = dr, ncolour = aux_colour;
    int kind = MB2_NONE, add_c = 1, check = 1;
    switch (seq) {
      MB2_RUN_SLOT(1)
      MB2_RUN_SLOT(2)
      MB2_RUN_SLOT(3)
      MB2_RUN_SLOT(4)
      MB2_RUN_SLOT(5)
      MB2_RUN_SLOT(6)
      MB2_RUN_SLOT(7)
      MB2_RUN_SLOT(8)
      MB2_RUN_SLOT(9)
    }
    if (add_c) nz = v3_add(nz, c);
    if (!PARAM(hybrid)) check = 1;
    if (PARAM(hybrid) && counter >= MB2_SLOT_FIELD(seq, _iterations)) {
      counter = 0;
      slot = mb2_next_slot(slot, params);
    }
    const real_t nr2 = v3_length2(nz) + nw * nw;
    /* A NaN orbit keeps its last finite z and stops. */
    const mask_t finite = !isnan(nr2);
    const mask_t step = live & finite;
    mask_t stop = live & !finite;
    if (colouring && check) {
      const real_t nr = sqrt(nr2);
      const int standard = PARAM(colour_algorithm) == MB2_COLOUR_STANDARD;
      const int box = kind == MB2_MANDELBOX;
      if (!box || !standard)
        colour_min = lane_select(step, fmin(colour_min, mb2_trap_value(nz, p, params)), colour_min);
      mask_t out = step & (nr > ((box && standard) ? to_real(1e15) : bailout));
      if (box || kind == MB2_PSEUDO_KLEINIAN) {
        const vec3_t dz = v3_sub(nz, z);
        const real_t dw = nw - w;
        out = out | (step & (sqrt(v3_length2(dz) + dw * dw) < to_real(1e-15) * nr));
      }
      stop = stop | out;
    }
    if (!colouring && MB2_USES(MB2_PSEUDO_KLEINIAN)) {
      z_prev2 = v3_select(step, z_prev, z_prev2);
      z_prev = v3_select(step, z, z_prev);
    }
    z = v3_select(step, nz, z);
    w = lane_select(step, nw, w);
    dr = lane_select(step, ndr, dr);
    r2 = lane_select(step, nr2, r2);
    if (colouring) aux_colour = lane_select(step, ncolour, aux_colour);
    orbit_min = lane_select(step, fmin(orbit_min, nr2), orbit_min);
    if (!colouring && check) {
      const mask_t out = step & (nr2 > bailout2);
      stop = stop | out;
      escaped = escaped | out;
    }
    if (!colouring && check && kind == MB2_PSEUDO_KLEINIAN) {
      /* Mandelbulber2's convergence test for Kleinian orbits. */
      const real_t limit = to_real(0.1) / bailout * fmax(sqrt(nr2), to_real(FR_SCALAR_MIN));
      const mask_t converged = step & ((v3_length(v3_sub(z, z_prev)) < limit) |
                                       (v3_length(v3_sub(z, z_prev2)) < limit));
      stop = stop | converged;
      escaped = escaped | converged;
    }
    live = live & !stop;
  }
  *trap = orbit_min;
  const real_t r = mb2_length4(z, w);
  if (colouring) {
    orbit->colour_min = colour_min;
    orbit->aux_colour = aux_colour;
    orbit->r = r;
    orbit->dr = dr;
    return r;
  }
  real_t d = mb2_distance(PARAM(estimate), z, r, dr, PARAM(linear_offset), PARAM(pk_de_offset));
  /* Mandelbulber2 with limits: an orbit that ran all N iterations is surface. */
  if (PARAM(solid_interior)) d = lane_select(escaped, d, to_real(0));
  d = lane_select(no_formula, to_real(10), d);
  if (PARAM(limits)) {
    const vec3_t lo = PARAM(limit_min), hi = PARAM(limit_max);
    const vec3_t centre = v3_scale(v3_add(lo, hi), to_real(0.5));
    const vec3_t half_size = v3_abs(v3_scale(v3_sub(hi, lo), to_real(0.5)));
    d = fmax(d, sd_box(v3_sub(p, centre), half_size));
  }
  return d;
}

FR_MB2_INLINE inline real_t mb2_de(vec3_t p, __constant const scene_params_t* params,
                                   real_t* trap) {
  mb2_orbit_t unused;
  return mb2_iterate(p, params, 0, trap, &unused);
}

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  return mb2_de(p, params, &trap);
}
