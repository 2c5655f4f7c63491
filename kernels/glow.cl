/* glow.cl — glow around the surface from how close a missing ray passed to it: the march tracks
 * its smallest DE value d, and the sky behind gets glow_color * strength * exp(-d / falloff). */

#define FR_MARCH_TRACK(min_dist, dist, active) \
  min_dist = lane_select(active, fmin(min_dist, dist), min_dist)

inline vec3_t add_glow(vec3_t color, real_t min_dist, mask_t miss,
                       __constant const fr_frame_constants* fc) {
  real_t amount = (real_t)fc->glow_strength *
                  exp(-fmax(min_dist, (real_t)0) / (real_t)fc->glow_falloff);
  return v3_select(miss, v3_mad(color, v3_from_float4(fc->glow_color), amount), color);
}

#define FR_APPLY_GLOW(color, m, miss) color = add_glow(color, (m).min_dist, miss, fc)
