/* material_probe.cl — a scene's material function (scene_material, prelude.cl) at given points,
 * as it returns them, before material.cl clamps them: `fractalis check` reports values outside
 * material_t's ranges, which the renderer would otherwise change silently. Pasted after
 * material.cl into a kernel with the scene's surface source. fr_probe_material (FR_MATERIAL_FLOATS
 * floats a point, in material_t's order) exists only for scenes that define the function;
 * fr_probe_albedo (the surface function's albedo) for every scene. */

#define FR_MATERIAL_FLOATS 19

/* The packet's points, from the first at `first` (a partial last packet repeats the last). */
inline vec3_t probe_points(__global const float* xyz, int first, int count) {
  float x[FR_LANES], y[FR_LANES], z[FR_LANES];
  for (int lane = 0; lane < FR_LANES; ++lane) {
    const int i = min(first + lane, count - 1);
    x[lane] = xyz[3 * i + 0];
    y[lane] = xyz[3 * i + 1];
    z[lane] = xyz[3 * i + 2];
  }
  return v3(load_lanes(x), load_lanes(y), load_lanes(z));
}

/* Field `field` of each of the packet's points, `floats` floats a point. */
inline void probe_store(real_t v, int field, int floats, int first, int count,
                        __global float* out) {
  float lanes[FR_LANES];
  store_lanes(v, lanes);
  for (int lane = 0; lane < FR_LANES && first + lane < count; ++lane)
    out[(first + lane) * floats + field] = lanes[lane];
}

#if FR_SCENE_MATERIAL
__kernel void fr_probe_material(__constant const fr_frame_constants* fc,
                                __constant const scene_params_t* params,
                                __global const float* xyz, __global float* out, int count) {
  const int first = get_global_id(0) * FR_LANES;
  const vec3_t p = probe_points(xyz, first, count);
  const material_t m = scene_material(p, default_material(scene_surface(p, params), fc), params);
  const real_t fields[FR_MATERIAL_FLOATS] = {
      m.base_color.x,       m.base_color.y,       m.base_color.z, m.specular,
      m.roughness,          m.metalness,          m.transmission, m.ior,
      m.absorption.x,       m.absorption.y,       m.absorption.z, m.subsurface,
      m.subsurface_color.x, m.subsurface_color.y, m.subsurface_color.z,
      m.mean_free_path,     m.emission.x,         m.emission.y,   m.emission.z};
  for (int f = 0; f < FR_MATERIAL_FLOATS; ++f)
    probe_store(fields[f], f, FR_MATERIAL_FLOATS, first, count, out);
}
#endif

/* The surface function's albedo at given points, 3 floats a point: tests compare a scene's
 * colouring with an independent answer. */
__kernel void fr_probe_albedo(__constant const scene_params_t* params, __global const float* xyz,
                              __global float* out, int count) {
  const int first = get_global_id(0) * FR_LANES;
  const surface_t s = scene_surface(probe_points(xyz, first, count), params);
  probe_store(s.albedo.x, 0, 3, first, count, out);
  probe_store(s.albedo.y, 1, 3, first, count, out);
  probe_store(s.albedo.z, 2, 3, first, count, out);
}
