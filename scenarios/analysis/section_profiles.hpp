#pragma once
/// Profiles across sections (scene [analysis.profiles], SCENES.md): the statistics a duct or
/// bed experiment reads from bins across the flow at chosen heights. A section is the slab of
/// thickness `thickness` centred on a height along the vertical axis; it is cut into `bins`
/// equal bins across the domain along the bin axis, each spanning the whole domain along the
/// third axis. A particle counts wholly in the bin holding its centre.
///
/// Every sample adds one row of sums to /timeseries/profile_sums (width K x B x 11 for K
/// sections and B bins, section-major): per bin, the particle count, their solid volume (m^3),
/// the sums of v_x, v_y, v_z (m/s), of v_x^2, v_y^2, v_z^2 (m^2/s^2) and of w_x, w_y, w_z
/// (rad/s). The averages over the samples at or after `start` are the conclusions:
///   solid_fraction   sum of solid volumes / (samples x bin volume)
///   mean_velocity    sum of v / sum of counts, m/s
///   std_velocity     sqrt(sum of v^2 / sum of counts - mean^2) per component, m/s (the spread
///                    of the velocities of the particle samples: a particle seen in several
///                    samples counts each time)
///   mean_spin        sum of w / sum of counts, rad/s
/// NaN where a bin saw no particle. The bin volume is the geometric box volume: bins cut by a
/// curved wall (a cylinder) read low by their closed fraction.
#include <cstddef>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

/// Where the sections lie and how they are binned.
struct ProfileGeometry {
  std::vector<double> heights;  ///< Section centres along the vertical axis, m.
  double thickness = 0;         ///< Section extent along the vertical axis, m.
  int vertical = 2;             ///< Axis of the heights (0 x, 1 y, 2 z).
  int axis = 0;                 ///< Bin axis across the section (differs from vertical).
  int bins = 1;                 ///< Bins across the domain along `axis`.
  double lower = 0, upper = 0;  ///< Extent of the domain along `axis`, m.
  double depth = 0;             ///< Extent of the domain along the third axis, m.
  double start = 0;             ///< Samples before this time are left out of the averages, s.

  /// Values per bin in a row of sums.
  static constexpr std::size_t kValuesPerBin = 11;
  /// Width of a row of sums.
  std::size_t row_width() const {
    return heights.size() * static_cast<std::size_t>(bins) * kValuesPerBin;
  }
  /// Volume of one bin, m^3.
  double bin_volume() const { return thickness * (upper - lower) / bins * depth; }
  /// Centre of bin b along `axis`, m.
  double bin_centre(int b) const { return lower + (b + 0.5) * (upper - lower) / bins; }
};

/// One sample's row of sums (see above) from the particles' positions (m), velocities (m/s),
/// spins (rad/s) and radii (m). Particles outside every section or outside [lower, upper) along
/// the bin axis are not counted.
std::vector<double> profile_sums(const ProfileGeometry& geometry,
                                 const std::vector<Vec3>& positions,
                                 const std::vector<Vec3>& velocities,
                                 const std::vector<Vec3>& spins, const std::vector<double>& radii);

/// The averaged profiles of one section.
struct SectionProfile {
  double height = 0;                   ///< Section centre, m.
  std::vector<double> solid_fraction;  ///< Per bin.
  std::vector<double> particles;       ///< Mean particle count per sample, per bin.
  std::vector<Vec3> mean_velocity;     ///< Per bin, m/s.
  std::vector<Vec3> std_velocity;      ///< Per bin, m/s.
  std::vector<Vec3> mean_spin;         ///< Per bin, rad/s.
};

/// The conclusions: the profiles averaged over the samples at or after geometry.start.
struct ProfileConclusions {
  std::size_t samples = 0;     ///< Rows averaged.
  double first = 0, last = 0;  ///< Times of the first and last rows averaged, s.
  std::vector<SectionProfile> sections;
};

/// Averages the rows of `sums` (one per entry of `times`, s) at or after geometry.start.
ProfileConclusions conclude_profiles(const ProfileGeometry& geometry,
                                     const std::vector<double>& times,
                                     const std::vector<double>& sums);

/// The "profiles" object of summary.json (JSON text).
std::string profiles_json(const ProfileGeometry& geometry, const ProfileConclusions& c);
/// The profiles section of report.md.
std::string profiles_report(const ProfileGeometry& geometry, const ProfileConclusions& c);

}  // namespace carom
