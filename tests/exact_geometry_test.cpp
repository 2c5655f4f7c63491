// The Menger sponge and Sierpinski tetrahedron at level n are exact unions of boxes and
// tetrahedra. Two kinds of check against that union, computed in double on the CPU:
//
// Point-wise: the scene's DE (on the device, in double, through the probe kernel) at a few
// thousand points is never larger than the exact distance to the union. A DE that over-estimates
// lets the march step through surfaces; a rendered view can hide it (over-relaxation's fallback
// and grazing views absorb small excesses), this cannot: with the DE scaled by 1.02 the check
// fails at hundreds of points (MengerDeIsALowerBound's mutation case).
//
// Rendered: every pixel's ray is cast against the union and compared with the renderer:
//  - where the exact geometry is hit, the renderer hits too, and not behind it (the folded DEs
//    are lower bounds, so the march cannot step through a surface);
//  - where the renderer hits, the ray passes within delta of the exact geometry, and the hit is
//    no nearer than where the ray enters the geometry grown by delta. delta = 3 eps(t): the march
//    stops once the DE is below eps, and the folded DEs under-estimate by a small factor near
//    fold planes (measured below 3 on these views).
// Growing a box or tetrahedron by pushing each face out by delta contains every point within
// delta of it, so "the ray misses the grown union" proves "the ray passes farther than delta".
// Besides the scenes' oblique default views, a face-on view: there the DE is exact in front of
// the faces, so a march that over-steps lands behind the surface (render.step_scale = 1.02
// fails it; the mutation case below keeps that true).
#include "exact_shapes.hpp"
#include "plugin/scene_instance.hpp"
#include "render/camera.hpp"
#include "render/de_probe.hpp"
#include "render/renderer.hpp"
#include "test_support.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

namespace fr {
namespace {

using glm::dvec3;
using test::box_entry;
using test::kNone;
using test::menger_entry;

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

// --- Exact distances from a point (0 inside) -------------------------------------------------

double box_distance(dvec3 p, dvec3 centre, double half) {
  const dvec3 outside = glm::max(glm::abs(p - centre) - dvec3(half), dvec3(0));
  return glm::length(outside);
}

// Distance to the level-n sponge in the cube centre +- half. The sponge lies inside its cube,
// so the cube's distance bounds every sub-cube's from below and prunes the recursion.
double menger_distance(dvec3 p, dvec3 centre, double half, int level, double best = kNone) {
  const double bound = box_distance(p, centre, half);
  if (bound >= best) return best;
  if (level == 0) return bound;
  const double third = half / 3;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        if ((i == 0) + (j == 0) + (k == 0) >= 2) continue;
        best = menger_distance(p, centre + 2 * third * dvec3(i, j, k), third, level - 1, best);
      }
  return best;
}

// Closest point to p on the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
dvec3 closest_on_triangle(dvec3 p, dvec3 a, dvec3 b, dvec3 c) {
  const dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double tetra_distance(dvec3 p, const Tetra& v) {
  bool inside = true;
  double best = kNone;
  for (int f = 0; f < 4; ++f) {
    const dvec3 a = v[(f + 1) % 4], b = v[(f + 2) % 4], c = v[(f + 3) % 4];
    dvec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, v[f] - a) > 0) n = -n;
    inside &= glm::dot(n, p - a) <= 0;
    best = std::min(best, glm::length(p - closest_on_triangle(p, a, b, c)));
  }
  return inside ? 0 : best;
}

double sierpinski_distance(dvec3 p, const Tetra& v, int level, double best = kNone) {
  const dvec3 centre = (v[0] + v[1] + v[2] + v[3]) / 4.0;
  const double bound = glm::length(p - centre) - glm::length(v[0] - centre);
  if (bound >= best) return best;
  if (level == 0) return std::min(best, tetra_distance(p, v));
  for (int i = 0; i < 4; ++i) {
    Tetra sub;
    for (int j = 0; j < 4; ++j) sub[j] = (v[i] + v[j]) / 2.0;
    best = sierpinski_distance(p, sub, level - 1, best);
  }
  return best;
}

const Tetra kSierpinskiBase = {dvec3(1, 1, 1), dvec3(1, -1, -1), dvec3(-1, 1, -1),
                               dvec3(-1, -1, 1)};

// A scene's DE scaled by `factor`: the mutation the lower-bound check must catch.
SceneInfo with_scaled_de(SceneInfo info, double factor) {
  info.de_source = "#define scene_de scene_de_unscaled\n" + info.de_source +
                   "\n#undef scene_de\n"
                   "real_t scene_de(vec3_t p, __constant const scene_params_t* params) {\n"
                   "  return (real_t)" +
                   std::to_string(factor) + " * scene_de_unscaled(p, params);\n}\n";
  return info;
}

