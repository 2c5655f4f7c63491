/* dd_relative.cl — a double-double kernel's estimate (render.precision "dd", docs/deep_zoom.md).
 *
 * Every stage of such a kernel works in double, in coordinates relative to the eye: the camera's
 * eye is the origin, the scene's bounding sphere lies at -eye (frame_constants.h's
 * bounding_centre), point lights are moved by -eye. Near the surface of a deep view a position is
 * t x dir with t about the view's size, so double resolves it to 1e-16 of t, far finer than a
 * pixel. Only the estimate needs the absolute point: scene_de(d, params) below is the scene's
 * pair estimate at eye + d, the eye a pair per coordinate at the end of the parameter block
 * (kernel_assembly.cpp, PairOrigin), and the resolution it must reach is d's distance from the eye
 * times the frame's resolution angle (a pixel's footprint, or the hit threshold's where finer).
 * The scene's surface source gets the point in world coordinates, rounded to double: colours do
 * not need the pairs.
 *
 * Pasted after the scene's code, which must define scene_de_dd (the host checks it: it is what
 * makes a scene able to zoom past double; fr/mandelbox_dd.cl and fr/menger_dd.cl are the library's
 * own). */

inline scalar_t fr_eye_part(__constant const scene_params_t* params, int i) {
  return as_double(((ulong)params->fr_eye_bits[2 * i + 1] << 32) | (ulong)params->fr_eye_bits[2 * i]);
}

/* The eye as pairs (the same in every lane). */
inline dd3_t fr_eye_pairs(__constant const scene_params_t* params) {
  return dd3_make(dd_make((real_t)fr_eye_part(params, 0), (real_t)fr_eye_part(params, 1)),
                  dd_make((real_t)fr_eye_part(params, 2), (real_t)fr_eye_part(params, 3)),
                  dd_make((real_t)fr_eye_part(params, 4), (real_t)fr_eye_part(params, 5)));
}

/* A point relative to the eye in world coordinates, rounded to double. */
inline vec3_t fr_world_point(vec3_t d, __constant const scene_params_t* params) {
  return v3_add(d, v3s(fr_eye_part(params, 0) + fr_eye_part(params, 1),
                       fr_eye_part(params, 2) + fr_eye_part(params, 3),
                       fr_eye_part(params, 4) + fr_eye_part(params, 5)));
}

inline real_t fr_de_relative(vec3_t d, __constant const scene_params_t* params) {
  const real_t resolution = v3_length(d) * (real_t)params->fr_resolution_rad;
  return scene_de_dd(dd3_add_v3(fr_eye_pairs(params), d), params, resolution);
}

/* From here on, every stage's estimate is the pair estimate. */
#define scene_de(p, params) fr_de_relative((p), (params))
