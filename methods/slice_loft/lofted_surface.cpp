#include "methods/slice_loft/lofted_surface.h"

#include "methods/slice_loft/discrete_curvature.h"

#include <algorithm>
#include <cmath>

namespace holebench::slice_loft {
namespace {

// Second derivatives of the natural cubic spline through (x_i, y_i): the tridiagonal system
// h0/6 m_{i-1} + (h0 + h1)/3 m_i + h1/6 m_{i+1} = (y_{i+1} - y_i)/h1 - (y_i - y_{i-1})/h0,
// m_0 = m_{n-1} = 0 (Thomas algorithm; the system is diagonally dominant).
template <typename Value>
std::vector<Value> natural_second_derivatives(const std::vector<double>& x,
                                              const std::vector<Value>& y, Value zero) {
  const std::size_t n = x.size();
  std::vector<Value> m(n, zero);
  if (n <= 2)
    return m;
  std::vector<double> c(n, 0.0);
  std::vector<Value> r(n, zero);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
    const double a = h0 / 6.0, b = (h0 + h1) / 3.0, cc = h1 / 6.0;
    const Value rhs = (y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0;
    const double denom = b - a * c[i - 1];
    c[i] = cc / denom;
    r[i] = (rhs - r[i - 1] * a) / denom;
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    m[i] = r[i] - m[i + 1] * c[i];
    if (i == 1)
      break;
  }
  return m;
}

// The knot interval [x_i, x_{i+1}] that holds `at` (x_0 < at < x_{n-1}).
std::size_t knot_interval(const std::vector<double>& x, double at) {
  return std::min<std::size_t>(x.size() - 2,
                               std::upper_bound(x.begin(), x.end(), at) - x.begin() - 1);
}

template <typename Value>
Value evaluate_spline(const std::vector<double>& x, const std::vector<Value>& y,
                      const std::vector<Value>& m, double at) {
  const std::size_t n = x.size();
  if (n == 1)
    return y[0];
  auto slope = [&](std::size_t i, bool at_left) {
    const double h = x[i + 1] - x[i];
    const Value base = (y[i + 1] - y[i]) / h;
    return at_left ? base - (m[i] * 2.0 + m[i + 1]) * (h / 6.0)
                   : base + (m[i] + m[i + 1] * 2.0) * (h / 6.0);
  };
  if (at <= x[0])
    return y[0] + slope(0, true) * (at - x[0]);
  if (at >= x[n - 1])
    return y[n - 1] + slope(n - 2, false) * (at - x[n - 1]);
  const std::size_t i = knot_interval(x, at);
  const double h = x[i + 1] - x[i], a = (x[i + 1] - at) / h, b = (at - x[i]) / h;
  return y[i] * a + y[i + 1] * b +
         (m[i] * (a * a * a - a) + m[i + 1] * (b * b * b - b)) * (h * h / 6.0);
}

// First and second derivatives of the spline at `at` (beyond the ends: the end slope, 0).
template <typename Value>
std::pair<Value, Value> spline_derivatives(const std::vector<double>& x,
                                           const std::vector<Value>& y, const std::vector<Value>& m,
                                           double at, Value zero) {
  const std::size_t n = x.size();
  if (n == 1)
    return {zero, zero};
  const bool before = at <= x[0], after = at >= x[n - 1];
  const std::size_t i = before ? 0 : after ? n - 2 : knot_interval(x, at);
  const double h = x[i + 1] - x[i];
  const double clamped = std::clamp(at, x[i], x[i + 1]);
  const double a = (x[i + 1] - clamped) / h, b = (clamped - x[i]) / h;
  const Value first = (y[i + 1] - y[i]) / h - m[i] * ((3.0 * a * a - 1.0) * h / 6.0) +
                      m[i + 1] * ((3.0 * b * b - 1.0) * h / 6.0);
  const Value second = (before || after) ? zero : m[i] * a + m[i + 1] * b;
  return {first, second};
}

std::vector<Point> without_repeats(const std::vector<Point>& points, double tolerance) {
  std::vector<Point> kept;
  for (const Point& p : points) {
    if (kept.empty() || (p - kept.back()).norm() > tolerance)
      kept.push_back(p);
  }
  return kept;
}

}  // namespace

NaturalCubicSpline::NaturalCubicSpline(std::vector<double> x, std::vector<Point> y)
    : x_(std::move(x)), y_(std::move(y)) {
  second_ = natural_second_derivatives(x_, y_, Point(0, 0, 0));
}

Point NaturalCubicSpline::operator()(double at) const {
  return evaluate_spline(x_, y_, second_, at);
}

std::pair<Point, Point> NaturalCubicSpline::derivatives(double at) const {
  return spline_derivatives(x_, y_, second_, at, Point(0, 0, 0));
}

std::vector<double> NaturalCubicSpline::weights(const std::vector<double>& x, double at) {
  std::vector<double> w(x.size(), 0.0), unit(x.size(), 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    unit[i] = 1.0;
    w[i] = evaluate_spline(x, unit, natural_second_derivatives(x, unit, 0.0), at);
    unit[i] = 0.0;
  }
  return w;
}

// The arc length of the point nearest the axis point origin + u d on the polyline continued
// linearly beyond both ends: a section that stops short of the axis keeps the alignment of
// s = 0 across the sections (the foot of the perpendicular, not the section's end).
double LoftedSurface::reference_arc_length(const std::vector<Point>& polyline, double u) const {
  const Point axis = origin_ + d_ * u;
  double best = 1e300, at = 0.0, walked = 0.0;
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point a = polyline[i], ab = polyline[i + 1] - a;
    const double length = ab.norm();
    if (length > 0.0) {
      double t = OpenMesh::dot(axis - a, ab) / (length * length);
      t = std::min(t, i + 2 == polyline.size() ? 1e300 : 1.0);
      t = std::max(t, i == 0 ? -1e300 : 0.0);
      const double distance = (a + ab * t - axis).sqrnorm();
      if (distance < best) {
        best = distance;
        at = walked + t * length;
      }
    }
    walked += length;
  }
  return at;
}

