#pragma once
/// What a fluidized-bed researcher measures (scene [analysis.bed], SCENES.md), for every method.
/// Heights are along the vertical axis (opposite gravity) above the domain's floor (its lower
/// face along that axis). Every sample adds to /timeseries:
///   bed_height          Q + 1, m: for each share q of height_shares the height below which that
///                       share of the beads lie, a bead counted by its top (centre + radius), as
///                       the narrow-tube study counts a bead at the lid: the k-th lowest top,
///                       k = ceil(q N); then the surface: the height where the horizontally
///                       averaged solid fraction, in bins of `bin` from the floor up (each
///                       sphere's exact volume in each bin, over the open cross-section times
///                       the bin), falls through `threshold` above the highest bin at or above
///                       it (linear between bin centres; NaN when no bin reaches it)
///   bed_pressure        3, Pa (with a gas): the gas pressure drop over the domain
///                       (GasCoupling::pressure_drop), the gas's net momentum inflow per area
///                       (GasCoupling::momentum_inflow), and the beads' buoyant weight per area
///                       W/A = sum_i (rho_p,i - rho_g) |g| V_i / A, A the gas grid's open
///                       cross-section (its open volume over its height)
///   bed_probe_pressure  P + H, Pa (with a gas and probes): the gas pressure at each probe point
///                       (trilinear between gas-cell centres, the outermost centres' values
///                       beyond them), then at each probe height (the open-volume-weighted mean
///                       over the gas cells of a layer, linear between layer centres)
///   bed_map_sums        U x C x 4 (U bins up, C across; up-major): per bin of the mid-plane slab
///                       the beads' volume (m^3), mass (kg) and momentum across and up (kg m/s),
///                       each bead's shared by the exact part of its volume in the bin
///                       (fluid/overlap.hpp; periodic images included), so the maps are smooth
///                       where bins are a few diameters and hold the whole solid volume
/// The gas series are NaN before the first fluid step. The conclusions use the samples at or
/// after `start` (s):
///   heights     mean, standard deviation, minimum and maximum of each bed_height column
///   pressure    the mean pressure drop and its spread, the gas column's own part rho_g |g| H,
///               the mean momentum inflow, the part that carries the bed
///               drop - rho_g |g| H + inflow (fluid/README.md, "pressure drop and weight"), the
///               mean W/A, and their ratio
///   probes      mean, standard deviation and amplitude spectrum (spectrum.hpp) of each probe
///               series over its evenly spaced samples (from the first finite one at or after
///               `start`, while the intervals equal the first within 1e-6 of it)
///   maps        time averages over the slab's bins: solid fraction sum V / (samples V_bin),
///               solids velocity sum m v / sum m (m/s; NaN in a bin no bead visited), solids mass
///               flux sum m v / (samples V_bin) (kg/(m^2 s)), across and up.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "events/method.hpp"
#include "fluid/coupling.hpp"
#include "scenarios/analysis/gas_probes.hpp"
#include "scenarios/analysis/spectrum.hpp"

namespace carom {

struct Scene;

/// Where and how the bed is measured (from [analysis.bed] and the system).
struct BedGeometry {
  int vertical = 2;            ///< Axis opposite gravity (0 x, 1 y, 2 z).
  double floor = 0;            ///< Lower face of the domain along `vertical`, m.
  double extent = 0;           ///< Extent of the domain along `vertical`, m.
  double area = 0;             ///< Cross-section open to the beads, m^2.
  std::vector<double> shares;  ///< Shares q of the share heights, in (0, 1].
  double threshold = 0.1;      ///< Solid fraction that marks the surface.
  double bin = 0;              ///< Bin thickness of the solid-fraction profile, m.
  int bins = 0;                ///< Its bins from the floor up.
  double start = 0;            ///< Samples before this time are left out of the conclusions, s.
  // With a gas.
  bool gas = false;
  double gas_density = 0;            ///< rho_g, kg/m^3.
  double gravity = 0;                ///< |g|, m/s^2.
  double gas_height = 0;             ///< H: the gas grid's extent along `vertical`, m.
  std::vector<Vec3> probes;          ///< Probe points, m.
  std::vector<double> probe_heights; ///< Probe heights above the floor, m.
  // The mid-plane maps.
  int map_axis = 0;                  ///< Axis across the maps (horizontal).
  std::array<int, 2> map_bins{1, 1}; ///< Bins across and up.
  double map_lower = 0, map_upper = 0;  ///< Extent of the maps across, m (up: the floor to the top).
  double slab_centre = 0;            ///< Slab centre along the third axis, m.
  double slab_thickness = 0;         ///< Slab thickness along the third axis, m.
  std::array<double, 3> lower{}, upper{};  ///< The domain, m.
  std::array<bool, 3> periodic{};          ///< Its periodic axes.

