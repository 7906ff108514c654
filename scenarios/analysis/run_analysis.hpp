#pragma once
/// What a run measures at every sample beyond the standard time series (scene [analysis],
/// SCENES.md "Analysis"), and what it concludes at the end (summary.json "analysis", report.md).
///
/// At every sample, with S species:
///   lacey_index            Lacey index of the mixing species' height tags (mixing only)
///   axial_msd              mean squared vertical displacement of the mixing species since
///                          t = 0 about its mean displacement (the bed's rise and fall as a
///                          whole removed), m^2 (mixing only)
///   segregation_index      2 (h_small - h_large) / (h_small + h_large), the mean heights above
///                          the floor of the smallest and the largest species (2+ species)
///   granular_temperature   per species: <|v - u_local|^2> / 3, m^2/s^2 (local fields)
///   kinetic_collision_rate S x S: kinetic theory from the local fields, 1/s per particle
///   kinetic_impact_rate    S x S: the same for the impacts only, the collisions faster than
///                          the impact speed (local_fields.hpp, impact_share)
///   gas_velocity_seen      S x 3: mean interstitial gas velocity at the species' particles, m/s
///   gas_force_mean         S x 3: mean gas force (drag + pressure gradient) on one particle, N
///   porosity_seen          S: mean porosity at the species' particles
/// (the last three with a gas), with tagged bodies their series (tagged_bodies.hpp), and with
/// [analysis.profiles] the sums of the profiles across sections (section_profiles.hpp), and with
/// [analysis.plugs] the axial solid fraction and every particle's height (plugs.hpp), and with
/// [analysis.bed] the bed heights, pressures and map sums (bed_measures.hpp). The tags
/// and start heights are stored in run.h5 /analysis so a resumed run carries on with them; the
/// whole history is read back, so the conclusions always cover the run from t = 0.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "events/flow/flow_boundaries.hpp"
#include "events/method.hpp"
#include "fluid/coupling.hpp"
#include "scenarios/analysis/bed_measures.hpp"
#include "scenarios/analysis/dispersion.hpp"
#include "scenarios/analysis/mixing.hpp"
#include "scenarios/analysis/plugs.hpp"
#include "scenarios/analysis/section_profiles.hpp"
#include "scenarios/analysis/tagged_bodies.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

/// One column of a time series row: its name, its width (0: a 1-D series) and its values.
struct SeriesColumn {
  std::string name;
  std::size_t columns = 0;
  std::vector<double> values;
};
using SeriesRow = std::vector<SeriesColumn>;

class RunAnalysis {
 public:
  /// A fresh run at t = 0: tags the mixing species (the lower half by height, the median of its
  /// particles' heights splitting them) and records every particle's start height.
  RunAnalysis(const Scene& scene, const CollisionMethod& sim);
  /// A resumed run: the tags, start heights and history (up to `resume_time`, exclusive of rows
  /// at or after it, as the run file drops them) read from the run file.
  RunAnalysis(const Scene& scene, const CollisionMethod& sim, const std::string& run_file,
              double resume_time);

  /// The /analysis group of a fresh run file: tagged (by particle id, 0/1), start_height (m),
  /// sample grids, the geometry of the profiles, plugs and bed measures. Written once at t = 0.
  void write_setup(const std::string& run_file) const;
  /// Measures a sample at sim.time(), remembers it and returns it for the run file.
  SeriesRow sample(const CollisionMethod& sim, const GasCoupling* gas);
  /// The conclusions that go into the run file: with [analysis.bed], /analysis/bed/results
  /// (replaced at every call: each stretch of a run ends with its own).
  void write_results(const std::string& run_file, const CollisionMethod& sim) const;
  /// The "analysis" object of summary.json (JSON text, no trailing newline).
  std::string summary_json(const CollisionMethod& sim) const;
  /// report.md: the numbers, with what they say about the mechanism.
  std::string report(const CollisionMethod& sim) const;

