// The gallery's formulas on the device (each scene's own OpenCL source, through the probe kernel)
// against references written here in plain double-precision C++, independently of the kernels:
// the Mandelbox and Amazing Surf (Lowe), the three KIFS (Knighty; the icosahedral fold checked
// against "reflect across any mirror that separates the point from the chamber until none does",
// not the kernel's fixed sequence), the Juliabulb (through acos, atan2 and pow, where the kernel
// uses de Moivre), the quaternion Mandelbrot set (a general quaternion product), and the
// Jerusalem cube (against the exact distance to the union of its level-2 boxes, which its DE must
// never exceed).
//
// In double (read back as float: 6e-8 relative), every point must agree to 1e-6 of its value plus
// 0.05 (a floor: near the surface the estimate is a difference of nearly equal numbers, and
// chaotic orbits amplify the last bit) but for at most 1% (a fold or bailout decided differently
// by the last bit moves a point onto another branch); in float, 95% to 2e-3 likewise. The shapes
// are a unit or more across: 5e-8 and 1e-4 of absolute error are far below a pixel at any view.
// A formula mistake — a sign, a missing +1, a fold plane off — moves nearly every point.
#include "plugin/scene_instance.hpp"
#include "render/de_probe.hpp"
#include "test_support.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <random>
#include <sstream>

