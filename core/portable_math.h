// Elementary functions that give the same bits on every machine: ports of fdlibm's sin, cos
// and atan2 (Sun Microsystems, 1993; the notice is in portable_math.cpp), which use only the
// IEEE 754 operations +, -, *, / on doubles (each correctly rounded, hence the same
// everywhere), and a hypot from +, *, sqrt (also correctly rounded). The C library's own
// std::sin or std::atan2 may differ in the last bit between C libraries and versions (glibc,
// musl, Apple's, Microsoft's), which changed generated cases between machines; the case
// generators use these instead, so that a case id and a seed give the same mesh bytes on
// any machine (tests/generators/case_checksums_test.cpp checks stored checksums).
//
// Accuracy (fdlibm's): sin, cos and atan2 within 1 ulp of the true value. portable_hypot
// within 2 ulp for arguments whose squares neither overflow nor underflow (the generators'
// lengths); it is not the correctly rounded hypot.
//
// Compile without -ffast-math and without floating-point contraction of these files (FMA
// would change the bits): the project's options do not enable either.
#pragma once

namespace holebench {

/// pi, the double nearest to it (0x400921FB54442D18).
inline constexpr double kPi = 3.14159265358979311600e+00;

/// sin(x) for |x| <= 2^19 * pi/2 (about 823550); throws std::domain_error beyond (the
/// generators' angles are within a few turns). NaN and infinities give NaN.
double portable_sin(double x);

/// cos(x), with the same domain as portable_sin.
double portable_cos(double x);

/// atan2(y, x) in [-pi, pi], every special case of C's atan2 (signed zeros, infinities, NaN).
double portable_atan2(double y, double x);

/// atan(x) in [-pi/2, pi/2].
double portable_atan(double x);

/// sqrt(x * x + y * y).
double portable_hypot(double x, double y);

}  // namespace holebench
