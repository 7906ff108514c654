// The bed measures (scenarios/analysis/bed_measures.hpp) and the amplitude spectrum
// (scenarios/analysis/spectrum.hpp) on constructed states and series whose answers are known
// exactly: beads on a lattice, linear pressure fields, sines of known frequency and amplitude.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "scenarios/analysis/bed_measures.hpp"
#include "scenarios/analysis/spectrum.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using carom::test::kPi;

/// Tops of a lattice of `layers` layers of `per_layer` beads of diameter d resting on the floor:
/// layer j's centres at (j + 1/2) d, so its tops at (j + 1/2) d + d/2.
std::vector<double> lattice_tops(int layers, int per_layer, double d) {
  std::vector<double> tops;
  for (int j = 0; j < layers; ++j)
    for (int k = 0; k < per_layer; ++k) tops.push_back((j + 0.5) * d + 0.5 * d);
  return tops;
}

TEST(BedHeights, ShareHeightsOfALatticeAreItsLayerTops) {
  // 20 layers of 10 beads: 95 % of 200 is 190 beads, the first 19 layers; 99 % is 198, which
  // needs the 20th; half is the first 10. Each answer is a layer's top exactly (the same sum).
  const double d = 1e-3;
  std::vector<double> tops = lattice_tops(20, 10, d);
  std::shuffle(tops.begin(), tops.end(), std::mt19937(7));  // the order does not matter
  const std::vector<double> h = share_heights(tops, {0.95, 0.99, 0.5, 1.0});
  ASSERT_EQ(h.size(), 4u);
  EXPECT_EQ(h[0], (18 + 0.5) * d + 0.5 * d);
  EXPECT_EQ(h[1], (19 + 0.5) * d + 0.5 * d);
  EXPECT_EQ(h[2], (9 + 0.5) * d + 0.5 * d);
  EXPECT_EQ(h[3], (19 + 0.5) * d + 0.5 * d);
  // 0.07 x 100 is 7.000000000000001 in doubles: the 7th lowest, not the 8th.
  std::vector<double> hundred;
  for (int i = 0; i < 100; ++i) hundred.push_back(i);
  EXPECT_EQ(share_heights(hundred, {0.07})[0], 6.0);
  EXPECT_TRUE(std::isnan(share_heights({}, {0.95})[0]));
}

TEST(BedHeights, SolidFractionOfASimpleCubicLatticeIsPiOverSix) {
  // 5 x 5 beads per layer on a square lattice of spacing d over a 5d x 5d cross-section, 8
  // layers: every layer-aligned bin holds 25 whole spheres in (5d)^2 d, pi/6; bins of d/2 hold
  // their halves, pi/6 again, so the exact slab volumes are right to round-off (1e-12).
  const double d = 2e-3, a = 0.5 * d, area = 25 * d * d;
  std::vector<double> centres, radii;
  for (int j = 0; j < 8; ++j)
    for (int k = 0; k < 25; ++k) {
      centres.push_back((j + 0.5) * d);
      radii.push_back(a);
    }
  const std::vector<double> whole = layer_solid_fraction(centres, radii, d, 10, area);
  const std::vector<double> halves = layer_solid_fraction(centres, radii, 0.5 * d, 20, area);
  for (int b = 0; b < 10; ++b) EXPECT_NEAR(whole[b], b < 8 ? kPi / 6 : 0.0, 1e-12) << b;
  for (int b = 0; b < 20; ++b) EXPECT_NEAR(halves[b], b < 16 ? kPi / 6 : 0.0, 1e-12) << b;
  // Bins that cut the spheres anywhere (0.3 d) keep every sphere's volume.
  const std::vector<double> cut = layer_solid_fraction(centres, radii, 0.3 * d, 40, area);
  double volume = 0.0;
  for (double phi : cut) volume += phi * area * 0.3 * d;
  EXPECT_NEAR(volume / (200 * kPi / 6 * d * d * d), 1.0, 1e-12);
  // The surface: the last full bin (7) at pi/6, the next empty; linear between their centres.
  const double phi = kPi / 6;
  EXPECT_NEAR(surface_height(whole, d, 0.1), 7.5 * d + d * (phi - 0.1) / phi, 1e-15);
}

