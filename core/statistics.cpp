#include "core/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace holebench {

double median_of(std::vector<double> values) {
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double quantile(const std::vector<double>& sorted, double p) {
  const double position = p * static_cast<double>(sorted.size() - 1);
  const auto lower = static_cast<std::size_t>(std::floor(position));
  const std::size_t upper = std::min(lower + 1, sorted.size() - 1);
  const double t = position - static_cast<double>(lower);
  return sorted[lower] + t * (sorted[upper] - sorted[lower]);
}

namespace {

/// P(W+ <= w) and P(W+ >= w) for doubled ranks `ranks2` (integers: twice the midranks), w
/// doubled too, over the 2^n equally likely sign patterns.
std::pair<double, double> exact_tails(const std::vector<long>& ranks2, long w2) {
  const long total = std::accumulate(ranks2.begin(), ranks2.end(), 0L);
  std::vector<double> count(static_cast<std::size_t>(total) + 1, 0.0);
  count[0] = 1.0;
  long reach = 0;
  for (long r : ranks2) {
    for (long s = reach; s >= 0; --s) {
      if (count[static_cast<std::size_t>(s)] != 0.0)
        count[static_cast<std::size_t>(s + r)] += count[static_cast<std::size_t>(s)];
    }
    reach += r;
  }
  const double patterns = std::ldexp(1.0, static_cast<int>(ranks2.size()));
  double below = 0.0, above = 0.0;
  for (long s = 0; s <= total; ++s) {
    if (s <= w2)
      below += count[static_cast<std::size_t>(s)];
    if (s >= w2)
      above += count[static_cast<std::size_t>(s)];
  }
  return {below / patterns, above / patterns};
}

}  // namespace

SignedRankTest wilcoxon_signed_rank(const std::vector<double>& differences,
                                    const SignedRankOptions& options) {
  SignedRankTest test;
  std::vector<double> nonzero;
  for (double d : differences) {
    if (d == 0.0)
      ++test.zeros;
    else
      nonzero.push_back(d);
  }
  test.n = nonzero.size();
  if (test.n == 0)
    return test;
  std::sort(nonzero.begin(), nonzero.end(),
            [](double a, double b) { return std::fabs(a) < std::fabs(b); });

  // Midranks, doubled so that they are integers: a group of tied |d| at 1-based positions
  // i..j gets the rank (i + j) / 2.
  std::vector<long> ranks2(test.n);
  double tie_term = 0.0;  // sum of t^3 - t over groups of t tied magnitudes
  for (std::size_t i = 0; i < test.n;) {
    std::size_t j = i;
    while (j + 1 < test.n && std::fabs(nonzero[j + 1]) == std::fabs(nonzero[i]))
      ++j;
    const auto t = static_cast<double>(j - i + 1);
    tie_term += t * t * t - t;
    for (std::size_t k = i; k <= j; ++k)
      ranks2[k] = static_cast<long>(i + 1 + j + 1);
    i = j + 1;
  }
  long w_plus2 = 0;
  for (std::size_t i = 0; i < test.n; ++i) {
    if (nonzero[i] > 0.0)
      w_plus2 += ranks2[i];
  }
  const auto n = static_cast<double>(test.n);
  test.w_plus = 0.5 * static_cast<double>(w_plus2);
  test.w_minus = n * (n + 1.0) / 2.0 - test.w_plus;

  const double mean = n * (n + 1.0) / 4.0;
  const double variance = n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - tie_term / 48.0;
  test.z = variance > 0.0 ? (test.w_plus - mean) / std::sqrt(variance) : 0.0;
  if (test.n <= options.max_exact_n) {
    const auto [below, above] = exact_tails(ranks2, w_plus2);
    test.p_value = std::min(1.0, 2.0 * std::min(below, above));
    test.exact = true;
  } else {
    test.p_value = std::min(1.0, std::erfc(std::fabs(test.z) / std::sqrt(2.0)));
  }
  return test;
}

PairedComparison compare_paired(const std::vector<BoundedValue>& first,
                                const std::vector<BoundedValue>& second,
                                const SignedRankOptions& options) {
  PairedComparison result;
  const std::size_t count = std::min(first.size(), second.size());
  std::vector<double> differences;
  differences.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const BoundedValue& a = first[i];
    const BoundedValue& b = second[i];
    if (a.upper < b.lower) {
      ++result.wins;
      differences.push_back(a.value - b.value);
    } else if (b.upper < a.lower) {
      ++result.losses;
      differences.push_back(a.value - b.value);
    } else {
      ++result.ties;
      differences.push_back(0.0);
    }
  }
  result.test = wilcoxon_signed_rank(differences, options);
  return result;
}

}  // namespace holebench