  /// The run's inflows and outflows (null: none): collision frequencies are then per particle
  /// present (collisions over the time integral of the number of particles).
  void set_flow(const FlowBoundaries* flow) { flow_ = flow; }

  /// Sample grid of the Lacey index, and of the local fields.
  const SampleGrid& mixing_grid() const { return mixing_grid_; }
  const SampleGrid& field_grid() const { return field_grid_; }

 private:
  /// Conclusions from the history, shared by summary_json and report.
  struct Conclusions {
    bool mixing = false;
    MixingRate rate{};
    double lacey_start = NAN, lacey_end = NAN;
    Dispersion dispersion{};        ///< Confined-bed fit over the whole record.
    Dispersion early_dispersion{};  ///< Line fit of the early growth (biased low in a bounded bed).
    double saturation_msd = NAN;
    double duration = 0;                ///< s: t = 0 to now.
    std::vector<std::size_t> count;     ///< Particles per species.
    std::vector<double> measured_rate;  ///< S x S, 1/s per particle of the row species.
    std::vector<double> kinetic_rate;   ///< S x S time average, 1/s.
    std::vector<double> wall_rate;      ///< S: wall collisions per particle per s.
    std::vector<double> impact_rate;          ///< S x S: impacts per particle of the row species, 1/s.
    std::vector<double> kinetic_impact_rate;  ///< S x S time average of kinetic theory's impacts, 1/s.
    std::vector<double> wall_impact_rate;     ///< S: wall impacts per particle per s.
    std::vector<double> temperature;    ///< S: time average, m^2/s^2.
    std::vector<double> impulse_rate;   ///< S x S: |J| per s on one particle of the row species, N.
    std::vector<double> weight;         ///< S: m_s |g|, N.
    double segregation_start = NAN, segregation_end = NAN, segregation_mean = NAN;
    bool gas = false;
    std::vector<Vec3> gas_velocity, gas_force;  ///< S: time averages, m/s and N.
    std::vector<double> porosity;               ///< S: time average.
    TaggedConclusions tagged;                   ///< Tagged bodies (bodies = 0: none).
    bool has_profiles = false;                  ///< Profiles across sections measured.
    ProfileConclusions profiles;
    std::vector<PlugConclusions> plugs;  ///< One per threshold (empty: no plug analysis).
    bool has_bed = false;                ///< Bed measures taken.
    BedConclusions bed;
  };
  /// report.md's impact table: measured impacts against kinetic theory's at the same speed.
  std::string impacts_report(const System& system, const Conclusions& c) const;
  Conclusions conclude(const CollisionMethod& sim) const;
  const FlowBoundaries* flow_ = nullptr;

  const Scene& scene_;
  int vertical_ = 2;    ///< Axis opposite gravity (z without gravity).
  double floor_ = 0.0;  ///< Lower end of the domain along vertical_, m.
  SampleGrid mixing_grid_, field_grid_;
  std::vector<std::uint64_t> ids_;        ///< Particle ids, ascending: the by-id arrays' rows.
  std::vector<char> tagged_;              ///< By particle id: tagged (lower half) or not.
  std::vector<double> start_height_;      ///< By particle id: height at t = 0, m.
  std::int32_t small_ = -1, large_ = -1;  ///< Smallest and largest species (segregation).
  std::vector<std::uint64_t> tagged_ids_;  ///< Tagged bodies' particle ids (slot order).
  std::size_t tagged_partners_ = 0;        ///< Their partner categories: S species + W walls.
  ProfileGeometry profiles_;               ///< Profiles across sections (no heights: none).
  PlugGeometry plugs_;                     ///< Plugs along the vertical axis (bins = 0: none).
  bool bed_enabled_ = false;               ///< [analysis.bed] given.
  BedGeometry bed_;                        ///< Its geometry.
  /// Every series this run may write and its width.
  std::vector<std::pair<std::string, std::size_t>> widths() const;
  /// Every series sampled so far (since t = 0), by name, row after row.
  std::map<std::string, std::vector<double>> history_;
  std::vector<double> times_;
};

}  // namespace carom