  int depth_axis() const { return 3 - vertical - map_axis; }
  std::size_t height_width() const { return shares.size() + 1; }
  std::size_t probe_width() const { return probes.size() + probe_heights.size(); }
  static constexpr std::size_t kMapValues = 4;
  std::size_t map_width() const {
    return static_cast<std::size_t>(map_bins[0]) * static_cast<std::size_t>(map_bins[1]) * kMapValues;
  }
  /// Volume of one map bin, m^3.
  double map_bin_volume() const {
    return (map_upper - map_lower) / map_bins[0] * extent / map_bins[1] * slab_thickness;
  }
};

/// The geometry of a scene's [analysis.bed].
BedGeometry bed_geometry(const Scene& scene);

// ---- one sample ----------------------------------------------------------------------------

/// Heights below which each share q of the beads' tops lie: the k-th lowest of `tops`,
/// k = ceil(q N) (a relative 1e-12 taken off q N, so that 0.95 x 200 is 190 and not 191). NaN
/// without beads.
std::vector<double> share_heights(std::vector<double> tops, const std::vector<double>& shares);

/// Solid fraction in `bins` bins of `bin` m from 0 up: each sphere's exact volume between the
/// bin's faces (centres `heights`, radii `radii`, m, above the floor), over area x bin.
std::vector<double> layer_solid_fraction(const std::vector<double>& heights,
                                         const std::vector<double>& radii, double bin, int bins,
                                         double area);

/// The surface of a solid-fraction profile (bins of `bin` m from 0): above the highest bin at
/// or above `threshold`, where the profile, linear between bin centres, falls through it (the
/// top of the profile when that bin is the last); NaN when no bin reaches it.
double surface_height(const std::vector<double>& profile, double bin, double threshold);

/// One sample's bed_map_sums row (see above; bed_maps.cpp).
std::vector<double> map_sums(const BedGeometry& g, const std::vector<Vec3>& positions,
                             const std::vector<Vec3>& velocities, const std::vector<double>& radii,
                             const std::vector<double>& masses);

/// One sample's series: bed_height, and with a gas bed_pressure and bed_probe_pressure.
struct BedSample {
  std::vector<double> heights, pressure, probes, map;
};
BedSample sample_bed(const BedGeometry& g, const CollisionMethod& sim, const GasCoupling* gas);

// ---- conclusions ---------------------------------------------------------------------------

/// Mean, standard deviation (over the samples), minimum and maximum of one series' finite values.
struct SeriesSpread {
  double mean = 0, sd = 0, min = 0, max = 0;
};

struct BedConclusions {
  std::size_t samples = 0;     ///< Samples at or after start.
  double first = 0, last = 0;  ///< Their first and last times, s.
  double interval = 0;         ///< Their mean interval, s.
  std::vector<SeriesSpread> heights;  ///< One per bed_height column, m.
  bool pressure = false;              ///< With a gas.
  SeriesSpread pressure_drop;         ///< Over the domain, Pa.
  double gas_column = 0;              ///< rho_g |g| H, Pa.
  double momentum_inflow = 0;         ///< Mean, Pa.
  double bed_pressure_drop = 0;       ///< Mean drop - gas column + mean inflow, Pa.
  double buoyant_weight = 0;          ///< Mean W/A, Pa.
  std::vector<Spectrum> probes;       ///< One per probe column.
  std::vector<double> solid_fraction;      ///< Map, U x C.
  std::vector<double> velocity, flux;      ///< Maps, U x C x 2 (across, up): m/s, kg/(m^2 s).
};

/// Concludes from the record: times (s) and the series' rows (empty for a series not recorded).
BedConclusions conclude_bed(const BedGeometry& g, const std::vector<double>& times,
                            const std::vector<double>& heights, const std::vector<double>& pressure,
                            const std::vector<double>& probes, const std::vector<double>& map);

// ---- outputs (bed_outputs.cpp) -------------------------------------------------------------

namespace h5 {
class Group;
}  // namespace h5

/// run.h5 /analysis/bed: the geometry, each quantity's unit beside it.
void write_bed_setup(const h5::Group& analysis, const BedGeometry& g);
/// run.h5 /analysis/bed/results (replaced): the conclusions, each dataset with its unit.
void write_bed_results(const h5::Group& analysis, const BedGeometry& g, const BedConclusions& c);
/// The "bed" object of summary.json (JSON text).
std::string bed_json(const BedGeometry& g, const BedConclusions& c);
/// The bed section of report.md.
std::string bed_report(const BedGeometry& g, const BedConclusions& c);

}  // namespace carom
