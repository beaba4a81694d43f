// Ports of fdlibm 5.3's k_sin.c, k_cos.c, e_rem_pio2.c (the reduction of arguments up to
// 2^19 * pi/2; fdlibm's __kernel_rem_pio2 for larger ones is left out), s_sin.c, s_cos.c,
// s_atan.c and e_atan2.c to C++17, with the words of a double read by std::memcpy instead of
// fdlibm's __HI/__LO macros. The arithmetic and the constants are fdlibm's.
//
// ====================================================
// Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//
// Developed at SunSoft, a Sun Microsystems, Inc. business.
// Permission to use, copy, modify, and distribute this
// software is freely granted, provided that this notice
// is preserved.
// ====================================================
#include "core/portable_math.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace holebench {
namespace {

std::uint64_t bits_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

double from_bits(std::uint64_t bits) {
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

/// The high 32 bits of a double (fdlibm's __HI), as a signed int.
std::int32_t high_word(double x) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(bits_of(x) >> 32));
}

/// The low 32 bits (fdlibm's __LO).
std::uint32_t low_word(double x) {
  return static_cast<std::uint32_t>(bits_of(x));
}

/// A double from its two words.
double from_words(std::uint32_t high, std::uint32_t low) {
  return from_bits((static_cast<std::uint64_t>(high) << 32) | low);
}

// --- k_sin.c: sin on [-pi/4, pi/4]; x + y is the argument, y its tail; iy = 0: y is 0 ----

constexpr double kHalf = 5.00000000000000000000e-01;
constexpr double kS1 = -1.66666666666666324348e-01;  // 0xBFC55555 55555549
constexpr double kS2 = 8.33333333332248946124e-03;   // 0x3F811111 1110F8A6
constexpr double kS3 = -1.98412698298579493134e-04;  // 0xBF2A01A0 19C161D5
constexpr double kS4 = 2.75573137070700676789e-06;   // 0x3EC71DE3 57B1FE7D
constexpr double kS5 = -2.50507602534068634195e-08;  // 0xBE5AE5E6 8A2B9CEB
constexpr double kS6 = 1.58969099521155010221e-10;   // 0x3DE5D93A 5ACFD57C

double kernel_sin(double x, double y, int iy) {
  const std::int32_t ix = high_word(x) & 0x7fffffff;
  if (ix < 0x3e400000) {  // |x| < 2^-27
    if (static_cast<int>(x) == 0)
      return x;
  }
  const double z = x * x;
  const double v = z * x;
  const double r = kS2 + z * (kS3 + z * (kS4 + z * (kS5 + z * kS6)));
  if (iy == 0)
    return x + v * (kS1 + z * r);
  return x - ((z * (kHalf * y - v * r) - y) - v * kS1);
}

// --- k_cos.c: cos on [-pi/4, pi/4] -----------------------------------------------------------

constexpr double kOne = 1.00000000000000000000e+00;
constexpr double kC1 = 4.16666666666666019037e-02;   // 0x3FA55555 5555554C
constexpr double kC2 = -1.38888888888741095749e-03;  // 0xBF56C16C 16C15177
constexpr double kC3 = 2.48015872894767294178e-05;   // 0x3EFA01A0 19CB1590
constexpr double kC4 = -2.75573143513906633035e-07;  // 0xBE927E4F 809C52AD
constexpr double kC5 = 2.08757232129817482790e-09;   // 0x3E21EE9E BDB4B1C4
constexpr double kC6 = -1.13596475577881948265e-11;  // 0xBDA8FAE9 BE8838D4

double kernel_cos(double x, double y) {
  const std::int32_t ix = high_word(x) & 0x7fffffff;
  if (ix < 0x3e400000) {  // |x| < 2^-27
    if (static_cast<int>(x) == 0)
      return kOne;
  }
  const double z = x * x;
  const double r = z * (kC1 + z * (kC2 + z * (kC3 + z * (kC4 + z * (kC5 + z * kC6)))));
  if (ix < 0x3FD33333)  // |x| < 0.3
    return kOne - (0.5 * z - (z * r - x * y));
  double qx;
  if (ix > 0x3fe90000) {  // |x| > 0.78125
    qx = 0.28125;
  } else {
    qx = from_words(static_cast<std::uint32_t>(ix - 0x00200000), 0);  // x/4
  }
  const double hz = 0.5 * z - qx;
  const double a = kOne - qx;
  return a - (hz - (z * r - x * y));
}