namespace fr {
namespace {

using Vec = std::array<double, 3>;
using Reference = std::function<double(const Vec&)>;

Vec add(Vec a, Vec b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec sub(Vec a, Vec b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec scale(Vec a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(Vec a, Vec b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length(Vec a) { return std::sqrt(dot(a, a)); }

struct Scene {
  std::shared_ptr<const LoadedScene> scene;
  std::vector<fr_value> values;
  void set(const char* key, std::array<double, 3> v) {
    const int i = scene->info.find_param(key);
    ASSERT_GE(i, 0) << key;
    values[i].v[0] = v[0];
    values[i].v[1] = v[1];
    values[i].v[2] = v[2];
  }
  void set(const char* key, double v) { set(key, {v, 0, 0}); }
  double get(const char* key, int c = 0) const {
    return values[scene->info.find_param(key)].v[c];
  }
};

Scene load(const std::string& id) {
  Scene s;
  s.scene = test::load_or_fail(std::filesystem::path(SCENE_PLUGIN_DIR) / (id + PLUGIN_SUFFIX));
  if (s.scene) s.values = make_default_state(s.scene->info).params;
  return s;
}

std::vector<std::array<float, 3>> random_points(double half_side, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(static_cast<float>(-half_side),
                                          static_cast<float>(half_side));
  std::vector<std::array<float, 3>> points;
  for (int i = 0; i < count; ++i) points.push_back({u(rng), u(rng), u(rng)});
  return points;
}

// The scene's DE at `points` against `reference`, in double and in float, lanes 1 and 16.
void expect_matches(const Scene& s, const std::vector<std::array<float, 3>>& points,
                    const Reference& reference, const std::string& what) {
  ASSERT_TRUE(s.scene);
  std::vector<double> expected;
  for (const auto& p : points) expected.push_back(reference({p[0], p[1], p[2]}));
  struct Mode {
    Precision precision;
    int lanes;
    double tolerance, share;
  };
  for (Mode m : {Mode{Precision::Double, 1, 1e-6, 0.99}, Mode{Precision::Double, 16, 1e-6, 0.99},
                 Mode{Precision::Float, 16, 2e-3, 0.95}}) {
    const auto got = probe_de(test::runtime(), s.scene->info, s.values, points, m.lanes,
                              m.precision);
    ASSERT_EQ(got.size(), points.size());
    size_t close = 0;
    std::string first_miss;
    for (size_t i = 0; i < points.size(); ++i) {
      ASSERT_TRUE(std::isfinite(got[i])) << what << ": not finite at point " << i;
      const double error = std::abs(got[i] - expected[i]);
      if (error <= m.tolerance * (std::abs(expected[i]) + 0.05)) {
        ++close;
      } else if (first_miss.empty()) {
        std::ostringstream miss;
        miss << "(" << points[i][0] << ", " << points[i][1] << ", " << points[i][2]
             << "): " << got[i] << " against " << expected[i];
        first_miss = miss.str();
      }
    }
    EXPECT_GE(static_cast<double>(close), m.share * static_cast<double>(points.size()))
        << what << (m.precision == Precision::Double ? ", double" : ", float") << ", lanes "
        << m.lanes << ": " << close << " of " << points.size() << " agree; first miss "
        << first_miss;
  }
}

// Lowe's Mandelbox; `surf`: the box fold on x and y only (Amazing Surf).
double mandelbox(Vec p, int iterations, double s, double min_r, double fixed_r, double limit,
                 bool surf) {
  Vec z = p;
  double dr = 1;
  for (int i = 0; i < iterations && dot(z, z) < 1e8; ++i) {
    for (int c = 0; c < (surf ? 2 : 3); ++c) {
      if (z[c] > limit)
        z[c] = 2 * limit - z[c];
      else if (z[c] < -limit)
        z[c] = -2 * limit - z[c];
    }
    const double r2 = dot(z, z);
    double factor = 1;
    if (r2 < min_r * min_r)
      factor = (fixed_r * fixed_r) / (min_r * min_r);
    else if (r2 < fixed_r * fixed_r)
      factor = (fixed_r * fixed_r) / r2;
    z = add(scale(z, factor * s), p);
    dr = dr * factor * std::abs(s) + 1;
  }
  return length(z) / std::abs(dr);
}

TEST(SceneFormulas, Mandelbox) {
  Scene s = load("mandelbox");
  for (double sc : {2.0, -1.5}) {
    s.set("scale", sc);
    const int n = static_cast<int>(s.get("iterations"));
    expect_matches(
        s, random_points(6, 400, 1),
        [&](const Vec& p) { return mandelbox(p, n, sc, 0.5, 1, 1, false); },
        "mandelbox scale " + std::to_string(sc));
  }
}

TEST(SceneFormulas, AmazingSurf) {
  Scene s = load("amazing_surf");
  const double sc = s.get("scale");
  const int n = static_cast<int>(s.get("iterations"));
  expect_matches(
      s, random_points(5, 400, 2),
      [&](const Vec& p) {
        return mandelbox(p, n, sc, s.get("min_radius"), s.get("fixed_radius"),
                         s.get("fold_limit"), true);
      },
      "amazing_surf");
}

// Rotations of the point by -angle about x, y, z in turn, as a shape rotated by angle.
Vec rotate_xyz(Vec p, double ax, double ay, double az) {
  if (ax != 0) p = {p[0], std::cos(ax) * p[1] + std::sin(ax) * p[2],
                    -std::sin(ax) * p[1] + std::cos(ax) * p[2]};
  if (ay != 0) p = {std::cos(ay) * p[0] - std::sin(ay) * p[2], p[1],
                    std::sin(ay) * p[0] + std::cos(ay) * p[2]};
  if (az != 0) p = {std::cos(az) * p[0] + std::sin(az) * p[1],
                    -std::sin(az) * p[0] + std::cos(az) * p[1], p[2]};
  return p;
}

// The octahedral group's chamber x >= y >= z >= 0.
Vec fold_octahedral(Vec z) {
  for (double& c : z) c = std::abs(c);
  std::sort(z.begin(), z.end(), std::greater<double>());
  return z;
}

// The icosahedral group's chamber around +z, reached by reflecting across any of the 15 mirrors
// that separates the point from a point inside the chamber, until none does (each reflection
// brings the point nearer to that inner point, and the orbit is finite).
Vec fold_icosahedral(Vec z) {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  const Vec inner = {0.1, 0.35, 1.0};
  std::vector<Vec> mirrors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Vec base = {phi / 2, 0.5, 0.5 / phi};
  for (int shift = 0; shift < 3; ++shift)
    for (Vec sign : std::vector<Vec>{{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}}) {
      Vec n;
      for (int c = 0; c < 3; ++c) n[c] = base[(c + 3 - shift) % 3] * sign[c];
      mirrors.push_back(n);
    }
  for (Vec& n : mirrors)
    if (dot(n, inner) < 0) n = scale(n, -1);
  for (int round = 0; round < 100; ++round) {
    bool moved = false;
    for (const Vec& n : mirrors) {
      const double t = dot(z, n);
      if (t < -1e-12) {
        z = sub(z, scale(n, 2 * t));
        moved = true;
      }
    }
    if (!moved) break;
  }
  return z;
}

double kifs(Vec p, bool icosahedral, int iterations, double s, Vec offset, Vec angles) {
  Vec z = p;
  double shrink = 1;
  const double reach = length(offset);
  for (int i = 0; i < iterations && dot(z, z) < 1e8 * std::max(reach * reach, 1.0); ++i) {
    z = icosahedral ? fold_icosahedral(z) : fold_octahedral(z);
    z = rotate_xyz(z, angles[0], angles[1], angles[2]);
    z = sub(scale(z, s), scale(offset, s - 1));
    shrink /= s;
  }
  return (length(z) - reach) * shrink;
}

void check_kifs(const std::string& id, bool icosahedral) {
  Scene s = load(id);
  const double deg = std::acos(-1.0) / 180;
  for (Vec angles : {Vec{0, 0, 0}, Vec{12, -20, 33}}) {
    s.set("angle_x_deg", angles[0]);
    s.set("angle_y_deg", angles[1]);
    s.set("angle_z_deg", angles[2]);
    const int n = static_cast<int>(s.get("iterations"));
    const Vec offset = {s.get("offset", 0), s.get("offset", 1), s.get("offset", 2)};
    expect_matches(
        s, random_points(1.2, 400, 3),
        [&](const Vec& p) {
          return kifs(p, icosahedral, n, s.get("scale"), offset,
                      scale(angles, deg));
        },
        id + " angles " + std::to_string(angles[0]));
  }
}

TEST(SceneFormulas, KifsOctahedron) { check_kifs("kifs_octahedron", false); }
TEST(SceneFormulas, KifsIcosahedron) { check_kifs("kifs_icosahedron", true); }
TEST(SceneFormulas, KifsDodecahedron) { check_kifs("kifs_dodecahedron", true); }

// The Juliabulb through the angles: z <- r^n (sin n theta cos n phi, sin n theta sin n phi,
// cos n theta) + c, dr <- n r^(n-1) dr.
double juliabulb(Vec p, double n, Vec c, double bailout, int iterations) {
  Vec z = p;
  double dr = 1, r = length(z);
  for (int i = 0; i < iterations && r < bailout && r > 1e-4; ++i) {
    const double theta = std::acos(std::clamp(z[2] / r, -1.0, 1.0)) * n;
    const double phi = std::atan2(z[1], z[0]) * n;
    const double rn = std::pow(r, n);
    dr = n * std::pow(r, n - 1) * dr;
    z = add({rn * std::sin(theta) * std::cos(phi), rn * std::sin(theta) * std::sin(phi),
             rn * std::cos(theta)},
            c);
    r = length(z);
  }
  return 0.5 * std::log(r) * r / dr;
}

// The scene takes 0.55 of the library's estimate (plugins/juliabulb/juliabulb.cl: near its poles
// the estimate runs long, as de-near-surface measured).
TEST(SceneFormulas, Juliabulb) {
  Scene s = load("juliabulb");
  const Vec c = {s.get("c", 0), s.get("c", 1), s.get("c", 2)};
  for (double power : {8.0, 5.5}) {
    s.set("power", power);
    expect_matches(
        s, random_points(1.6, 400, 4),
        [&](const Vec& p) {
          return 0.55 *
                 juliabulb(p, power, c, s.get("bailout"), static_cast<int>(s.get("iterations")));
        },
        "juliabulb power " + std::to_string(power));
  }
}

using Quaternion = std::array<double, 4>;  // (real, i, j, k)
Quaternion multiply(const Quaternion& a, const Quaternion& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
double norm(const Quaternion& q) {
  return std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
}

// q <- q^2 + c from q = c, |dq| <- 2 |q| |dq| + 1.
double quaternion_mandelbrot(Vec p, double w, double bailout, int iterations) {
  const Quaternion c = {p[0], p[1], p[2], w};
  Quaternion q = c;
  double dr = 1, r = norm(q);
  for (int i = 1; i < iterations && r < bailout; ++i) {
    dr = 2 * r * dr + 1;
    q = multiply(q, q);
    for (int k = 0; k < 4; ++k) q[k] += c[k];
    r = norm(q);
  }
  return 0.5 * r * std::log(r) / dr;
}

TEST(SceneFormulas, QuaternionMandelbrot) {
  Scene s = load("quaternion_mandelbrot");
  for (double w : {0.0, 0.3}) {
    s.set("slice_w", w);
    expect_matches(
        s, random_points(2, 400, 5),
        [&](const Vec& p) {
          return quaternion_mandelbrot(p, w, s.get("bailout"),
                                       static_cast<int>(s.get("iterations")));
        },
        "quaternion_mandelbrot w " + std::to_string(w));
  }
}

// The Jerusalem cube's level-2 boxes (corner copies scaled by k = sqrt 2 - 1 at (+-(1 - k))^3,
// edge copies scaled by k^2 at the edges' middles), listed by brute force.
struct Box {
  Vec centre;
  double half;
};
std::vector<Box> jerusalem_boxes(const Box& cube, int level) {
  if (level == 0) return {cube};
  const double k = std::sqrt(2.0) - 1, k2 = k * k;
  std::vector<Box> out;
  for (int sx = -1; sx <= 1; sx += 2)
    for (int sy = -1; sy <= 1; sy += 2)
      for (int sz = -1; sz <= 1; sz += 2) {
        const Vec c = add(cube.centre, scale(Vec{double(sx), double(sy), double(sz)},
                                             (1 - k) * cube.half));
        for (const Box& b : jerusalem_boxes({c, k * cube.half}, level - 1)) out.push_back(b);
      }
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 = -1; s1 <= 1; s1 += 2)
      for (int s2 = -1; s2 <= 1; s2 += 2) {
        Vec offset = {0, 0, 0};
        offset[(axis + 1) % 3] = s1 * (1 - k2) * cube.half;
        offset[(axis + 2) % 3] = s2 * (1 - k2) * cube.half;
        for (const Box& b : jerusalem_boxes({add(cube.centre, offset), k2 * cube.half}, level - 1))
          out.push_back(b);
      }
  return out;
}

double box_distance(const Vec& p, const Box& b) {
  double outside = 0, inside = -1e300;
  for (int c = 0; c < 3; ++c) {
    const double d = std::abs(p[c] - b.centre[c]) - b.half;
    outside += std::max(d, 0.0) * std::max(d, 0.0);
    inside = std::max(inside, d);
  }
  return std::sqrt(outside) + std::min(inside, 0.0);
}

TEST(SceneFormulas, JerusalemCubeNeverExceedsTheExactDistance) {
  Scene s = load("jerusalem_cube");
  ASSERT_TRUE(s.scene);
  s.set("iterations", 2);
  const std::vector<Box> boxes = jerusalem_boxes({{0, 0, 0}, 1}, 2);
  ASSERT_EQ(boxes.size(), 400u);
  const auto points = random_points(1.3, 3000, 6);
  const auto got = probe_de(test::runtime(), s.scene->info, s.values, points, 16,
                            Precision::Double);
  size_t tight = 0, outside = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec p = {points[i][0], points[i][1], points[i][2]};
    double exact = 1e300;
    for (const Box& b : boxes) exact = std::min(exact, box_distance(p, b));
    if (exact <= 0) continue;  // inside: the DE's sign is all that matters there
    ++outside;
    // (The DE comes back as a float: 6e-8 relative.)
    ASSERT_LE(got[i], exact * (1 + 1e-6) + 1e-9) << "over-estimates at (" << p[0] << ", " << p[1] << ", "
                                    << p[2] << "): " << got[i] << " > " << exact;
    if (got[i] >= 0.5 * exact) ++tight;
  }
  // A lower bound of zero would pass the check above: most points must be within 2x.
  EXPECT_GE(tight, outside * 9 / 10) << tight << " of " << outside;
}


// Knighty's pseudo-Kleinian, written out: box fold, inversion where |z|^2 < k, + offset; the tube
// max(rxy - r, |rxy z| / |z|) over the scale product, times the library's 3/4, cut to the ball.
double pseudo_kleinian(Vec p, int iterations, Vec box, double k, Vec offset, double tube,
                       double extent) {
  Vec z = p;
  double product = 1;
  for (int i = 0; i < iterations; ++i) {
    for (int c = 0; c < 3; ++c) z[c] = 2 * std::clamp(z[c], -box[c], box[c]) - z[c];
    const double f = std::max(k / std::max(dot(z, z), 1e-20), 1.0);
    z = add(scale(z, f), offset);
    product *= f;
  }
  const double rxy = std::hypot(z[0], z[1]);
  const double to_tube = std::max(rxy - tube, std::abs(rxy * z[2]) / length(z));
  return std::max(0.75 * to_tube / product, length(p) - extent);
}

// The folds amplify a difference of the last bits of the parameters (an operation done in
// another order) to 1e-5 near the surface, so the parameters are numbers that float holds
// exactly, the same in every kernel and here.
TEST(SceneFormulas, PseudoKleinian) {
  Scene s = load("pseudo_kleinian");
  auto as_float = [](double x) { return static_cast<double>(static_cast<float>(x)); };
  s.set("box_size", {as_float(s.get("box_size", 0)), as_float(s.get("box_size", 1)),
                     as_float(s.get("box_size", 2))});
  s.set("tube_radius", as_float(s.get("tube_radius")));
  for (double k : {1.0, 1.3}) {
    s.set("inversion_k", as_float(k));
    k = as_float(k);
    const Vec box = {s.get("box_size", 0), s.get("box_size", 1), s.get("box_size", 2)};
    const Vec offset = {s.get("offset", 0), s.get("offset", 1), s.get("offset", 2)};
    expect_matches(
        s, random_points(4, 400, 11),
        [&](const Vec& p) {
          return pseudo_kleinian(p, static_cast<int>(s.get("iterations")), box, k, offset,
                                 s.get("tube_radius"), s.get("extent"));
        },
        "pseudo_kleinian k " + std::to_string(k));
  }
}

// Jos Leys' Kleinian group in the Maskit slice, written out from his description: wrap x (in the
// frame sheared by b / a) and z into their periods, turn half-way about (-b/2, a/2) above the
// separation line, then apply a: z -> -z / |z|^2, x -> -b - x, y -> a + y; stop on a two-cycle.
double kleinian(Vec p, int iterations, double a, double b, double box_x, double box_z,
                double extent) {
  auto wrap = [](double x, double half) { return x - 2 * half * std::floor((x + half) / (2 * half)); };
  Vec z = p, last = add(p, {1, 1, 1}), before_last = sub(p, {1, 1, 1});
  double product = 1;
  const double f = b > 0 ? 1 : (b < 0 ? -1 : 0);
  for (int i = 0; i < iterations; ++i) {
    z[0] += b / a * z[1];
    z[0] = wrap(z[0], box_x);
    z[2] = wrap(z[2], box_z);
    z[0] -= b / a * z[1];
    const double u = z[0] + b / 2;
    const double line = a / 2 + f * (2 * a - 1.95) / 4 * (u > 0 ? 1 : (u < 0 ? -1 : 0)) *
                                    (1 - std::exp(-(7.2 - (1.95 - a) * 15) * std::abs(u)));
    if (z[1] >= line) z = sub({-b, a, 0}, z);
    const double inv = 1 / std::max(dot(z, z), 1e-20);
    z = scale(z, -inv);
    z[0] = -b - z[0];
    z[1] = a + z[1];
    product *= inv;
    const Vec d = sub(z, before_last);
    if (dot(d, d) < 1e-5) break;
    before_last = last;
    last = z;
  }
  const double y = std::min(z[1], a - z[1]);
  return std::max(0.25 * std::min(y, 0.3) / std::max(product, 2.0), length(p) - extent);
}

TEST(SceneFormulas, Kleinian) {
  Scene s = load("kleinian");
  for (double b : {0.0112785606117658, 0.0}) {
    s.set("trace_im", b);
    expect_matches(
        s, random_points(2.5, 400, 12),
        [&](const Vec& p) {
          return kleinian(p, static_cast<int>(s.get("iterations")), s.get("trace_re"), b,
                          s.get("box_x"), s.get("box_z"), s.get("extent"));
        },
        "kleinian b " + std::to_string(b));
  }
}

// The Apollonian network: mirror cells, inversion in the sphere of squared radius k.
double apollonian(Vec p, int iterations, double k, double extent) {
  Vec z = p;
  double product = 1;
  for (int i = 0; i < iterations; ++i) {
    for (double& c : z) c = -1 + 2 * (0.5 * c + 0.5 - std::floor(0.5 * c + 0.5));
    const double f = k / std::max(dot(z, z), 1e-20);
    z = scale(z, f);
    product *= f;
  }
  return std::max(0.25 * std::abs(z[1]) / product, length(p) - extent);
}

TEST(SceneFormulas, Apollonian) {
  Scene s = load("apollonian");
  for (double k : {1.3, 1.12}) {
    s.set("inversion_k", k);
    expect_matches(
        s, random_points(2.6, 400, 13),
        [&](const Vec& p) {
          return apollonian(p, static_cast<int>(s.get("iterations")), k, s.get("extent"));
        },
        "apollonian k " + std::to_string(k));
  }
}

// The Tetrabrot through std::complex: u = x + i (y - z), w = x + i (y + z), each iterated as a
// Mandelbrot point with its derivative, Koebe's bound (1 - e^(-2G)) |z| 2^n / (4 |z'|) for each,
// combined as sqrt((b_u^2 + b_w^2) / 2).
double mandelbrot_bound(std::complex<double> c, int iterations) {
  std::complex<double> z = c, dz = 1;
  double two_n = 1;
  for (int i = 0; i < iterations && std::norm(z) < 65536.0 * 65536.0; ++i) {
    dz = 2.0 * z * dz + 1.0;
    z = z * z + c;
    two_n *= 2;
  }
  if (std::norm(z) < 4) return 0;
  const double g = std::log(std::abs(z)) / two_n;
  return -std::expm1(-2 * g) * std::abs(z) * two_n / (4 * std::abs(dz));
}

TEST(SceneFormulas, Tetrabrot) {
  Scene s = load("tetrabrot");
  const int n = static_cast<int>(s.get("iterations"));
  expect_matches(
      s, random_points(2.2, 400, 14),
      [&](const Vec& p) {
        const double bu = mandelbrot_bound({p[0], p[1] - p[2]}, n);
        const double bw = mandelbrot_bound({p[0], p[1] + p[2]}, n);
        return std::sqrt(0.5 * (bu * bu + bw * bw));
      },
      "tetrabrot");
}

// The Tetrabrot's bound never exceeds the true distance: on the real axis (y = z = 0) both
// complex points are x itself, and the Mandelbrot set's real part is [-2, 1/4], so from x > 1/4
// the distance is at most x - 1/4 (the set's point 1/4 lies on the slice).
TEST(SceneFormulas, TetrabrotIsABound) {
  Scene s = load("tetrabrot");
  ASSERT_TRUE(s.scene);
  std::vector<std::array<float, 3>> points;
  for (float x : {0.3f, 0.5f, 1.0f, 2.0f, 2.8f}) points.push_back({x, 0, 0});
  const auto got = probe_de(test::runtime(), s.scene->info, s.values, points, 1,
                            Precision::Double);
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_LE(got[i], points[i][0] - 0.25 + 1e-9) << "x = " << points[i][0];
    // Not zero either: a fifth of the distance from x = 1 on (near the cusp at 1/4 the escape
    // is parabolic and the bound weak).
    if (points[i][0] >= 1) {
      EXPECT_GT(got[i], 0.2 * (points[i][0] - 0.25)) << "x = " << points[i][0];
    }
  }
}

// The cubic quaternion Julia set through a general quaternion product (q q q), p = x + y i + z j
// + w k.
double cubic_julia(Vec p, double w, Quaternion c, double bailout, int iterations) {
  Quaternion q = {p[0], p[1], p[2], w};
  double dr = 1, r = norm(q);
  for (int i = 0; i < iterations && r < bailout && r > 1e-4; ++i) {
    dr = 3 * r * r * dr;
    q = multiply(multiply(q, q), q);
    for (int k = 0; k < 4; ++k) q[k] += c[k];
    r = norm(q);
  }
  return 0.5 * r * std::log(r) / dr;
}

TEST(SceneFormulas, QuaternionCubicJulia) {
  Scene s = load("quaternion_cubic_julia");
  for (double w : {0.0, 0.3}) {
    s.set("slice_w", w);
    const Quaternion c = {s.get("c", 0), s.get("c", 1), s.get("c", 2), s.get("c_w")};
    expect_matches(
        s, random_points(1.6, 400, 15),
        [&](const Vec& p) {
          return cubic_julia(p, w, c, 4, static_cast<int>(s.get("iterations")));
        },
        "quaternion_cubic_julia w " + std::to_string(w));
  }
}

// Kali's Kalibox, written out: rotate, |z| + t, sphere fold factor clamp(max(m / r^2, m), 0, 1)
// times scale / m, + c; Rrrola's estimate.
double kalibox(Vec p, int iterations, double s, double m, Vec t, Vec c) {
  Vec z = p;
  double dr = 1;
  for (int i = 0; i < iterations && dot(z, z) < 1e10; ++i) {
    for (int k = 0; k < 3; ++k) z[k] = std::abs(z[k]) + t[k];
    const double f = std::clamp(std::max(m / std::max(dot(z, z), 1e-30), m), 0.0, 1.0);
    z = add(scale(z, f * s / m), c);
    dr = dr * f * std::abs(s) / m + 1;
  }
  return (length(z) - std::abs(s - 1)) / dr - std::pow(std::abs(s), 1 - iterations);
}

TEST(SceneFormulas, Kalibox) {
  Scene s = load("kalibox");
  const Vec t = {s.get("translation", 0), s.get("translation", 1), s.get("translation", 2)};
  const Vec c = {s.get("c", 0), s.get("c", 1), s.get("c", 2)};
  expect_matches(
      s, random_points(3, 400, 16),
      [&](const Vec& p) {
        return kalibox(p, static_cast<int>(s.get("iterations")), s.get("scale"),
                       s.get("min_radius2"), t, c);
      },
      "kalibox");
}

// Cantor dust against the exact distance to its 64 level-2 cubes, found by trying every one.
TEST(SceneFormulas, CantorDustIsTheExactDistanceToItsCubes) {
  Scene s = load("cantor_dust");
  s.set("iterations", 2);
  std::vector<Box> cubes;
  for (int i = 0; i < 64; ++i) {
    Vec centre{};
    for (int c = 0; c < 3; ++c) {
      const int outer = (i >> c) & 1, inner = (i >> (c + 3)) & 1;
      centre[c] = (outer ? 2.0 : -2.0) / 3 + (inner ? 2.0 : -2.0) / 9;
    }
    cubes.push_back({centre, 1.0 / 9});
  }
  expect_matches(
      s, random_points(1.5, 400, 17),
      [&](const Vec& p) {
        double d = 1e300;
        for (const Box& b : cubes) d = std::min(d, box_distance(p, b));
        return d;
      },
      "cantor_dust");
}

// The sphereflake and the Pythagoras tree against the min over every sphere (every branch) of
// their first levels, with the last level's bounding balls, found by trying each: the folds'
// one-child-per-level walk must give the same.
struct Ball {
  Vec centre;
  double radius;
};

TEST(SceneFormulas, SphereflakeIsTheNearestOfAllItsSpheres) {
  Scene s = load("sphereflake");
  const int levels = 3;
  s.set("levels", levels);
  const double k = s.get("child_scale");
  std::vector<Ball> balls = {{{0, 0, 0}, 1}};
  std::vector<Ball> generation = balls;
  for (int level = 1; level <= levels; ++level) {
    std::vector<Ball> next;
    for (const Ball& b : generation)
      for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
          Vec centre = b.centre;
          centre[axis] += sign * b.radius * (1 + k);
          next.push_back({centre, b.radius * k});
        }
    generation = next;
    for (const Ball& b : next)
      balls.push_back({b.centre, level == levels ? b.radius * (1 + 2 * k / (1 - k)) : b.radius});
  }
  ASSERT_EQ(balls.size(), 1u + 6 + 36 + 216);
  expect_matches(
      s, random_points(2.2, 400, 18),
      [&](const Vec& p) {
        double d = 1e300;
        for (const Ball& b : balls) d = std::min(d, length(sub(p, b.centre)) - b.radius);
        return d;
      },
      "sphereflake");
}

double capsule_distance(Vec p, Vec a, Vec b, double r) {
  const Vec pa = sub(p, a), ba = sub(b, a);
  const double h = std::clamp(dot(pa, ba) / dot(ba, ba), 0.0, 1.0);
  return length(sub(pa, scale(ba, h))) - r;
}

TEST(SceneFormulas, PythagorasTreeIsTheNearestOfAllItsBranches) {
  Scene s = load("pythagoras_tree");
  const int levels = 3;
  s.set("levels", levels);
  const double k = s.get("child_scale"), width = s.get("width");
  const double tilt = s.get("tilt_deg") * std::acos(-1.0) / 180;
  struct Branch {
    Vec base, up, side;  // up: the branch's axis (its length), side: a unit normal to it
    double size;
  };
  std::vector<Branch> generation = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 1}};
  std::vector<std::pair<Branch, bool>> all = {{generation[0], false}};
  for (int level = 1; level <= levels; ++level) {
    std::vector<Branch> next;
    for (const Branch& b : generation) {
      const Vec top = add(b.base, scale(b.up, b.size));
      const Vec axis = scale(b.up, 1 / length(b.up));
      const Vec side1 = b.side, side2 = {axis[1] * side1[2] - axis[2] * side1[1],
                                          axis[2] * side1[0] - axis[0] * side1[2],
                                          axis[0] * side1[1] - axis[1] * side1[0]};
      for (const Vec& side : {side1, side2, scale(side1, -1), scale(side2, -1)}) {
        const Vec up = add(scale(axis, std::cos(tilt)), scale(side, std::sin(tilt)));
        const Vec new_side = sub(scale(side, std::cos(tilt)), scale(axis, std::sin(tilt)));
        next.push_back({top, up, new_side, b.size * k});
      }
    }
    generation = next;
    for (const Branch& b : next) all.push_back({b, level == levels});
  }
  ASSERT_EQ(all.size(), 1u + 4 + 16 + 64);
  const double reach = 1 / (1 - k) + width;
  expect_matches(
      s, random_points(2.5, 400, 19),
      [&](const Vec& p) {
        double d = 1e300;
        for (const auto& [b, last] : all) {
          d = std::min(d, last ? length(sub(p, b.base)) - reach * b.size
                               : capsule_distance(p, b.base, add(b.base, scale(b.up, b.size)),
                                                  width * b.size));
        }
        return d;
      },
      "pythagoras_tree");
}

}  // namespace
}  // namespace fr
