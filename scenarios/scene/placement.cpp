#include "scenarios/scene/placement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace carom {

Placer::Placer(System& system, std::vector<double> radii)
    : system_(system), radii_(std::move(radii)), grid_(system.domain, radii_) {
  for (std::size_t i = 0; i < system_.particles.size(); ++i)
    grid_.insert(static_cast<std::int32_t>(i), system_.particles.position[i]);
}

void Placer::centre_range(int k, double a, const Vec3& lower, const Vec3& upper, double& lo, double& hi,
                          bool& wraps) const {
  carom::centre_range(system_.domain, k, a, lower, upper, lo, hi, wraps);
}

void centre_range(const Domain& d, int k, double a, const Vec3& lower, const Vec3& upper, double& lo, double& hi,
                  bool& wraps) {
  wraps = d.periodic[k] && lower[k] <= d.lower[k] && upper[k] >= d.upper[k];
  if (wraps) {
    lo = d.lower[k];
    hi = d.upper[k];
  } else {
    lo = lower[k] + a;
    hi = upper[k] - a;
  }
}

bool Placer::fits(std::int32_t index, const Vec3& r, double a) const {
  for (int k = 0; k < 3; ++k)
    if (r[k] < system_.domain.lower[k] || r[k] >= system_.domain.upper[k]) return false;
  for (const Wall& wall : system_.walls)
    if (wall.gap(r, a) < 0.0) return false;
  bool overlap = false;
  grid_.for_each_candidate(index, [&](std::int32_t j) {
    if (overlap || j >= index) return;  // only particles already placed
    Vec3 dr = r - system_.particles.position[j];
    system_.domain.minimum_image(dr);
    const double contact = a + radii_[j];
    if (dr.squaredNorm() < contact * contact) overlap = true;
  });
  return !overlap;
}

bool Placer::try_place(std::uint32_t s, const Vec3& r) {
  const auto index = static_cast<std::int32_t>(system_.particles.size());
  const double a = radii_.at(static_cast<std::size_t>(index));
  grid_.insert(index, r);
  if (!fits(index, r, a)) {
    grid_.remove(index);
    return false;
  }
  system_.add_particle(s, r, Vec3::Zero());
  return true;
}

std::size_t Placer::random(std::uint32_t s, std::size_t count, const Vec3& lower, const Vec3& upper, Rng& rng,
                           std::size_t attempts_per_particle) {
  const double a = system_.species.at(s).radius();
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    bool wraps;
    centre_range(k, a, lower, upper, lo[k], hi[k], wraps);
    if (hi[k] < lo[k]) return 0;
  }
  std::size_t placed = 0;
  for (; placed < count; ++placed) {
    std::size_t attempt = 0;
    for (;; ++attempt) {
      if (attempt == attempts_per_particle || (attempt % 1024 == 0 && stopped())) return placed;
      const Vec3 r(rng.uniform(lo[0], hi[0]), rng.uniform(lo[1], hi[1]), rng.uniform(lo[2], hi[2]));
      if (try_place(s, r)) break;
    }
  }
  return placed;
}

namespace {
/// Points along one axis of a lattice with nominal spacing h.
struct AxisSites {
  double first = 0;
  double step = 0;
  long count = 0;
};

AxisSites axis_sites(double lo, double hi, bool wraps, double h, bool even) {
  AxisSites axis;
  if (hi < lo) return axis;
  if (wraps) {
    long m = static_cast<long>(std::floor((hi - lo) / h));
    if (even) m -= m % 2;  // fcc parity must survive the periodic wrap
    if (m < 1) return axis;
    axis.count = m;
    axis.step = (hi - lo) / static_cast<double>(m);
    axis.first = lo + 0.5 * axis.step;
  } else {
    axis.count = static_cast<long>(std::floor((hi - lo) / h)) + 1;
    axis.step = h;
    axis.first = lo + 0.5 * ((hi - lo) - static_cast<double>(axis.count - 1) * h);  // centred
  }
  return axis;
}
}  // namespace