// --- e_rem_pio2.c: x - n * pi/2 as y[0] + y[1], |x| <= 2^19 * pi/2 ----------------------------

constexpr double kInvPio2 = 6.36619772367581382433e-01;  // 0x3FE45F30 6DC9C883
constexpr double kPio2_1 = 1.57079632673412561417e+00;   // 0x3FF921FB 54400000
constexpr double kPio2_1t = 6.07710050650619224932e-11;  // 0x3DD0B461 1A626331
constexpr double kPio2_2 = 6.07710050630396597660e-11;   // 0x3DD0B461 1A600000
constexpr double kPio2_2t = 2.02226624879595063154e-21;  // 0x3BA3198A 2E037073
constexpr double kPio2_3 = 2.02226624871116645580e-21;   // 0x3BA3198A 2E000000
constexpr double kPio2_3t = 8.47842766036889956997e-32;  // 0x397B839A 252049C1

int rem_pio2(double x, double* y) {
  const std::int32_t hx = high_word(x);
  const std::int32_t ix = hx & 0x7fffffff;
  if (ix <= 0x3fe921fb) {  // |x| <= pi/4: no reduction
    y[0] = x;
    y[1] = 0;
    return 0;
  }
  if (ix < 0x4002d97c) {  // |x| < 3pi/4: n = +-1
    if (hx > 0) {
      double z = x - kPio2_1;
      if (ix != 0x3ff921fb) {  // 33 + 53 bits of pi are enough
        y[0] = z - kPio2_1t;
        y[1] = (z - y[0]) - kPio2_1t;
      } else {  // near pi/2: 33 + 33 + 53 bits
        z -= kPio2_2;
        y[0] = z - kPio2_2t;
        y[1] = (z - y[0]) - kPio2_2t;
      }
      return 1;
    }
    double z = x + kPio2_1;
    if (ix != 0x3ff921fb) {
      y[0] = z + kPio2_1t;
      y[1] = (z - y[0]) + kPio2_1t;
    } else {
      z += kPio2_2;
      y[0] = z + kPio2_2t;
      y[1] = (z - y[0]) + kPio2_2t;
    }
    return -1;
  }
  if (ix > 0x413921fb)  // fdlibm's __kernel_rem_pio2, not ported
    throw std::domain_error("portable_sin/cos: |x| above 2^19 * pi/2 is not supported");
  // Medium size. fdlibm first tries a quick exit through a table of the high words of
  // n * pi/2 (npio2_hw); that exit gives the same result as the check below whenever it is
  // taken (no cancellation), so the check alone is done here.
  double t = std::fabs(x);
  const int n = static_cast<int>(t * kInvPio2 + kHalf);
  const double fn = static_cast<double>(n);
  double r = t - fn * kPio2_1;
  double w = fn * kPio2_1t;  // first round: 85 bits
  const std::int32_t j = ix >> 20;
  y[0] = r - w;
  std::int32_t i = j - ((high_word(y[0]) >> 20) & 0x7ff);
  if (i > 16) {  // second iteration: 118 bits
    t = r;
    w = fn * kPio2_2;
    r = t - w;
    w = fn * kPio2_2t - ((t - r) - w);
    y[0] = r - w;
    i = j - ((high_word(y[0]) >> 20) & 0x7ff);
    if (i > 49) {  // third iteration: 151 bits, covers every case
      t = r;
      w = fn * kPio2_3;
      r = t - w;
      w = fn * kPio2_3t - ((t - r) - w);
      y[0] = r - w;
    }
  }
  y[1] = (r - y[0]) - w;
  if (hx < 0) {
    y[0] = -y[0];
    y[1] = -y[1];
    return -n;
  }
  return n;
}

// --- s_atan.c ----------------------------------------------------------------------------------