TEST(BedHeights, SurfaceIsTheHighestFallThroughTheThreshold) {
  // Bins of 1 mm. A splash above the bed (bin 5 at 0.05) is below the threshold and ignored;
  // the highest bin at or above 0.1 is bin 2 (0.3), the next 0.05: 2.5 + (0.3 - 0.1) / 0.25 bins.
  EXPECT_NEAR(surface_height({0.6, 0.6, 0.3, 0.05, 0.0, 0.05}, 1e-3, 0.1), 3.3e-3, 1e-15);
  EXPECT_NEAR(surface_height({0.6, 0.6, 0.1}, 1e-3, 0.1), 3e-3, 1e-15);  // up to the top
  EXPECT_TRUE(std::isnan(surface_height({0.05, 0.02}, 1e-3, 0.1)));
}

TEST(BedPressure, ProbesInterpolateALinearFieldExactly) {
  // Cells of 1 x 2 x 4 mm, 3 x 2 x 5 of them; p = 100 - 2000 z + 50 x at the cell centres. A
  // trilinear interpolation reproduces a linear field exactly between the centres, and holds the
  // outermost centres' values beyond them.
  const std::array<int, 3> cells{3, 2, 5};
  const Vec3 lower(0, 0, 0), size(1e-3, 2e-3, 4e-3);
  std::vector<double> p, open;
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) {
        p.push_back(100.0 - 2000.0 * (z + 0.5) * 4e-3 + 50.0 * (x + 0.5) * 1e-3);
        open.push_back(x == 0 ? 0.5 : 1.0);  // a wall cuts the first column of cells in half
      }
  const auto field = [](double x, double z) { return 100.0 - 2000.0 * z + 50.0 * x; };
  EXPECT_NEAR(pressure_at_point(p, cells, lower, size, Vec3(1.7e-3, 1.1e-3, 9e-3)),
              field(1.7e-3, 9e-3), 1e-12);
  EXPECT_NEAR(pressure_at_point(p, cells, lower, size, Vec3(0.0, 0.0, 0.0)),
              field(0.5e-3, 2e-3), 1e-12);  // below and beside the outermost centres
  // Across the section, open-volume weighted: x mean (0.5 x0 + x1 + x2) / 2.5 of the centres.
  const double mean_x = (0.5 * 0.5e-3 + 1.5e-3 + 2.5e-3) / 2.5;
  EXPECT_NEAR(pressure_at_level(p, open, cells, lower, size, 2, 11e-3), field(mean_x, 11e-3), 1e-12);
  EXPECT_NEAR(pressure_at_level(p, open, cells, lower, size, 2, 19.9e-3), field(mean_x, 18e-3), 1e-12);
}

