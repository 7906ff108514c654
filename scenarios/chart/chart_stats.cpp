#include "scenarios/chart/chart_stats.hpp"

#include <cmath>
#include <limits>

#include "core/nan.hpp"

namespace carom {

namespace {

bool usable(const ChartPoint& p) {
  return std::isfinite(p.cost) && std::isfinite(p.error);
}

/// a at least as cheap and as accurate as b, and better in one.
bool dominates(const ChartPoint& a, const ChartPoint& b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

}  // namespace

SeedStatistics seed_statistics(const std::vector<double>& values) {
  SeedStatistics s;
  double sum = 0;
  for (const double x : values)
    if (std::isfinite(x)) {
      sum += x;
      ++s.count;
    }
  if (s.count == 0) return {0, kNaN, kNaN};
  s.mean = sum / static_cast<double>(s.count);
  if (s.count < 2) {
    s.standard_error = kNaN;
    return s;
  }
  double squares = 0;
  for (const double x : values)
    if (std::isfinite(x)) squares += (x - s.mean) * (x - s.mean);
  const double n = static_cast<double>(s.count);
  s.standard_error = std::sqrt(squares / (n - 1) / n);
  return s;
}

ErrorEstimate error_against_reference(const SeedStatistics& variant,
                                      const SeedStatistics& reference, ErrorMeasure measure,
                                      bool is_reference) {
  ErrorEstimate e;
  const double mv = variant.mean, mr = reference.mean;
  const double sv = variant.standard_error, sr = reference.standard_error;
  if (measure == ErrorMeasure::Absolute) {
    e.error = mv - mr;
    e.noise = sv;
    e.uncertainty = std::sqrt(sv * sv + sr * sr);
  } else {
    const double scale = std::abs(mr);
    e.error = mv / mr - 1;
    e.noise = sv / scale;
    const double ratio = mv / mr;
    e.uncertainty = std::sqrt(sv * sv + ratio * ratio * sr * sr) / scale;
  }
  if (is_reference) {
    e.error = std::isfinite(mr) ? 0.0 : kNaN;
    e.uncertainty = e.noise;
  }
  e.within_noise =
      std::isfinite(e.error) && std::isfinite(e.uncertainty) && std::abs(e.error) < e.uncertainty;
  return e;
}

std::vector<FrontMembership> pareto_front(const std::vector<ChartPoint>& points) {
  std::vector<FrontMembership> out(points.size());
  for (std::size_t b = 0; b < points.size(); ++b) {
    if (!usable(points[b])) continue;
    bool dominated = false, clearly = false;
    for (std::size_t a = 0; a < points.size(); ++a) {
      if (a == b || !usable(points[a]) || !dominates(points[a], points[b])) continue;
      dominated = true;
      const double noise =
          std::sqrt(points[a].noise * points[a].noise + points[b].noise * points[b].noise);
      // Within noise: more accurate by less than the noise. An unknown (NaN) noise claims
      // nothing, so b then counts as clearly dominated.
      if (!(points[b].error - points[a].error < noise)) clearly = true;
    }
    out[b].on_front = !dominated;
    out[b].dominated_within_noise = dominated && !clearly;
  }
  return out;
}

std::optional<std::size_t> cheapest_within(const std::vector<ChartPoint>& points, double tolerance,
                                           std::size_t excluded) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const ChartPoint& p = points[k];
    if (k == excluded || !usable(p) || p.error > tolerance) continue;
    if (!best || p.cost < points[*best].cost ||
        (p.cost == points[*best].cost && p.error < points[*best].error))
      best = k;
  }
  return best;
}

}  // namespace carom