constexpr double kAtanHi[] = {
    4.63647609000806093515e-01,  // atan(0.5) high  0x3FDDAC67 0561BB4F
    7.85398163397448278999e-01,  // atan(1.0) high  0x3FE921FB 54442D18
    9.82793723247329054082e-01,  // atan(1.5) high  0x3FEF730B D281F69B
    1.57079632679489655800e+00,  // atan(inf) high  0x3FF921FB 54442D18
};
constexpr double kAtanLo[] = {
    2.26987774529616870924e-17,  // atan(0.5) low  0x3C7A2B7F 222F65E2
    3.06161699786838301793e-17,  // atan(1.0) low  0x3C81A626 33145C07
    1.39033110312309984516e-17,  // atan(1.5) low  0x3C700788 7AF0CBBD
    6.12323399573676603587e-17,  // atan(inf) low  0x3C91A626 33145C07
};
constexpr double kAT[] = {
    3.33333333333329318027e-01,   // 0x3FD55555 5555550D
    -1.99999999998764832476e-01,  // 0xBFC99999 9998EBC4
    1.42857142725034663711e-01,   // 0x3FC24924 920083FF
    -1.11111104054623557880e-01,  // 0xBFBC71C6 FE231671
    9.09088713343650656196e-02,   // 0x3FB745CD C54C206E
    -7.69187620504482999495e-02,  // 0xBFB3B0F2 AF749A6D
    6.66107313738753120669e-02,   // 0x3FB10D66 A0D03D51
    -5.83357013379057348645e-02,  // 0xBFADDE2D 52DEFD9A
    4.97687799461593236017e-02,   // 0x3FA97B4B 24760DEB
    -3.65315727442169155270e-02,  // 0xBFA2B444 2C6A6C2F
    1.62858201153657823623e-02,   // 0x3F90AD3A E322DA11
};

// --- e_atan2.c ---------------------------------------------------------------------------------

constexpr double kTiny = 1.0e-300;
constexpr double kPiO4 = 7.8539816339744827900E-01;  // 0x3FE921FB 54442D18
constexpr double kPiO2 = 1.5707963267948965580E+00;  // 0x3FF921FB 54442D18
constexpr double kPiLo = 1.2246467991473531772E-16;  // 0x3CA1A626 33145C07

}  // namespace

double portable_sin(double x) {
  const std::int32_t ix = high_word(x) & 0x7fffffff;
  if (ix <= 0x3fe921fb)
    return kernel_sin(x, 0.0, 0);
  if (ix >= 0x7ff00000)  // infinity or NaN
    return std::numeric_limits<double>::quiet_NaN();
  double y[2];
  const int n = rem_pio2(x, y);
  switch (n & 3) {
    case 0:
      return kernel_sin(y[0], y[1], 1);
    case 1:
      return kernel_cos(y[0], y[1]);
    case 2:
      return -kernel_sin(y[0], y[1], 1);
    default:
      return -kernel_cos(y[0], y[1]);
  }
}

double portable_cos(double x) {
  const std::int32_t ix = high_word(x) & 0x7fffffff;
  if (ix <= 0x3fe921fb)
    return kernel_cos(x, 0.0);
  if (ix >= 0x7ff00000)
    return std::numeric_limits<double>::quiet_NaN();
  double y[2];
  const int n = rem_pio2(x, y);
  switch (n & 3) {
    case 0:
      return kernel_cos(y[0], y[1]);
    case 1:
      return -kernel_sin(y[0], y[1], 1);
    case 2:
      return -kernel_cos(y[0], y[1]);
    default:
      return kernel_sin(y[0], y[1], 1);
  }
}