TEST(BedMaps, BeadsAreSharedOverBinsAndTheSlabByVolume) {
  // A 4 x 2 x 6 mm domain, maps across x (2 bins of 2 mm) and up z (3 bins of 2 mm) in a slab
  // 1 mm thick about y = 1 mm. Beads 0-2 lie wholly inside a bin and the slab; bead 3 is
  // centred on the face x = 2 mm (half in each of two bins, by symmetry); bead 4 on the slab's
  // face y = 1.5 mm (half inside); bead 5 outside the slab, bead 6 above the domain.
  BedGeometry g;
  g.vertical = 2;
  g.floor = 0;
  g.extent = 6e-3;
  g.shares = {0.95};
  g.map_axis = 0;
  g.map_bins = {2, 3};
  g.map_lower = 0;
  g.map_upper = 4e-3;
  g.slab_centre = 1e-3;
  g.slab_thickness = 1e-3;
  g.lower = {0, 0, 0};
  g.upper = {4e-3, 2e-3, 6e-3};
  const std::vector<Vec3> r{{0.5e-3, 1.0e-3, 0.5e-3}, {3.0e-3, 0.8e-3, 5.0e-3},
                            {3.5e-3, 1.2e-3, 5.5e-3}, {2.0e-3, 1.0e-3, 3.0e-3},
                            {1.0e-3, 1.5e-3, 3.0e-3}, {1.0e-3, 1.8e-3, 1.0e-3},
                            {1.0e-3, 1.0e-3, 7.0e-3}};
  const std::vector<Vec3> v{{1, 0, 2}, {0, 0, -1}, {-2, 0, -3}, {4, 0, 8}, {-1, 0, 1}, {5, 5, 5}, {5, 5, 5}};
  const std::vector<double> radius(7, 0.25e-3), mass{1e-6, 2e-6, 3e-6, 4e-6, 6e-6, 5e-6, 5e-6};
  const std::vector<double> row = map_sums(g, r, v, radius, mass);
  ASSERT_EQ(row.size(), 2u * 3u * 4u);
  const double vol = 4.0 / 3.0 * kPi * 0.25e-3 * 0.25e-3 * 0.25e-3;
  const auto at = [&](int up, int across, int k) { return row[(up * 2 + across) * 4 + k]; };
  // Whole beads: to round-off of the closed-form overlap (1e-15 of a sphere, tolerance 1e-12).
  EXPECT_NEAR(at(0, 0, 0) / vol, 1.0, 1e-12);
  EXPECT_NEAR(at(0, 0, 1), 1e-6, 1e-18);
  EXPECT_NEAR(at(0, 0, 2), 1e-6, 1e-18);
  EXPECT_NEAR(at(0, 0, 3), 2e-6, 1e-18);
  EXPECT_NEAR(at(2, 1, 0) / vol, 2.0, 1e-12);
  EXPECT_NEAR(at(2, 1, 1), 5e-6, 1e-18);
  EXPECT_NEAR(at(2, 1, 2), -6e-6, 1e-18);
  EXPECT_NEAR(at(2, 1, 3), -2e-6 - 9e-6, 1e-18);
  // Bead 3 halved across x = 2 mm, bead 4 halved by the slab face (both in the middle row).
  EXPECT_NEAR(at(1, 1, 0) / vol, 0.5, 1e-12);
  EXPECT_NEAR(at(1, 1, 3), 0.5 * 4e-6 * 8, 1e-17);
  EXPECT_NEAR(at(1, 0, 0) / vol, 1.0, 1e-12);
  EXPECT_NEAR(at(1, 0, 1), 0.5 * 4e-6 + 0.5 * 6e-6, 1e-17);
  EXPECT_NEAR(at(1, 0, 2), 0.5 * 4e-6 * 4 - 0.5 * 6e-6, 1e-17);
  // Nothing else anywhere: the volume over every bin is four and a half beads'.
  double volume = 0.0;
  for (std::size_t b = 0; b < 6; ++b) volume += row[4 * b];
  EXPECT_NEAR(volume / vol, 4.5, 1e-12);
  // A periodic depth: the slab covers the whole depth, and a bead across its face y = 0 is
  // counted whole through its image.
  g.periodic = {false, true, false};
  g.slab_centre = 1e-3;
  g.slab_thickness = 2e-3;
  const std::vector<double> wrapped = map_sums(g, {{1e-3, 0.1e-3, 1e-3}}, {{0, 0, 0}}, {0.25e-3}, {1e-6});
  EXPECT_NEAR(wrapped[0] / vol, 1.0, 1e-12);
  g.periodic = {false, false, false};
  EXPECT_LT(map_sums(g, {{1e-3, 0.1e-3, 1e-3}}, {{0, 0, 0}}, {0.25e-3}, {1e-6})[0] / vol, 0.9);
  g.slab_centre = 1e-3;
  g.slab_thickness = 1e-3;

  // Two samples (the second with every sum doubled) averaged: solid fraction sum V / (2 V_bin),
  // velocity sum m v / sum m, flux sum m v / (2 V_bin); a bin no bead visited has no velocity.
  std::vector<double> map = row;
  for (double x : row) map.push_back(2 * x);
  const std::vector<double> heights{1e-3, 2e-3, 3e-3, 4e-3};
  const BedConclusions c = conclude_bed(g, {0.0, 0.1}, heights, {}, {}, map);
  const double bin = 2e-3 * 2e-3 * 1e-3;
  EXPECT_DOUBLE_EQ(c.solid_fraction[0], 3 * row[0] / (2 * bin));
  EXPECT_DOUBLE_EQ(c.velocity[0], row[2] / row[1]);
  EXPECT_DOUBLE_EQ(c.velocity[1], row[3] / row[1]);
  EXPECT_DOUBLE_EQ(c.flux[2 * 5 + 1], 3 * row[4 * 5 + 3] / (2 * bin));
  EXPECT_TRUE(std::isnan(c.velocity[2 * 1]));  // bottom right: no bead
  EXPECT_EQ(c.flux[2 * 1], 0.0);
  // The heights over both samples.
  EXPECT_DOUBLE_EQ(c.heights[0].mean, 2e-3);
  EXPECT_DOUBLE_EQ(c.heights[1].mean, 3e-3);
  EXPECT_DOUBLE_EQ(c.heights[1].sd, 1e-3);
  EXPECT_EQ(c.heights[0].min, 1e-3);
  EXPECT_EQ(c.heights[1].max, 4e-3);
}