struct BoundCheck {
  int points = 0, near_surface = 0, violations = 0;
  double worst_ratio = 0;  // largest DE / exact distance among points outside the geometry
  std::string first;       // where the first violation was
};

// DE <= exact distance at points spread through the bounding cube and concentrated near the
// surface (where a relative over-estimate matters most), in double on the device. Tolerance:
// 1e-9 absolute (double rounding of the folds) plus 1e-6 relative.
template <typename Distance>
BoundCheck check_lower_bound(const SceneInfo& info, int level, Distance exact) {
  std::vector<fr_value> values = make_default_state(info).params;
  values[info.find_param("iterations")].v[0] = level;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> u(-1.4f, 1.4f);
  std::vector<std::array<float, 3>> points;
  std::vector<double> distances;
  while (points.size() < 3000) {
    const std::array<float, 3> q{u(rng), u(rng), u(rng)};
    const double d = exact(dvec3(q[0], q[1], q[2]));
    // Keep every point near the surface and one in four of the rest.
    if (d > 0.05 && rng() % 4 != 0) continue;
    points.push_back(q);
    distances.push_back(d);
  }
  const auto de = probe_de(test::runtime(), info, values, points, 16, Precision::Double);
  BoundCheck c;
  for (size_t i = 0; i < points.size(); ++i) {
    ++c.points;
    c.near_surface += distances[i] < 0.05;
    if (distances[i] > 1e-6) c.worst_ratio = std::max(c.worst_ratio, de[i] / distances[i]);
    if (de[i] > distances[i] * (1 + 1e-6) + 1e-9) {
      if (c.violations++ == 0)
        c.first = "DE " + std::to_string(de[i]) + " > exact " + std::to_string(distances[i]) +
                  " at (" + std::to_string(points[i][0]) + ", " + std::to_string(points[i][1]) +
                  ", " + std::to_string(points[i][2]) + ")";
    }
  }
  return c;
}

struct Comparison {
  int exact_hits = 0, rendered_hits = 0, checked = 0;
  int missed = 0, behind = 0, stray = 0, early = 0;
};

// How a view is rendered: the scene's default camera unless `eye` is set, looking at the origin.
struct View {
  std::optional<dvec3> eye;
  float step_scale = 1.0f;
};