LoftedSurface LoftedSurface::loft(const Point& origin, const Point& d,
                                  const std::vector<SectionPolyline>& sections,
                                  const LoftOptions& options) {
  LoftedSurface surface;
  surface.origin_ = origin;
  surface.d_ = d;
  if (sections.size() < 2) {
    surface.error_ = "fewer than two section curves";
    return surface;
  }
  std::vector<std::vector<Point>> polylines;
  std::vector<double> lengths;
  double scale = 0.0;
  for (const auto& section : sections)
    scale = std::max(scale, polyline_length(section.points));
  for (const auto& section : sections) {
    if (!surface.u_.empty() && !(section.u > surface.u_.back())) {
      surface.error_ = "section offsets not increasing";
      return surface;
    }
    polylines.push_back(without_repeats(section.points, 1e-12 * scale));
    lengths.push_back(polyline_length(polylines.back()));
    if (polylines.back().size() < 2 || !(lengths.back() > 0.0)) {
      surface.error_ = "a section curve without length";
      return surface;
    }
    surface.u_.push_back(section.u);
    surface.reference_.push_back(surface.reference_arc_length(polylines.back(), section.u));
  }
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 0; k < polylines.size(); ++k) {
    lo = std::min(lo, -surface.reference_[k]);
    hi = std::max(hi, lengths[k] - surface.reference_[k]);
  }
  const double spacing = options.sample_spacing > 0.0 ? options.sample_spacing : (hi - lo) / 64;
  const int count = std::clamp(static_cast<int>(std::ceil((hi - lo) / spacing)) + 1, 4, 4000);
  for (int j = 0; j < count; ++j)
    surface.s_.push_back(lo + (hi - lo) * j / (count - 1));
  // Each section sampled on the common grid (linearly continued beyond its ends) and
  // interpolated along s: the C2 section curve.
  for (std::size_t k = 0; k < polylines.size(); ++k) {
    std::vector<Point> row;
    for (double s : surface.s_)
      row.push_back(point_at_arc_length(polylines[k], s + surface.reference_[k]));
    surface.along_.emplace_back(surface.s_, row);
    surface.grid_.push_back(std::move(row));
  }
  return surface;
}

Point LoftedSurface::across(const std::vector<double>& w, double s) const {
  Point p(0, 0, 0);
  for (std::size_t k = 0; k < along_.size(); ++k)
    p += along_[k](s) * w[k];
  return p;
}

std::vector<Point> LoftedSurface::across_on_grid(const std::vector<double>& w) const {
  std::vector<Point> curve(s_.size(), Point(0, 0, 0));
  for (std::size_t k = 0; k < grid_.size(); ++k) {
    for (std::size_t j = 0; j < s_.size(); ++j)
      curve[j] += grid_[k][j] * w[k];
  }
  return curve;
}

Point LoftedSurface::evaluate(double u, double s) const {
  return across(NaturalCubicSpline::weights(u_, u), s);
}