TEST(Spectrum, SineOnTheFrequencyGridIsExact) {
  // 400 samples every 2.5 ms (T = 1 s, resolution 1 Hz, Nyquist 200 Hz) of 30 + 4 sin(2 pi 37 t
  // + 0.3): the amplitude at 37 Hz is 4 and every other bin is 0, to round-off (1e-12 of it).
  const double dt = 2.5e-3;
  std::vector<double> x;
  for (int n = 0; n < 400; ++n) x.push_back(30.0 + 4.0 * std::sin(2 * kPi * 37.0 * n * dt + 0.3));
  const Spectrum s = amplitude_spectrum(x, dt);
  EXPECT_NEAR(s.resolution(), 1.0, 1e-12);
  EXPECT_NEAR(s.nyquist(), 200.0, 1e-12);
  ASSERT_EQ(s.amplitude.size(), 200u);
  EXPECT_NEAR(s.dominant_frequency, 37.0, 1e-12);
  EXPECT_NEAR(s.dominant_amplitude, 4.0, 1e-12);
  EXPECT_NEAR(s.mean, 30.0, 1e-12);
  EXPECT_NEAR(s.standard_deviation, 4.0 / std::sqrt(2.0), 1e-12);
  for (std::size_t k = 0; k < s.amplitude.size(); ++k) {
    if (k == 36) continue;
    EXPECT_LT(s.amplitude[k], 1e-11) << s.frequency[k] << " Hz";
  }
}

TEST(Spectrum, SineOffTheGridPeaksWithinHalfABin) {
  // 37.4 Hz over T = 1 s: the peak lies in the bin nearest, 37 Hz, within half the resolution.
  const double dt = 2.5e-3;
  std::vector<double> x;
  for (int n = 0; n < 400; ++n) x.push_back(2.0 * std::sin(2 * kPi * 37.4 * n * dt));
  const Spectrum s = amplitude_spectrum(x, dt);
  EXPECT_LE(std::abs(s.dominant_frequency - 37.4), 0.5 * s.resolution());
  EXPECT_LT(s.dominant_amplitude, 2.0);  // leakage spreads it
  EXPECT_GT(s.dominant_amplitude, 2.0 * 2.0 / kPi);  // by at most the sinc's worst, 2/pi
}

TEST(Spectrum, FastTransformAgreesWithThePlainSumAndParseval) {
  // Random series of a prime length, an odd one and a power of two: the FFT against the O(N^2)
  // sum to 1e-12 of the largest amplitude; Parseval: the amplitudes' power is the variance.
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(5.0, 2.0);
  for (std::size_t n : {97u, 255u, 256u}) {
    std::vector<double> x(n);
    for (double& v : x) v = noise(rng);
    const Spectrum fast = amplitude_spectrum(x, 0.01), slow = amplitude_spectrum_by_sum(x, 0.01);
    ASSERT_EQ(fast.amplitude.size(), slow.amplitude.size());
    double largest = 0.0, power = 0.0;
    for (double a : slow.amplitude) largest = std::max(largest, a);
    for (std::size_t k = 0; k < fast.amplitude.size(); ++k) {
      EXPECT_NEAR(fast.amplitude[k], slow.amplitude[k], 1e-12 * largest) << n << " " << k;
      const bool nyquist = 2 * (k + 1) == n;
      power += fast.amplitude[k] * fast.amplitude[k] * (nyquist ? 1.0 : 0.5);
    }
    EXPECT_EQ(fast.dominant_frequency, slow.dominant_frequency) << n;
    EXPECT_NEAR(power, fast.standard_deviation * fast.standard_deviation, 1e-12 * power) << n;
  }
  EXPECT_TRUE(std::isnan(amplitude_spectrum({1.0}, 0.1).dominant_frequency));
}

