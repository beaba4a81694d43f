// Closed forms of the mean over a triangle of a linear function L given by its values v at the
// corners: of L, of L^2, of its positive part max(0, L) (or its square), and of |L|. The mean
// search's bounds use them (mean_search.cpp).
#pragma once

#include <array>

namespace holebench {

/// The mean of L over the triangle.
double linear_mean(const std::array<double, 3>& v);
/// The mean of L^2 over the triangle.
double linear_square_mean(const std::array<double, 3>& v);

/// The mean over a triangle of max(0, L)^power (power 1 or 2). With one positive corner v0
/// (v1, v2 <= 0) the positive part lives on the sub-triangle at v0 cut where L = 0, a share
/// v0^2 / ((v0 - v1)(v0 - v2)) of the area, on which L runs linearly from v0 to 0 and 0: its
/// mean there is v0 / 3, of its square v0^2 / 6. Two positive corners: the whole minus the
/// negative part, which has one.
double positive_part_mean(std::array<double, 3> v, int power);

/// The mean of |L| over a triangle.
double absolute_mean(const std::array<double, 3>& v);

}  // namespace holebench