template <typename Entry>
Comparison compare(const std::string& id, int level, Entry entry, const View& view = {}) {
  auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  SceneState state = make_default_state(scene->info);
  state.params[scene->info.find_param("iterations")].v[0] = level;
  std::string error;
  auto instance = SceneInstance::create(scene, &error);
  EXPECT_TRUE(instance->update(state, 0, &error)) << error;
  if (view.eye)
    for (int a = 0; a < 3; ++a) {
      state.camera.eye[a] = (*view.eye)[a];
      state.camera.target[a] = 0;
    }
  RenderSettings settings;
  settings.width_px = 96;
  settings.height_px = 96;
  settings.step_scale = view.step_scale;
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

auto menger_level(int level) {
  return [level](dvec3 o, dvec3 d, double grow) {
    return menger_entry(o, d, dvec3(0), 1.0, level, grow);
  };
}
auto sierpinski_level(int level) {
  return [level](dvec3 o, dvec3 d, double grow) {
    return sierpinski_entry(o, d, kSierpinskiBase, level, grow);
  };
}

TEST(ExactGeometry, MengerSpongeLevel3) {
  const auto c = compare("menger", 3, menger_level(3));
  expect_matches(c, "Menger level 3");
  RecordProperty("missed", c.missed);
}

TEST(ExactGeometry, MengerSpongeLevel1) {
  expect_matches(compare("menger", 1, menger_level(1)), "Menger level 1");
}

TEST(ExactGeometry, SierpinskiTetrahedronLevel5) {
  const auto c = compare("sierpinski", 5, sierpinski_level(5));
  expect_matches(c, "Sierpinski level 5");
  RecordProperty("missed", c.missed);
}

// Face-on: the camera looks straight at the sponge's +z face (the default camera's up is y).
TEST(ExactGeometry, MengerSpongeFaceOn) {
  expect_matches(compare("menger", 3, menger_level(3), View{dvec3(0.05, 0.1, 3.5)}),
                 "Menger level 3, face-on");
}

// Face-on to the Sierpinski face opposite the vertex (1, 1, 1): its outward normal is -(1,1,1).
TEST(ExactGeometry, SierpinskiFaceOn) {
  expect_matches(compare("sierpinski", 5, sierpinski_level(5), View{dvec3(-2.1, -2.0, -2.2)}),
                 "Sierpinski level 5, face-on");
}

// The mutation the face-on view exists for: a march over-stepping by 2% (what a DE 2% too large
// does) must be caught, by pixels behind the exact surface. (Not so for the Sierpinski face-on
// view: there the folded DE is 0.96 to 0.9986 of the exact distance, measured at 200 points in
// front of the face, so 2% more stays a lower bound; its point-wise check catches the mutation.)
TEST(ExactGeometry, FaceOnViewCatchesATwoPercentOverstep) {
  const auto m = compare("menger", 3, menger_level(3), View{dvec3(0.05, 0.1, 3.5), 1.02f});
  EXPECT_GT(m.behind, 96 * 96 / 100) << "Menger: the over-step went unseen";  // measured: 172
  RecordProperty("pixels_behind_with_2_percent_overstep", m.behind);
}

// The point-wise check at two levels, and its mutation: the same DE 2% too large must fail at a
// tenth of the points or more.
template <typename Exact>
void expect_lower_bound(const std::string& id, std::array<int, 2> levels, Exact exact,
                        int min_near_surface) {
  auto scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  ASSERT_TRUE(scene);
  for (int level : levels) {
    auto at_level = [&](dvec3 p) { return exact(p, level); };
    const BoundCheck c = check_lower_bound(scene->info, level, at_level);
    EXPECT_EQ(c.violations, 0) << id << " level " << level << ": " << c.first;
    EXPECT_GT(c.near_surface, min_near_surface) << id << " level " << level;
    testing::Test::RecordProperty(id + "_worst_ratio_level_" + std::to_string(level),
                                  std::to_string(c.worst_ratio));
    const BoundCheck m = check_lower_bound(with_scaled_de(scene->info, 1.02), level, at_level);
    EXPECT_GT(m.violations, c.points / 10)
        << id << " level " << level << ": 2% over-estimate unseen";
  }
}

TEST(ExactGeometry, MengerDeIsALowerBound) {
  expect_lower_bound(
      "menger", {1, 3}, [](dvec3 p, int level) { return menger_distance(p, dvec3(0), 1.0, level); },
      1000);
}

TEST(ExactGeometry, SierpinskiDeIsALowerBound) {
  expect_lower_bound(
      "sierpinski", {1, 5},
      [](dvec3 p, int level) { return sierpinski_distance(p, kSierpinskiBase, level); }, 400);
}

// The exact distances themselves, at points whose answer follows from the geometry by hand.
TEST(ExactGeometry, ReferenceDistancesByHand) {
  // Menger level 1 keeps the 8 corner and 12 edge cubes of the 3x3x3 grid: from the centre the
  // nearest solid is an edge cube's edge at (1/3, 1/3, 0); 1 unit beyond the face centre it is
  // the tunnel's rim at (1/3, 0, 1). At level 3, (0.99, 0.99, 0.99) lies in a corner cube at
  // every level, and (1, 0.99, 0.99) likewise on the x = 1 face.
  EXPECT_NEAR(menger_distance(dvec3(0, 0, 0), dvec3(0), 1, 1), std::sqrt(2.0) / 3, 1e-12);
  EXPECT_NEAR(menger_distance(dvec3(0, 0, 2), dvec3(0), 1, 1), std::hypot(1.0 / 3, 1.0), 1e-12);
  EXPECT_EQ(menger_distance(dvec3(0.99, 0.99, 0.99), dvec3(0), 1, 3), 0);
  EXPECT_NEAR(menger_distance(dvec3(3, 0.99, 0.99), dvec3(0), 1, 3), 2, 1e-12);
  // Sierpinski: beyond the vertex (1,1,1) along the diagonal, the vertex is nearest.
  EXPECT_NEAR(sierpinski_distance(dvec3(2, 2, 2), kSierpinskiBase, 4), std::sqrt(3.0), 1e-12);
  EXPECT_EQ(sierpinski_distance(dvec3(0.99, 0.99, 0.99), kSierpinskiBase, 4), 0);
  // Level 1 leaves the octahedron around the centre empty: from the centre the nearest solid
  // is a face of the removed octahedron |x|+|y|+|z| = 1, at 1/sqrt 3.
  EXPECT_NEAR(sierpinski_distance(dvec3(0), kSierpinskiBase, 1), 1 / std::sqrt(3.0), 1e-12);
}

}  // namespace
}  // namespace fr
