/* fr/recursive.cl — shapes made of scaled copies attached to their parent: a sphereflake (after
 * Eric Haines' Sphereflake, "A Proposal for Standard Graphics Environments", IEEE CG&A 7(11),
 * 1987, here with six children on the axes) and a 3D Pythagoras tree (after Albert Bosman's tree,
 * 1942: each branch carries four smaller branches, tilted outwards).
 *
 * Both are mirror-symmetric in the planes the folds reflect across, and each child's whole
 * subtree lies on its own side of those planes, so for a point in the folds' chamber the nearest
 * subtree is the chamber's own (reflecting a set towards the point never increases its distance):
 * following one child per level and taking the min of the distances met is exact. The walk stops
 * after `levels`; what it did not visit below is covered by the subtree's bounding ball, so the
 * result is a lower bound of the distance to the whole infinite shape. */
#include "fr/primitives.cl"
#include "fr/operators.cl"
#include "fr/folds.cl"

/* The sphereflake: the unit sphere with six children of radius child_scale touching it on the
 * axes, recursively. child_scale <= 0.4 keeps each subtree (within child_scale (1 + 2 k / (1 - k))
 * of its centre, k = child_scale) on its side of the chamber's mirrors. *trap receives the level
 * whose sphere was nearest, over levels (0 to 1), for colouring. */
real_t de_sphereflake(vec3_t p, int levels, scalar_t child_scale, real_t* trap) {
  const scalar_t k = child_scale;
  const scalar_t subtree = 1 + 2 * k / (1 - k); /* bounding radius of a unit sphere's subtree */
  vec3_t z = p;
  real_t scale = to_real(1);
  real_t d = sd_sphere(z, to_real(1));
  real_t nearest_level = to_real(0);
  for (int i = 1; i <= levels; ++i) {
    z = p_fold_menger(z);
    z = v3_scale(v3_sub(z, v3s(1 + k, 0, 0)), to_real(1 / k));
    scale *= to_real(k);
    const real_t here = (v3_length(z) - to_real(i == levels ? subtree : 1)) * scale;
    nearest_level = lane_select(here < d, to_real(i), nearest_level);
    d = fmin(d, here);
  }
  *trap = nearest_level / to_real(levels > 0 ? levels : 1);
  return d;
}

/* The Pythagoras tree: a trunk from the origin to (0, length, 0) of radius `width`, and at its
 * top four branches child_scale times as large, tilted by tilt (radians) towards +-x and +-z.
 * The folds (|x|, |z|, then x >= z) pick the branch leaning towards +x. *trap receives the level
 * of the nearest branch (0 to 1). */
real_t de_pythagoras_tree(vec3_t p, int levels, scalar_t child_scale, scalar_t tilt,
                          scalar_t width, real_t* trap) {
  const scalar_t k = child_scale;
  const scalar_t reach = 1 / (1 - k) + width; /* a subtree's extent from its base */
  vec3_t z = p;
  real_t scale = to_real(1);
  real_t d = sd_capsule(z, v3s(0, 0, 0), v3s(0, 1, 0), to_real(width));
  real_t nearest_level = to_real(0);
  for (int i = 1; i <= levels; ++i) {
    z = v3_sub(z, v3s(0, 1, 0));
    z = v3(fabs(z.x), z.y, fabs(z.z));
    const mask_t swap = z.z > z.x;
    const real_t t = z.x;
    z.x = lane_select(swap, z.z, z.x);
    z.z = lane_select(swap, t, z.z);
    z = p_rotate_z(z, -tilt); /* the branch (sin tilt, cos tilt, 0) onto +y */
    z = v3_scale(z, to_real(1 / k));
    scale *= to_real(k);
    const real_t here =
        (i == levels ? v3_length(z) - to_real(reach)
                     : sd_capsule(z, v3s(0, 0, 0), v3s(0, 1, 0), to_real(width))) * scale;
    nearest_level = lane_select(here < d, to_real(i), nearest_level);
    d = fmin(d, here);
  }
  *trap = nearest_level / to_real(levels > 0 ? levels : 1);
  return d;
}