double portable_atan(double x) {
  const std::int32_t hx = high_word(x);
  const std::int32_t ix = hx & 0x7fffffff;
  int id;
  if (ix >= 0x44100000) {  // |x| >= 2^66
    if (ix > 0x7ff00000 || (ix == 0x7ff00000 && low_word(x) != 0))
      return x + x;  // NaN
    return hx > 0 ? kAtanHi[3] + kAtanLo[3] : -kAtanHi[3] - kAtanLo[3];
  }
  if (ix < 0x3fdc0000) {  // |x| < 0.4375
    if (ix < 0x3e200000)  // |x| < 2^-29
      return x;
    id = -1;
  } else {
    x = std::fabs(x);
    if (ix < 0x3ff30000) {    // |x| < 1.1875
      if (ix < 0x3fe60000) {  // 7/16 <= |x| < 11/16
        id = 0;
        x = (2.0 * x - kOne) / (2.0 + x);
      } else {  // 11/16 <= |x| < 19/16
        id = 1;
        x = (x - kOne) / (x + kOne);
      }
    } else if (ix < 0x40038000) {  // |x| < 2.4375
      id = 2;
      x = (x - 1.5) / (kOne + 1.5 * x);
    } else {  // 2.4375 <= |x| < 2^66
      id = 3;
      x = -1.0 / x;
    }
  }
  const double z = x * x;
  const double w = z * z;
  // The sum of aT[i] z^(i+1), i = 0..10, split into odd and even polynomials.
  const double s1 =
      z * (kAT[0] + w * (kAT[2] + w * (kAT[4] + w * (kAT[6] + w * (kAT[8] + w * kAT[10])))));
  const double s2 = w * (kAT[1] + w * (kAT[3] + w * (kAT[5] + w * (kAT[7] + w * kAT[9]))));
  if (id < 0)
    return x - x * (s1 + s2);
  const double result = kAtanHi[id] - ((x * (s1 + s2) - kAtanLo[id]) - x);
  return hx < 0 ? -result : result;
}

double portable_atan2(double y, double x) {
  const std::int32_t hx = high_word(x);
  const std::int32_t ix = hx & 0x7fffffff;
  const std::uint32_t lx = low_word(x);
  const std::int32_t hy = high_word(y);
  const std::int32_t iy = hy & 0x7fffffff;
  const std::uint32_t ly = low_word(y);
  if (std::isnan(x) || std::isnan(y))
    return x + y;
  if (hx == 0x3ff00000 && lx == 0)  // x = 1.0
    return portable_atan(y);
  const int m = ((hy >> 31) & 1) | ((hx >> 30) & 2);  // 2 * sign(x) + sign(y)
  if ((iy | static_cast<std::int32_t>(ly)) == 0) {    // y = 0
    switch (m) {
      case 0:
      case 1:
        return y;  // atan(+-0, +anything) = +-0
      case 2:
        return kPi + kTiny;  // atan(+0, -anything) = pi
      default:
        return -kPi - kTiny;  // atan(-0, -anything) = -pi
    }
  }
  if ((ix | static_cast<std::int32_t>(lx)) == 0)  // x = 0
    return hy < 0 ? -kPiO2 - kTiny : kPiO2 + kTiny;
  if (ix == 0x7ff00000) {  // x is infinite
    if (iy == 0x7ff00000) {
      switch (m) {
        case 0:
          return kPiO4 + kTiny;
        case 1:
          return -kPiO4 - kTiny;
        case 2:
          return 3.0 * kPiO4 + kTiny;
        default:
          return -3.0 * kPiO4 - kTiny;
      }
    }
    switch (m) {
      case 0:
        return 0.0;
      case 1:
        return -0.0;
      case 2:
        return kPi + kTiny;
      default:
        return -kPi - kTiny;
    }
  }
  if (iy == 0x7ff00000)  // y is infinite
    return hy < 0 ? -kPiO2 - kTiny : kPiO2 + kTiny;
  const std::int32_t k = (iy - ix) >> 20;
  double z;
  if (k > 60)  // |y / x| > 2^60
    z = kPiO2 + 0.5 * kPiLo;
  else if (hx < 0 && k < -60)  // |y| / x < -2^60
    z = 0.0;
  else
    z = portable_atan(std::fabs(y / x));
  switch (m) {
    case 0:
      return z;  // atan(+, +)
    case 1:
      return -z;  // atan(-, +): fdlibm flips the sign bit
    case 2:
      return kPi - (z - kPiLo);  // atan(+, -)
    default:
      return (z - kPiLo) - kPi;  // atan(-, -)
  }
}

double portable_hypot(double x, double y) {
  return std::sqrt(x * x + y * y);
}

}  // namespace holebench
