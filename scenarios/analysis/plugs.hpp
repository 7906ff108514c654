#pragma once
/// Plugs in a narrow tube (scene [analysis.plugs], SCENES.md): at every sample the axial solid
/// fraction profile along the vertical axis (bins of `bin` m; the particles' volume, centre
/// binned, over the tube's cross-section times the bin) and every particle's height go to
/// /timeseries/axial_solid_fraction (width B) and /timeseries/plug_height (width N, particles by
/// ascending id). From them the conclusions, for each threshold:
///   a plug            a maximal run of bins whose solid fraction is >= the threshold, at least
///                     `min_bins` long (shorter runs are a few beads in flight, not a plug)
///   plugs             mean and standard deviation of the number of plugs per sample
///   length            mean and standard deviation of the plug lengths lambda / d (all plugs of
///                     all samples), d the largest diameter
///   bed top           the top of the highest plug at each sample: where the profile (linear
///                     between bin centres) falls through the threshold above it, m; its rising
///                     and falling speeds: the means of its positive and of its negative changes
///                     per second over successive windows of at least `rate_window` whose two
///                     ends have the same number of plugs (a new plug on top is a jump, not a
///                     rise; a window of several samples keeps bin-sized jitter out)
///   exchange          the share of particles that were in plug k at one sample and in plug
///                     k' != k (counted from the bottom) at the next, with the same number of
///                     plugs at both, at least once in the run
///   travel            the mean |z(t + 1 s) - z(t)| over particles and over the samples t for
///                     which a sample 1 s later exists (m), all particles
/// The results at the other thresholds show how much the choice matters.
#include <cstddef>
#include <string>
#include <vector>

namespace carom {

/// One plug: its lower and upper ends along the vertical axis, m.
struct Plug {
  double lower = 0, upper = 0;
  double length() const { return upper - lower; }
};

/// The plugs of one axial profile (solid fraction per bin, bins of `bin` m from `bottom` m up).
std::vector<Plug> detect_plugs(const std::vector<double>& profile, double bottom, double bin,
                               double threshold, int min_bins);

/// The axial solid-fraction profile: `bins` bins of `bin` m from `bottom` (m), the volumes of the
/// spheres (radii m) centred in each bin over area x bin (area: the cross-section, m^2).
std::vector<double> axial_solid_fraction(const std::vector<double>& heights,
                                         const std::vector<double>& radii, double bottom,
                                         double bin, int bins, double area);

/// Where the profile lies and how plugs are told.
struct PlugGeometry {
  double bottom = 0;               ///< Lower end of the profile, m.
  double bin = 0;                  ///< Bin length, m.
  int bins = 0;                    ///< Bins.
  double area = 0;                 ///< Cross-section open to the particles, m^2.
  double diameter = 0;             ///< Largest particle diameter (the unit of plug lengths), m.
  int min_bins = 2;                ///< Shortest plug, bins.
  double rate_window = 0.05;       ///< Shortest window of the bed-top speeds, s.
  std::vector<double> thresholds;  ///< The first is the scene's; the others show sensitivity.
};

/// What the run says about its plugs at one threshold.
struct PlugConclusions {
  double threshold = 0;
  double plugs_mean = 0, plugs_std = 0;    ///< Plugs per sample.
  double length_mean = 0, length_std = 0;  ///< lambda / d over all plugs of all samples.
  std::size_t plug_count = 0;              ///< Plugs counted over all samples.
  double bed_top_mean = 0;                 ///< Mean of the bed top over the samples with a plug, m.
  double rise_speed = 0, fall_speed = 0;   ///< Mean positive / negative bed-top speeds, m/s.
  double exchange = 0;                     ///< Share of particles that changed plugs.
  double travel = 0;  ///< Mean |z(t + 1 s) - z(t)|, m (NaN: run shorter than 1 s).
};

/// Concludes from the record: times (s), the axial profiles (one row of g.bins per time) and the
/// particle heights (one row of `particles` per time), for each of g.thresholds.
std::vector<PlugConclusions> conclude_plugs(const PlugGeometry& g, const std::vector<double>& times,
                                            const std::vector<double>& profiles,
                                            const std::vector<double>& heights,
                                            std::size_t particles);

/// The "plugs" object of summary.json (JSON text).
std::string plugs_json(const PlugGeometry& g, const std::vector<PlugConclusions>& c);
/// The plugs section of report.md.
std::string plugs_report(const PlugGeometry& g, const std::vector<PlugConclusions>& c);

}  // namespace carom