LatticePlan plan_lattice(const Domain& domain, double a, std::size_t count, const Vec3& lower, const Vec3& upper,
                         bool fcc) {
  LatticePlan plan;
  double lo[3], hi[3];
  bool wraps[3];
  double volume = 1.0;
  for (int k = 0; k < 3; ++k) {
    centre_range(domain, k, a, lower, upper, lo[k], hi[k], wraps[k]);
    if (hi[k] < lo[k]) return plan;
    volume *= std::max(hi[k] - lo[k], 2.0 * a);
  }
  // Nearest neighbours of the fcc sites are at h sqrt(2).
  const double h_min = fcc ? std::sqrt(2.0) * a * (1.0 + 1e-12) : 2.0 * a * (1.0 + 1e-12);
  double h = std::max(h_min, std::cbrt(volume / (fcc ? 2.0 * static_cast<double>(count) : 1.0 * static_cast<double>(count))));
  for (;;) {
    double sites = 1.0;
    for (int k = 0; k < 3; ++k) sites *= static_cast<double>(axis_sites(lo[k], hi[k], wraps[k], h, fcc).count);
    if (fcc) sites = std::floor(sites / 2.0);
    plan.spacing = h;
    plan.sites = static_cast<std::size_t>(std::min(sites, 1e18));
    if (sites >= static_cast<double>(count) || h <= h_min) return plan;
    h = std::max(h_min, 0.98 * h);
  }
}

std::size_t Placer::lattice(std::uint32_t s, std::size_t count, const Vec3& lower, const Vec3& upper, bool fcc) {
  if (count == 0) return 0;
  const double a = system_.species.at(s).radius();
  const LatticePlan plan = plan_lattice(system_.domain, a, count, lower, upper, fcc);
  if (plan.sites == 0) return 0;
  double lo[3], hi[3];
  bool wraps[3];
  AxisSites axes[3];
  for (int k = 0; k < 3; ++k) {
    centre_range(k, a, lower, upper, lo[k], hi[k], wraps[k]);
    axes[k] = axis_sites(lo[k], hi[k], wraps[k], plan.spacing, fcc);
  }
  std::vector<Vec3> sites;
  for (long z = 0; z < axes[2].count; ++z) {
    if (stopped()) return 0;
    for (long y = 0; y < axes[1].count; ++y)
      for (long x = 0; x < axes[0].count; ++x) {
        if (fcc && (x + y + z) % 2 != 0) continue;
        sites.emplace_back(axes[0].first + x * axes[0].step, axes[1].first + y * axes[1].step,
                           axes[2].first + z * axes[2].step);
      }
  }
  const Vec3& g = system_.flight.gravity;
  if (g.squaredNorm() > 0.0)
    std::stable_sort(sites.begin(), sites.end(), [&](const Vec3& p, const Vec3& q) { return g.dot(p) > g.dot(q); });
  std::size_t placed = 0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    if (placed == count || (k % 1024 == 0 && stopped())) break;
    if (try_place(s, sites[k])) ++placed;
  }
  return placed;
}

void set_maxwellian(System& system, std::size_t first, double temperature, double rms_velocity, Rng& rng) {
  ParticleStore& p = system.particles;
  const std::size_t end = p.size();
  if (end <= first || (temperature <= 0.0 && rms_velocity <= 0.0)) return;
  const std::size_t n = end - first;
  Vec3 momentum = Vec3::Zero();
  double mass = 0.0, target = 0.0;
  for (std::size_t i = first; i < end; ++i) {
    const double sigma = rms_velocity > 0.0 ? rms_velocity / std::sqrt(3.0) : std::sqrt(temperature / p.mass[i]);
    p.velocity[i] = rng.normal3() * sigma;
    momentum += p.mass[i] * p.velocity[i];
    mass += p.mass[i];
    target += rms_velocity > 0.0 ? 0.5 * p.mass[i] * rms_velocity * rms_velocity : 0.0;
  }
  target = rms_velocity > 0.0 ? target * static_cast<double>(n - 1) / static_cast<double>(n)
                              : 1.5 * static_cast<double>(n - 1) * temperature;
  double kinetic = 0.0;
  for (std::size_t i = first; i < end; ++i) {
    p.velocity[i] -= momentum / mass;
    kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
  }
  if (n < 2 || kinetic <= 0.0) return;
  const double scale = std::sqrt(target / kinetic);
  for (std::size_t i = first; i < end; ++i) p.velocity[i] *= scale;
}

}  // namespace carom