Point LoftedSurface::point_with_coordinate(double u, const Point& axis, double value) const {
  const std::vector<double> w = NaturalCubicSpline::weights(u_, u);
  auto coordinate_at = [&](double s, Point* point, double* slope) {
    const Point q = across(w, s);
    Point first(0, 0, 0);
    for (std::size_t k = 0; k < along_.size(); ++k)
      first += along_[k].derivatives(s).first * w[k];
    *point = q;
    *slope = OpenMesh::dot(first, axis);
    return OpenMesh::dot(q - origin_, axis);
  };
  // The crossing on the curve through the grid points, nearest to the section's middle ...
  std::vector<double> g(s_.size(), 0.0);
  for (std::size_t k = 0; k < grid_.size(); ++k) {
    for (std::size_t j = 0; j < s_.size(); ++j)
      g[j] += OpenMesh::dot(grid_[k][j] - origin_, axis) * w[k];
  }
  double at = s_.front();
  if ((value < g.front()) == (value < g.back())) {
    // No crossing: continue linearly from the nearer end.
    const bool front = std::abs(value - g.front()) < std::abs(value - g.back());
    at = front ? s_.front() : s_.back();
  } else {
    for (std::size_t j = 0; j + 1 < g.size(); ++j) {
      if ((g[j] <= value) != (g[j + 1] <= value)) {
        at = s_[j] + (value - g[j]) / (g[j + 1] - g[j]) * (s_[j + 1] - s_[j]);
        break;
      }
    }
  }
  // ... then Newton's method on the spline (exact in one step where it is affine).
  Point point;
  double slope = 0.0;
  for (int i = 0; i < 6; ++i) {
    const double coordinate = coordinate_at(at, &point, &slope);
    if (!(std::abs(slope) > 1e-12))
      break;
    const double next = at - (coordinate - value) / slope;
    if (!(std::abs(next - at) < s_[1] - s_[0]))
      break;
    at = next;
  }
  coordinate_at(at, &point, &slope);
  return point;
}

std::array<double, 2> LoftedSurface::parameters(const Point& p) const {
  const double u = u_of(p);
  const std::vector<double> w = NaturalCubicSpline::weights(u_, u);
  // The curve S(u, .) at the grid's s values (the spline across sections is linear in the
  // data, so this is exact there); nearest point on that polyline first ...
  const std::vector<Point> curve = across_on_grid(w);
  double best = 1e300, s0 = s_.front();
  for (std::size_t j = 0; j + 1 < curve.size(); ++j) {
    const Point a = curve[j], ab = curve[j + 1] - a;
    const double len2 = ab.sqrnorm();
    const double t = len2 > 0.0 ? std::clamp(OpenMesh::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const double dist = (a + ab * t - p).sqrnorm();
    if (dist < best) {
      best = dist;
      s0 = s_[j] + t * (s_[j + 1] - s_[j]);
    }
  }
  // ... then refined on the spline itself by golden-section search within one grid step.
  const double step = s_[1] - s_[0];
  auto distance2 = [&](double s) { return (across(w, s) - p).sqrnorm(); };
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = s0 - step, b = s0 + step;
  double c = b - ratio * (b - a), e = a + ratio * (b - a);
  double fc = distance2(c), fe = distance2(e);
  for (int i = 0; i < 40; ++i) {
    if (fc < fe) {
      b = e;
      e = c;
      fe = fc;
      c = b - ratio * (b - a);
      fc = distance2(c);
    } else {
      a = c;
      c = e;
      fc = fe;
      e = a + ratio * (b - a);
      fe = distance2(e);
    }
  }
  // Newton's method on (S - p) . S_s = 0 polishes s to rounding precision (exact in one step
  // where the surface is affine, so collinear boundary points stay collinear in (u, s)).
  double at = 0.5 * (a + b);
  for (int i = 0; i < 4; ++i) {
    const Point q = across(w, at);
    Point first(0, 0, 0), second(0, 0, 0);
    for (std::size_t k = 0; k < along_.size(); ++k) {
      const auto [d1, d2] = along_[k].derivatives(at);
      first += d1 * w[k];
      second += d2 * w[k];
    }
    const double f = OpenMesh::dot(q - p, first);
    const double df = OpenMesh::dot(first, first) + OpenMesh::dot(q - p, second);
    if (!(df > 0.0))
      break;
    const double next = at - f / df;
    if (!(std::abs(next - at) < step))
      break;
    at = next;
  }
  return {u, at};
}

}  // namespace holebench::slice_loft
