// float128_reference.hpp — shapes' distance estimates in __float128 (113 bits), written apart
// from the kernels (no shared code), as the reference past double for the deep-zoom tests
// (double_double_test.cpp, deep_zoom_test.cpp).
#pragma once

#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace fr::test {

using quad = __float128;

inline quad quad_abs(quad x) {
  return x < 0 ? -x : x;
}

// sqrt in __float128 without libquadmath: Newton from the double root (each step doubles the
// correct bits: 53 -> 106 -> 113).
inline quad quad_sqrt(quad x) {
  if (!(x > 0)) return 0;
  quad r = std::sqrt(static_cast<double>(x));
  for (int i = 0; i < 3; ++i) r = (r + x / r) / 2;
  return r;
}

// A double-double's two doubles for a __float128: hi the nearest double, lo the rest rounded.
inline void split(quad x, double* hi, double* lo) {
  *hi = static_cast<double>(x);
  *lo = static_cast<double>(x - static_cast<quad>(*hi));
}

// The Mandelbox (scale 2, min radius 0.5, fixed radius 1, fold 1, 90 iterations) in __float128.
// (Its estimate resolves about 1 / dr: 2^-n after n iterations, so a view 1e-22 across needs
// some 75; 60 stall near 1e-19.) Its Julia form adds c in place of p (dr without the +1); its
// rotated form turns the folded point by angle_rad about x, then y, then z (the rotation's
// cosines and sines in double, as the scene's parameters give them).
struct BoxReference {
  int iterations = 90;
  double scale = 2, min_radius = 0.5, fixed_radius = 1, fold = 1;
  double bailout2 = 1e8;  // |z|^2 past which the orbit has escaped (the hybrid scene's is a parameter)
  bool julia = false;
  double c[3] = {0, 0, 0};
  double angle_rad[3] = {0, 0, 0};
  // The point turned as the scenes turn it (kernels' p_rotate_x, _y, _z, in that order).
  void rotate(quad z[3]) const {
    if (angle_rad[0] != 0) {
      const quad co = std::cos(angle_rad[0]), si = std::sin(angle_rad[0]);
      const quad y = co * z[1] + si * z[2], w = -si * z[1] + co * z[2];
      z[1] = y;
      z[2] = w;
    }
    if (angle_rad[1] != 0) {
      const quad co = std::cos(angle_rad[1]), si = std::sin(angle_rad[1]);
      const quad x = co * z[0] - si * z[2], w = si * z[0] + co * z[2];
      z[0] = x;
      z[2] = w;
    }
    if (angle_rad[2] != 0) {
      const quad co = std::cos(angle_rad[2]), si = std::sin(angle_rad[2]);
      const quad x = co * z[0] + si * z[1], y = -si * z[0] + co * z[1];
      z[0] = x;
      z[1] = y;
    }
  }
  quad de(const quad p[3]) const {
    quad z[3] = {p[0], p[1], p[2]};
    const quad added[3] = {julia ? quad(c[0]) : p[0], julia ? quad(c[1]) : p[1],
                           julia ? quad(c[2]) : p[2]};
    quad dr = 1;
    quad r2 = z[0] * z[0] + z[1] * z[1] + z[2] * z[2];
    const quad min2 = static_cast<quad>(min_radius) * min_radius,
               fixed2 = static_cast<quad>(fixed_radius) * fixed_radius;
    for (int i = 0; i < iterations && r2 < bailout2; ++i) {
      for (quad& c : z) {
        if (c > fold)
          c = 2 * static_cast<quad>(fold) - c;
        else if (c < -fold)
          c = -2 * static_cast<quad>(fold) - c;
      }
      const quad f2 = z[0] * z[0] + z[1] * z[1] + z[2] * z[2];
      const quad factor = f2 < min2 ? fixed2 / min2 : f2 < fixed2 ? fixed2 / f2 : quad(1);
      rotate(z);
      for (int c = 0; c < 3; ++c) z[c] = z[c] * factor * scale + added[c];
      dr = dr * factor * (scale < 0 ? -scale : scale) + (julia ? 0 : 1);
      r2 = z[0] * z[0] + z[1] * z[1] + z[2] * z[2];
    }
    return quad_sqrt(r2) / quad_abs(dr);
  }
};

// The Menger sponge (scale 3, offset (1, 1, 1), no rotation) in __float128: the level-n
// sponge's box distance over 3^n (exact outside the sponge).
struct SpongeReference {
  int iterations = 50;
  quad de(const quad p[3]) const {
    quad z[3] = {quad_abs(p[0]), quad_abs(p[1]), quad_abs(p[2])};
    quad scale_n = 1;
    for (int i = 0; i < iterations; ++i) {
      for (quad& c : z) c = quad_abs(c);
      if (z[0] < z[1]) std::swap(z[0], z[1]);
      if (z[0] < z[2]) std::swap(z[0], z[2]);
      if (z[1] < z[2]) std::swap(z[1], z[2]);
      z[0] = 3 * z[0] - 2;
      z[1] = 3 * z[1] - 2;
      z[2] = 3 * z[2];
      if (z[2] > 1) z[2] -= 2;
      scale_n *= 3;
    }
    quad outside2 = 0, inside = -1e30;
    for (const quad c : z) {
      const quad q = quad_abs(c) - 1;
      if (q > 0) outside2 += q * q;
      if (q > inside) inside = q;
    }
    return (quad_sqrt(outside2) + (inside < 0 ? inside : quad(0))) / scale_n;
  }
};

// The power-n Mandelbulb (polar axis z, theta = acos(z / r), phi = atan2(y, x)) through the
// angles, with libquadmath's trigonometry: written apart from the kernels' de Moivre form, it
// checks that too.
struct BulbReference {
  int iterations = 40;
  double power = 8, bailout = 2;
  quad de(const quad p[3]) const {
    quad z[3] = {p[0], p[1], p[2]};
    quad dr = 1;
    quad r = sqrtq(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
    for (int i = 0; i < iterations && r < bailout; ++i) {
      const quad theta = (r > 0 ? acosq(z[2] / r) : quad(0)) * power;
      const quad phi = atan2q(z[1], z[0]) * power;
      const quad r_pow = powq(r, power - 1);
      dr = power * r_pow * dr + 1;
      const quad zr = r_pow * r;
      z[0] = zr * sinq(theta) * cosq(phi) + p[0];
      z[1] = zr * sinq(theta) * sinq(phi) + p[1];
      z[2] = zr * cosq(theta) + p[2];
      r = sqrtq(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
    }
    return quad(0.5) * logq(r) * r / dr;
  }
};

}  // namespace fr::test
