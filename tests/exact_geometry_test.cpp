// The Menger sponge and Sierpinski tetrahedron at level n are exact unions of boxes and
// tetrahedra. These tests cast every pixel's ray against that union in double on the CPU and
// compare with the renderer:
//  - where the exact geometry is hit, the renderer hits too, and not behind it (the folded DEs
//    are lower bounds, so the march cannot step through a surface);
//  - where the renderer hits, the ray passes within delta of the exact geometry, and the hit is
//    no nearer than where the ray enters the geometry grown by delta. delta = 3 eps(t): the march
//    stops once the DE is below eps, and the folded DEs under-estimate by a small factor near
//    fold planes (measured below 3 on these views).
// Growing a box or tetrahedron by pushing each face out by delta contains every point within
// delta of it, so "the ray misses the grown union" proves "the ray passes farther than delta".
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <limits>

namespace fr {
namespace {

using glm::dvec3;
constexpr double kNone = std::numeric_limits<double>::infinity();

// Entry distance of the ray into the axis-aligned box centre +- half (0 if it starts inside).
double box_entry(dvec3 o, dvec3 d, dvec3 centre, double half) {
  double t0 = 0, t1 = kNone;
  for (int a = 0; a < 3; ++a) {
    const double lo = centre[a] - half, hi = centre[a] + half;
    if (d[a] == 0) {
      if (o[a] < lo || o[a] > hi) return kNone;
      continue;
    }
    double ta = (lo - o[a]) / d[a], tb = (hi - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return kNone;
  }
  return t0;
}

// The level-n sponge in the cube centre +- half, each leaf cube grown by `grow`.
double menger_entry(dvec3 o, dvec3 d, dvec3 centre, double half, int level, double grow) {
  if (box_entry(o, d, centre, half + grow) == kNone) return kNone;
  if (level == 0) return box_entry(o, d, centre, half + grow);
  double best = kNone;
  const double third = half / 3;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        if ((i == 0) + (j == 0) + (k == 0) >= 2) continue;  // the removed cross
        const dvec3 c = centre + 2 * third * dvec3(i, j, k);
        best = std::min(best, menger_entry(o, d, c, third, level - 1, grow));
      }
  return best;
}

using Tetra = std::array<dvec3, 4>;

// Entry distance into the tetrahedron with each face pushed out by `grow`.
double tetra_entry(dvec3 o, dvec3 d, const Tetra& v, double grow) {
  double t0 = 0, t1 = kNone;
  for (int f = 0; f < 4; ++f) {
    const dvec3 a = v[(f + 1) % 4], b = v[(f + 2) % 4], c = v[(f + 3) % 4];
    dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(n, v[f] - a) > 0) n = -n;  // outward: away from the opposite vertex
    const double offset = glm::dot(n, a) + grow;
    const double denom = glm::dot(n, d), dist = offset - glm::dot(n, o);  // inside: dist >= 0
    if (denom == 0) {
      if (dist < 0) return kNone;
      continue;
    }
    const double t = dist / denom;
    if (denom > 0)
      t1 = std::min(t1, t);
    else
      t0 = std::max(t0, t);
    if (t0 > t1) return kNone;
  }
  return t0;
}

double sierpinski_entry(dvec3 o, dvec3 d, const Tetra& v, int level, double grow) {
  const dvec3 centre = (v[0] + v[1] + v[2] + v[3]) / 4.0;
  const double radius = glm::length(v[0] - centre) + 3 * grow;
  // Cheap sphere rejection before the recursion.
  const dvec3 oc = o - centre;
  const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - radius * radius;
  if (b * b - c < 0 || (b > 0 && c > 0)) return kNone;
  if (level == 0) return tetra_entry(o, d, v, grow);
  double best = kNone;
  for (int i = 0; i < 4; ++i) {
    Tetra sub;
    for (int j = 0; j < 4; ++j) sub[j] = (v[i] + v[j]) / 2.0;
    best = std::min(best, sierpinski_entry(o, d, sub, level - 1, grow));
  }
  return best;
}

struct Comparison {
  int exact_hits = 0, rendered_hits = 0, checked = 0;
  int missed = 0, behind = 0, stray = 0, early = 0;
};

template <typename Entry>
Comparison compare(const std::string& id, int level, Entry entry) {
  auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + ".so"));
  SceneState state = make_default_state(scene->info);
  state.params[scene->info.find_param("iterations")].v[0] = level;
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  EXPECT_TRUE(instance->update(state, 0, &error)) << error;
  RenderSettings settings;
  settings.width_px = 96;
  settings.height_px = 96;
  const FrameImage img = Renderer(test::runtime()).render(scene->info, state, settings, true);
  const CameraRays rays = make_camera_rays(state.camera, 96, 96);

  Comparison c;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      const size_t i = static_cast<size_t>(y) * 96 + x;
      const dvec3 d = camera_ray_dir(rays, x, y);
      const double t_exact = entry(rays.eye, d, 0.0);
      const bool rendered = std::isfinite(img.depth[i]);
      const double t = img.depth[i];
      const double delta =
          3 * settings.hit_threshold_k * rays.pixel_angle_rad * (rendered ? t : 1.0);
      const double slack = 1e-4 * glm::length(rays.eye);  // float rays and depths
      c.exact_hits += t_exact != kNone;
      c.rendered_hits += rendered;
      if (t_exact != kNone && !rendered) ++c.missed;
      if (t_exact != kNone && rendered && t > t_exact + slack) ++c.behind;
      if (rendered) {
        const double t_grown = entry(rays.eye, d, delta);
        if (t_grown == kNone)
          ++c.stray;
        else if (t < t_grown - slack)
          ++c.early;
        ++c.checked;
      }
    }
  return c;
}

void expect_matches(const Comparison& c, const char* what) {
  EXPECT_GT(c.exact_hits, 96 * 96 / 20) << what << ": the view should show the object";
  EXPECT_EQ(c.behind, 0) << what << ": pixels behind the exact surface";
  EXPECT_EQ(c.stray, 0) << what
                        << ": pixels hit where the exact geometry (grown by delta) has none";
  EXPECT_EQ(c.early, 0) << what << ": pixels nearer than the grown geometry";
  // A ray that grazes an edge exactly can fall either side in float; allow a handful.
  EXPECT_LE(c.missed, 96 * 96 / 500) << what << ": exact hits the renderer missed";
}

TEST(ExactGeometry, MengerSpongeLevel3) {
  const auto c = compare("menger", 3, [](dvec3 o, dvec3 d, double grow) {
    return menger_entry(o, d, dvec3(0), 1.0, 3, grow);
  });
  expect_matches(c, "Menger level 3");
  RecordProperty("missed", c.missed);
}

TEST(ExactGeometry, MengerSpongeLevel1) {
  const auto c = compare("menger", 1, [](dvec3 o, dvec3 d, double grow) {
    return menger_entry(o, d, dvec3(0), 1.0, 1, grow);
  });
  expect_matches(c, "Menger level 1");
}

TEST(ExactGeometry, SierpinskiTetrahedronLevel5) {
  const Tetra base = {dvec3(1, 1, 1), dvec3(1, -1, -1), dvec3(-1, 1, -1), dvec3(-1, -1, 1)};
  const auto c = compare("sierpinski", 5, [&](dvec3 o, dvec3 d, double grow) {
    return sierpinski_entry(o, d, base, 5, grow);
  });
  expect_matches(c, "Sierpinski level 5");
  RecordProperty("missed", c.missed);
}

}  // namespace
}  // namespace fr
