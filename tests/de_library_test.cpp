// The DE helper library (kernels/de/) against analytic values at sample points, evaluated
// through the same OpenCL path the renderer uses (the probe kernel), at lane widths 1, 16 and 64,
// checking every lane.
#include "render/de_probe.hpp"
#include "test_support.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

namespace fr {
namespace {

struct Case {
  const char* expression;  // OpenCL, in terms of p; evaluated at each point
  std::array<float, 3> point;
  double expected;  // computed by hand from the shape's geometry
};

// All cases of one call go into one DE: the probe point (k, 0, 0) stands for case k, whose point
// comes from a table in the source, and the result is case k's expression at that point. The
// points are laid out so that, at width 16, every case is evaluated in every lane, next to
// different cases in the other lanes (work-item w, lane l holds case (w + l) mod N), and every
// lane is read back and checked. Mutation caught: a store that writes lane 0 into every lane
// (vstore16((float16)(v.s0), ...) in the prelude) fails every case in lanes 1-15.
void check(const char* include, const std::vector<Case>& cases) {
  const int n = static_cast<int>(cases.size());
  std::ostringstream src;
  src << std::hexfloat;  // the points' exact float values; integers stay decimal
  src << "#include \"" << include << "\"\n";
  src << "real_t scene_de(vec3_t q, __constant const scene_params_t* params) {\n"
      << "  vec3_t p = v3s(0, 0, 0);\n";
  for (int k = 0; k < n; ++k)
    src << "  p = v3_select(q.x == (real_t)" << k << ", v3s(" << double(cases[k].point[0]) << ", "
        << double(cases[k].point[1]) << ", " << double(cases[k].point[2]) << "), p);\n";
  src << "  real_t result = (real_t)0;\n";
  for (int k = 0; k < n; ++k)
    src << "  result = lane_select(q.x == (real_t)" << k << ", (" << cases[k].expression
        << "), result);\n";
  src << "  return result;\n}\n";
  SceneInfo info;
  info.id = "library_probe";
  info.de_source_name = "probe.cl";
  info.de_source = src.str();

  std::vector<std::array<float, 3>> points;
  std::vector<int> case_of;
  for (int w = 0; w < std::max(n, 1); ++w)
    for (int lane = 0; lane < 16; ++lane) {
      const int k = (w + lane) % n;
      points.push_back({static_cast<float>(k), 0, 0});
      case_of.push_back(k);
    }
  for (int lanes : {1, 16, 64}) {
    const auto got = probe_de(test::runtime(), info, {}, points, lanes);
    for (size_t i = 0; i < points.size(); ++i) {
      const Case& c = cases[case_of[i]];
      EXPECT_NEAR(got[i], c.expected, 2e-6 + 2e-6 * std::abs(c.expected))
          << c.expression << " at (" << c.point[0] << ", " << c.point[1] << ", " << c.point[2]
          << "), width " << lanes << ", lane " << i % static_cast<size_t>(lanes);
    }
  }
}

const double kSqrt2 = std::sqrt(2.0), kSqrt3 = std::sqrt(3.0);

TEST(DeLibrary, Primitives) {
  check("fr/primitives.cl",
        {
            {"sd_sphere(p, 1)", {3, 0, 0}, 2},
            {"sd_sphere(p, 1)", {0, 0, 0}, -1},
            {"sd_box(p, v3s(1, 1, 1))", {2, 0, 0}, 1},               // face
            {"sd_box(p, v3s(1, 1, 1))", {2, 2, 0}, kSqrt2},          // edge
            {"sd_box(p, v3s(1, 1, 1))", {2, 2, 2}, kSqrt3},          // corner
            {"sd_box(p, v3s(1, 2, 3))", {0, 0, 0}, -1},              // inside: nearest face
            {"sd_round_box(p, v3s(1, 1, 1), 0.25f)", {2, 0, 0}, 1},  // faces stay in place
            {"sd_round_box(p, v3s(1, 1, 1), 0.25f)", {2, 2, 0}, std::hypot(1.25, 1.25) - 0.25},
            {"sd_torus(p, 2, 0.5f)", {2, 0, 0}, -0.5},  // tube centre
            {"sd_torus(p, 2, 0.5f)", {0, 0, 0}, 1.5},   // hole centre
            {"sd_torus(p, 2, 0.5f)", {0, 3, 0}, std::hypot(2.0, 3.0) - 0.5},
            {"sd_plane(p, v3s(0, 1, 0), -1)", {5, 2, 7}, 3},
            {"sd_capsule(p, v3s(0, 0, 0), v3s(0, 2, 0), 0.5f)", {1, 1, 0}, 0.5},
            {"sd_capsule(p, v3s(0, 0, 0), v3s(0, 2, 0), 0.5f)", {0, 4, 0}, 1.5},
            {"sd_cylinder(p, 1, 2)", {3, 0, 0}, 2},
            {"sd_cylinder(p, 1, 2)", {0, 5, 0}, 3},
            {"sd_cylinder(p, 1, 2)", {2, 3, 0}, kSqrt2},
            {"sd_cylinder(p, 1, 2)", {0, 0, 0}, -1},
            // The tetrahedron (s = 1) has its face opposite (1,1,1) on x + y + z = -1, at distance
            // 1/sqrt 3 from the origin; a point on the axis beyond it is exact.
            {"de_tetrahedron(p, 1)", {-1, -1, -1}, (3.0 - 1.0) / kSqrt3},
            {"de_tetrahedron(p, 1)", {0, 0, 0}, -1 / kSqrt3},
            {"de_octahedron(p, 1)", {1, 1, 1}, 2 / kSqrt3},
            {"de_octahedron(p, 1)", {0, 0, 0}, -1 / kSqrt3},
        });
}

TEST(DeLibrary, OperatorsAndTransforms) {
  check("fr/operators.cl",
        {
            {"op_union(to_real(0.3f), to_real(-0.2f))", {0, 0, 0}, -0.2},
            {"op_intersect(to_real(0.3f), to_real(-0.2f))", {0, 0, 0}, 0.3},
            {"op_subtract(to_real(0.3f), to_real(-0.2f))", {0, 0, 0}, -0.2},  // b minus a
            {"op_subtract(to_real(-0.3f), to_real(-0.2f))", {0, 0, 0}, 0.3},
            // Smooth versions equal the sharp ones when the inputs differ by at least k...
            {"op_smooth_union(to_real(1), to_real(3), 0.5f)", {0, 0, 0}, 1},
            {"op_smooth_intersect(to_real(1), to_real(3), 0.5f)", {0, 0, 0}, 3},
            {"op_smooth_subtract(to_real(1), to_real(3), 0.5f)", {0, 0, 0}, 3},
            // ...and at equal inputs deviate by k/4: smin(a, a) = a - k/4, smax(a, a) = a + k/4.
            {"op_smooth_union(to_real(1), to_real(1), 0.5f)", {0, 0, 0}, 1 - 0.125},
            {"op_smooth_intersect(to_real(1), to_real(1), 0.5f)", {0, 0, 0}, 1 + 0.125},
            {"op_smooth_subtract(to_real(-1), to_real(1), 0.5f)", {0, 0, 0}, 1 + 0.125},
            // Domain transforms: a unit sphere moved, rotated, scaled, repeated.
            {"v3_length(p_translate(p, v3s(1, 2, 3))) - 1", {1, 2, 5}, 1},
            {"p_rotate_z(p, M_PI_F / 2).x", {0, 1, 0}, 1},  // the shape turned by +90 degrees
            {"p_rotate_x(p, M_PI_F / 2).y", {0, 0, 1}, 1},
            {"p_rotate_y(p, M_PI_F / 2).z", {1, 0, 0}, 1},
            {"op_rescale(v3_length(p_scale(p, 2)) - 1, 2)", {5, 0, 0}, 3},  // sphere of radius 2
            {"v3_length(p_repeat(p, v3s(4, 0, 0))) - 1", {8.5f, 0, 0}, -0.5},
            {"v3_length(p_repeat(p, v3s(4, 0, 0))) - 1", {0, 0, 3}, 2},  // y, z not repeated
            {"p_twist(p, M_PI_F / 2).x", {1, 1, 0}, 0},  // at height 1, a quarter turn
            {"p_bend(p, 0).y", {3, 2, 1}, 2},
        });
}

TEST(DeLibrary, Folds) {
  check("fr/folds.cl",
        {
            {"p_fold_abs(p).y", {1, -2, 3}, 2},
            {"p_fold_plane(p, v3s(1, 0, 0), 1).x", {-1, 0, 0}, 3},  // mirrored across x = 1
            {"p_fold_plane(p, v3s(1, 0, 0), 1).x", {2, 0, 0}, 2},   // already on the positive side
            {"p_fold_box(p, 1).x", {1.5f, 0, 0}, 0.5},              // 2 * 1 - 1.5
            {"p_fold_box(p, 1).y", {0, 0.5f, 0}, 0.5},
            {"p_fold_menger(p).x", {-1, 3, -2}, 3},  // |.| sorted: 3, 2, 1
            {"p_fold_menger(p).y", {-1, 3, -2}, 2},
            {"p_fold_menger(p).z", {-1, 3, -2}, 1},
            {"p_fold_sierpinski(p).x", {-1, -1, 1}, 1},  // vertex (-1,-1,1) folds onto (1,1,1)
            {"p_fold_sierpinski(p).y", {-1, -1, 1}, 1},
            {"p_fold_sierpinski(p).z", {-1, -1, 1}, 1},
            {"p_fold_sierpinski(p).x", {0.5f, 0.2f, 0.1f}, 0.5},  // already in the domain
        });
  // The box fold on two axes leaves z alone (Amazing Surf).
  check("fr/mandelbox.cl", {
                               {"p_fold_box_xy(p, 1).x", {3, -2.5f, 7}, -1},  // 2 * 1 - 3
                               {"p_fold_box_xy(p, 1).y", {3, -2.5f, 7}, 0.5},  // -2 + 2.5
                               {"p_fold_box_xy(p, 1).z", {3, -2.5f, 7}, 7},
                           });
  // The icosahedral fold against its chamber's image computed by reflecting across any of the 15
  // mirrors that separates the point from (0.1, 0.35, 1) until none does (in double, by hand with
  // a script, not with the kernel's three-round sequence); a point in the chamber stays put, a
  // cyclic permutation of coordinates is a symmetry. Rotations: (1, 0, 0) turned by pi/2 about z.
  check("fr/kifs.cl",
        {
            {"p_fold_icosahedral(p).x", {0.9f, -0.2f, 0.3f}, 0.145491503},
            {"p_fold_icosahedral(p).y", {0.9f, -0.2f, 0.3f}, 0.266311896},
            {"p_fold_icosahedral(p).z", {0.9f, -0.2f, 0.3f}, 0.920820393},
            {"p_fold_icosahedral(p).x", {-0.5f, 0.4f, -0.3f}, 0.116311896},
            {"p_fold_icosahedral(p).y", {-0.5f, 0.4f, -0.3f}, 0.019098301},
            {"p_fold_icosahedral(p).z", {-0.5f, 0.4f, -0.3f}, 0.697213595},
            {"p_fold_icosahedral(p).x", {0.2f, 0.8f, 0.1f}, 0.1},
            {"p_fold_icosahedral(p).z", {0.2f, 0.8f, 0.1f}, 0.8},
            {"p_fold_icosahedral(p).y", {0.1f, 0.35f, 1}, 0.35},
            {"p_rotate_xyz(p, 0, 0, 1.5707963267948966).y", {1, 0, 0}, -1},
            {"p_rotate_xyz(p, 1.5707963267948966, 0, 0).z", {0, 1, 0}, -1},
            {"p_rotate_xyz(p, 0, 0, 0).x", {0.25f, 0, 0}, 0.25},
        });
  // Inversion: a unit sphere about (3, 0, 0) inverted in the unit sphere is the sphere about
  // (0.375, 0, 0) of radius 0.125 (the images of x = 2 and x = 4); on the axis the bound is the
  // exact distance to it: 0.5 from (1, 0, 0), 0 from its point (0.5, 0, 0).
  check("fr/operators.cl",
        {
            {"p_invert_sphere(p, v3s(0, 0, 0), 4).x", {1, 0, 0}, 4},
            {"p_invert_sphere(p, v3s(0, 0, 0), 4).x", {2, 0, 0}, 2},
            {"p_invert_sphere(p, v3s(1, 0, 0), 1).y", {1, 0.5f, 0}, 2},
            {"({ vec3_t q = p_invert_sphere(p, v3s(0, 0, 0), 1); "
             "op_invert_de(v3_length(v3_sub(q, v3s(3, 0, 0))) - 1, v3_length(p), 1); })",
             {1, 0, 0},
             0.5},
            {"({ vec3_t q = p_invert_sphere(p, v3s(0, 0, 0), 1); "
             "op_invert_de(v3_length(v3_sub(q, v3s(3, 0, 0))) - 1, v3_length(p), 1); })",
             {0.5f, 0, 0},
             0},
        });
  // Cantor dust, one level at scale 3: the nearest corner cube is [1/3, 1]^3 (by hand: from
  // (2, 0, 0) the offsets are 1, 1/3, 1/3; from the centre, the corner (1/3, 1/3, 1/3)).
  check("fr/cantor.cl",
        {
            {"({ real_t t; de_cantor_dust(p, 1, 3, &t); })", {2, 0, 0}, std::sqrt(1 + 2.0 / 9)},
            {"({ real_t t; de_cantor_dust(p, 1, 3, &t); })", {0, 0, 0}, kSqrt3 / 3},
            {"({ real_t t; de_cantor_dust(p, 2, 3, &t); })", {2, 0, 0}, std::sqrt(1 + 2.0 / 9)},
        });
  // The sphereflake along an axis: its chain of spheres reaches 1 + 2k / (1 - k) = 2 for
  // k = 1/3, so from (0, 3, 0) the distance is 1 at every depth (the last level's bounding ball
  // touches the same point). The tree's trunk from below: 1 - width.
  check("fr/recursive.cl",
        {
            {"({ real_t t; de_sphereflake(p, 1, 1.0f / 3, &t); })", {0, 3, 0}, 1},
            {"({ real_t t; de_sphereflake(p, 4, 1.0f / 3, &t); })", {0, 3, 0}, 1},
            {"({ real_t t; de_sphereflake(p, 4, 1.0f / 3, &t); })", {0, 0, 0}, -1},
            {"({ real_t t; de_pythagoras_tree(p, 3, 0.5f, 0.7f, 0.1f, &t); })", {0, -1, 0}, 0.9},
        });
  // The smooth Menger sponge with no smoothing is the sponge itself (its last fold's sign is
  // undone by the box's symmetry); with smoothing, outside the cube it is still a lower bound of
  // the cube's distance (the sponge lies in the cube).
  check("fr/menger.cl",
        {
            {"({ real_t t; de_menger_smooth(p, 3, 3, v3s(1, 1, 1), 0, &t) - "
             "de_menger(p, 3, 3, v3s(1, 1, 1), 0, &t); })",
             {0.7f, 0.2f, 1.3f},
             0},
            {"({ real_t t; de_menger_smooth(p, 3, 3, v3s(1, 1, 1), 0, &t) - "
             "de_menger(p, 3, 3, v3s(1, 1, 1), 0, &t); })",
             {-0.45f, 0.05f, 0.61f},
             0},
            {"({ real_t t; fmin(de_menger_smooth(p, 4, 3, v3s(1, 1, 1), 0.01f, &t), 1.0f); })",
             {3, 0, 0},
             1},
        });
  // The sphere fold: inside the minimum radius scale by (fixed/min)^2 (here 4).
  check("fr/folds.cl",
        {{"({ real_t dr = 1; vec3_t q = p_fold_sphere(p, 0.5f, 1, &dr); q.x * 10 + dr; })",
          {0.25f, 0, 0},
          1 * 10 + 4}});
}

}  // namespace
// The scene guide lists every public function of the DE library with its exact signature: the
// signatures are read from kernels/de/*.cl here, so a function added or changed there without the
// guide fails this test.
TEST(DeLibrary, GuideListsEverySignature) {
  std::ifstream guide_file(std::string(SOURCE_DIR) + "/sdk/docs/writing-a-scene.md");
  const std::string guide((std::istreambuf_iterator<char>(guide_file)), {});
  ASSERT_FALSE(guide.empty());
  // Helpers the library uses internally, not meant for scenes.
  const std::set<std::string> internal = {"pow_int",
                                          "unit_complex_pow_int",
                                          "mandelbulb_pow_int",
                                          "mandelbulb_pow_real",
                                          "mandelbox_iterate",
                                          "kifs_iterate",
                                          "bulb_iterate",
                                          "kleinian_separation",
                                          "mandelbrot_distance_bound",
                                          "smooth_order",
                                          "sort_pair",
                                          "bristor_jacobian_times",
                                          "hybrid_rotate",
                                          "mb2_fold",
                                          "mb2_component",
                                          "mb2_with_component",
                                          "mb2_rotate_back",
                                          "dd_order",
                                          "dd_reflect_pair",
                                          "mandelbox_dd_iterate",
                                          "menger_step",
                                          "dd_unit_complex_pow_int",
                                          "dd_mandelbulb_whole"};
  size_t found = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(SOURCE_DIR) + "/kernels/de")) {
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), {});
    // A definition starts a line with a return type (after an optional "inline"), and its
    // parameter list may span lines; whitespace runs are joined to one space, as in the guide.
    // (Parsed by hand: std::regex trips GCC 12's -Wmaybe-uninitialized in the sanitizer build.)
    for (size_t line = 0; line < text.size(); line = text.find('\n', line) + 1) {
      size_t at = line;
      if (text.compare(at, 7, "inline ") == 0) at += 7;
      bool typed = false;
      for (const char* type : {"real_t ", "vec3_t ", "surface_t ", "void "})
        typed |= text.compare(at, std::strlen(type), type) == 0;
      const size_t close = text.find(')', at), brace = text.find('{', at);
      const size_t open = text.find('(', at);
      if (!typed || open == std::string::npos || close == std::string::npos || brace < close ||
          text.find('\n', at) < open)
        continue;
      std::string signature;
      for (size_t i = at; i <= close; ++i) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
          if (!signature.empty() && signature.back() != ' ') signature += ' ';
        } else {
          signature += c;
        }
      }
      const size_t name_end = signature.find('(');
      const std::string name = signature.substr(signature.rfind(' ', name_end) + 1,
                                                name_end - signature.rfind(' ', name_end) - 1);
      if (internal.count(name)) continue;
      ++found;
      EXPECT_NE(guide.find("`" + signature + "`"), std::string::npos)
          << entry.path().filename() << ": " << signature << " is not in the guide";
    }
  }
  EXPECT_GE(found, 30u);
}

}  // namespace fr