TEST(BedPressure, ProbeSpectrumUsesTheEvenlySpacedSamplesAfterStart) {
  // Samples every 5 ms from t = 0 to 0.995 s, then a last one at 0.997 s (an end time off the
  // grid); the gas series NaN at t = 0 (before the first fluid step). After start = 0.2 s the
  // probe reads 100 + 10 sin(2 pi 20 t): 160 samples, T = 0.8 s, resolution 1.25 Hz, so 20 Hz
  // is on the grid and its amplitude 10 exactly. The last sample, 1e6 Pa, must be left out.
  BedGeometry g;
  g.shares = {0.95};
  g.start = 0.2;
  g.gas = true;
  g.probe_heights = {0.01};
  std::vector<double> times, heights, probe;
  for (int n = 0; n < 200; ++n) {
    const double t = n * 5e-3;
    times.push_back(t);
    heights.insert(heights.end(), {t, t});
    probe.push_back(n == 0 ? NAN : 100.0 + 10.0 * std::sin(2 * kPi * 20.0 * t));
  }
  times.push_back(0.997);
  heights.insert(heights.end(), {0.997, 0.997});
  probe.push_back(1e6);
  const std::vector<double> pressure(3 * times.size(), 1.0);
  const std::vector<double> map(times.size() * g.map_width(), 0.0);
  const BedConclusions c = conclude_bed(g, times, heights, pressure, probe, map);
  ASSERT_EQ(c.probes.size(), 1u);
  const Spectrum& s = c.probes[0];
  EXPECT_EQ(s.samples, 160u);
  EXPECT_NEAR(s.interval, 5e-3, 1e-15);
  EXPECT_NEAR(s.resolution(), 1.25, 1e-12);
  EXPECT_NEAR(s.dominant_frequency, 20.0, 1e-9);
  EXPECT_NEAR(s.dominant_amplitude, 10.0, 1e-9);
  EXPECT_NEAR(s.mean, 100.0, 1e-9);
  EXPECT_NEAR(s.standard_deviation, 10.0 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(c.samples, 161u);  // every sample at or after start counts for the heights
  EXPECT_DOUBLE_EQ(c.heights[0].max, 0.997);
  // The pressure balance: the gas column's part apart.
  EXPECT_TRUE(c.pressure);
}

TEST(BedConclusions, ARunEndingBeforeTheStartConcludesNothingAndSaysSo) {
  // Start at 1 s, samples to 0.2 s: no sample to average. Every number is NaN (null in JSON),
  // the spectra are empty, and the report says why instead of a table of n/a.
  BedGeometry g;
  g.shares = {0.95};
  g.start = 1.0;
  g.gas = true;
  g.probe_heights = {0.01};
  const std::vector<double> times{0.0, 0.1, 0.2};
  const BedConclusions c = conclude_bed(g, times, std::vector<double>(6, 1e-3),
                                        std::vector<double>(9, 1.0), std::vector<double>(3, 5.0),
                                        std::vector<double>(3 * g.map_width(), 0.0));
  EXPECT_EQ(c.samples, 0u);
  EXPECT_TRUE(std::isnan(c.heights[0].mean));
  EXPECT_TRUE(std::isnan(c.pressure_drop.mean));
  ASSERT_EQ(c.probes.size(), 1u);
  EXPECT_TRUE(c.probes[0].amplitude.empty());
  EXPECT_TRUE(std::isnan(c.probes[0].resolution()));
  EXPECT_TRUE(std::isnan(c.solid_fraction[0]));
  EXPECT_NE(bed_report(g, c).find("No sample at or after `start`"), std::string::npos);
  EXPECT_NE(bed_json(g, c).find("\"mean\": null"), std::string::npos);
}

}  // namespace
}  // namespace carom
