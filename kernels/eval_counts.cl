/* eval_counts.cl — where the DE evaluations of a frame go, by stage (frame_constants.h's
 * FR_COUNT_* kinds, per bounce), and how busy the packet's lanes were while they were made.
 *
 * Compiled in only when the host builds the kernel with FR_COUNT_EVALS 1 (bench's counted pass,
 * render --counts, the explorer's statistics): otherwise every macro below expands to nothing,
 * so counting costs nothing when off. Stages that evaluate the DE take FR_COUNTS_PARAM in their
 * parameter list and pass FR_COUNTS_ARG on; each evaluation site says FR_COUNT(kind, lanes, n):
 * n evaluations of the whole packet, of which the lanes in `lanes` were wanted. A packet whose
 * lanes serve different kinds (shadow.cl's stream of every light's rays) says, per kind,
 * FR_COUNT_LANES(kind, wanted, held): the lanes that wanted the evaluation, and the lanes it
 * occupied for that kind. */

#if FR_COUNT_EVALS
typedef struct eval_counts_t {
  uint active[FR_COUNT_CELLS]; /* evaluations by lanes that wanted them */
  uint issued[FR_COUNT_CELLS]; /* lane evaluations made, wanted or not (FR_LANES a packet's) */
  int bounce;                  /* the bounce being rendered: 0 primary */
} eval_counts_t;

#if FR_LANES == 1
inline uint active_lanes(mask_t m) { return m ? 1u : 0u; }
#else
inline uint active_lanes(mask_t m) {
  /* A set lane is -1: its low bit is 1. */
  int bits[FR_LANES];
#if FR_LANES >= 32
  fr_wide_store_bits(m, bits);
#else
  FR_CAT(vstore, FR_LANES)(FR_CAT(convert_int, FR_LANES)(m) & 1, 0, bits);
#endif
  uint n = 0;
  for (int i = 0; i < FR_LANES; ++i) n += (uint)bits[i];
  return n;
}
#endif

#define FR_COUNTS_PARAM , eval_counts_t* counts
#define FR_COUNTS_ARG , counts
#define FR_COUNTS_BEGIN                                          \
  eval_counts_t counts_storage;                                  \
  for (int c_ = 0; c_ < FR_COUNT_CELLS; ++c_)                    \
    counts_storage.active[c_] = counts_storage.issued[c_] = 0u;  \
  counts_storage.bounce = 0;                                     \
  eval_counts_t* counts = &counts_storage
#define FR_COUNT_BOUNCE(b) counts->bounce = min((b), FR_COUNT_MAX_BOUNCES)
#define FR_COUNT(kind, lanes, n)                                       \
  do {                                                                 \
    const int cell_ = counts->bounce * FR_COUNT_KINDS + (kind);        \
    counts->active[cell_] += (uint)(n) * active_lanes(lanes);          \
    counts->issued[cell_] += (uint)(n) * FR_LANES;                     \
  } while (0)
#define FR_COUNT_LANES(kind, wanted, held)                             \
  do {                                                                 \
    const int cell_ = counts->bounce * FR_COUNT_KINDS + (kind);        \
    counts->active[cell_] += active_lanes(wanted);                     \
    counts->issued[cell_] += active_lanes(held);                       \
  } while (0)
/* Adds this work-item's sums into its slot of the frame's counters. */
#define FR_COUNTS_END(out)                                                              \
  do {                                                                                  \
    const size_t slot_ = (get_global_id(1) * get_global_size(0) + get_global_id(0)) %   \
                         FR_COUNT_SLOTS;                                                \
    __global uint* cells_ = (out) + slot_ * FR_COUNT_CELLS * 2;                         \
    for (int c_ = 0; c_ < FR_COUNT_CELLS; ++c_) {                                       \
      if (counts->issued[c_] == 0u) continue;                                           \
      atomic_add(&cells_[2 * c_ + 0], counts->active[c_]);                              \
      atomic_add(&cells_[2 * c_ + 1], counts->issued[c_]);                              \
    }                                                                                   \
  } while (0)
#else
#define FR_COUNTS_PARAM
#define FR_COUNTS_ARG
#define FR_COUNTS_BEGIN
#define FR_COUNT_BOUNCE(b)
#define FR_COUNT(kind, lanes, n)
#define FR_COUNT_LANES(kind, wanted, held)
#define FR_COUNTS_END(out)
#endif
