/* fractal_city.cl — a city of Menger-sponge towers on a grid, each of its own height, on a round
 * plain. Shapes from the DE library (fr/staging.cl); world y is up.
 *
 * The grid repeats one cell; a tower's height comes from a hash of its cell, so towers differ
 * and the repetition alone would not bound the distance to a neighbour's taller tower. The DE is
 * therefore the min of the own tower's distance and the distance to the cell's side walls, a
 * lower bound of the distance to anything in another cell. */
#include "fr/staging.cl"

#define CITY_CELL 1.6
#define CITY_HALF 0.5 /* a tower's half-width: 0.3 of the cell left as street */
#define CITY_RADIUS 6.0

/* Where p is in its cell's tower: the point in the frame of the tower's sponge cube it is
 * nearest (centred, CITY_HALF from each face), the tower's storeys (0: no tower) and the cell's
 * hash. */
inline vec3_t city_local(vec3_t p, real_t* storeys, lane_uint_t* hash, vec3_t* in_cell) {
  const real_t cx = rint(p.x / to_real(CITY_CELL)), cz = rint(p.z / to_real(CITY_CELL));
  *in_cell = v3(p.x - cx * to_real(CITY_CELL), p.y, p.z - cz * to_real(CITY_CELL));
  /* Storeys (1 to 4 sponge cubes) from the cell's hash, fewer towards the edge. */
  /* An integer hash of the cell, so that float and double kernels build the same city. */
  *hash = hash_uint(real_to_uint(cx + to_real(64)) * 73856093u ^
                    real_to_uint(cz + to_real(64)) * 19349663u);
  const real_t r = sqrt(cx * cx + cz * cz) * to_real(CITY_CELL);
  real_t n = uint_to_real(*hash & 3u) + 1;
  n = fmax(to_real(1), n - floor(r / to_real(2.5)));
  *storeys = lane_select(r > to_real(CITY_RADIUS - 1), to_real(0), n);
  /* Limited repetition of one sponge cube up the tower. */
  vec3_t q = p_translate(*in_cell, v3s(0, -1 + CITY_HALF, 0));
  q.y = q.y - to_real(2 * CITY_HALF) * clamp(rint(q.y / to_real(2 * CITY_HALF)), to_real(0), fmax(*storeys - 1, to_real(0)));
  return q;
}

inline real_t city_towers(vec3_t p, __constant const scene_params_t* params, real_t* trap) {
  real_t storeys;
  lane_uint_t hash;
  vec3_t in_cell;
  const vec3_t q = city_local(p, &storeys, &hash, &in_cell);
  real_t tower = de_sponge_at(q, v3s(0, 0, 0), CITY_HALF, PARAM(level), trap);
  tower = lane_select(storeys > 0, tower, to_real(1e3));
  /* Then the tower's own bound. */
  const real_t to_wall = to_real(CITY_CELL / 2) - fmax(fabs(in_cell.x), fabs(in_cell.z)) +
                         to_real(CITY_CELL / 2 - CITY_HALF);
  return fmin(tower, fmax(to_wall, to_real(0.02)));
}

inline real_t city_ground(vec3_t p) { return sd_floor_disc(p, -1.0, CITY_RADIUS + 0.5, 0.5); }

real_t scene_de(vec3_t p, __constant const scene_params_t* params) {
  real_t trap;
  /* Beyond the city's disc (plus its tallest tower) only the ground and its bound count. */
  const real_t to_city = fmax(sqrt(p.x * p.x + p.z * p.z) - to_real(CITY_RADIUS), p.y - to_real(3.2));
  real_t towers = city_towers(p, params, &trap);
  towers = lane_select(to_city > 0, fmax(to_city, towers), towers);
  return op_union(city_ground(p), towers);
}
