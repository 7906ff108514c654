#pragma once
/// A scene file read, checked and turned into a System plus the settings of its run.
///
/// Reading happens in two steps so that `carom resume` can rebuild the box, walls, species and
/// laws from the scene stored in a checkpoint without placing particles again:
///   parse_scene(...)        everything but the particles (cheap, pure validation);
///   build_initial_state()   places the particles and gives them velocities (may take a while).
/// Both throw SceneError with a message naming the file, line, key, value and allowed range.
/// SCENES.md documents every key.
#include <array>
#include <csignal>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/system.hpp"
#include "events/flow/flow_definitions.hpp"
#include "events/method_factory.hpp"
#include "fluid/gas_settings.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// A named box inside the domain where particles are placed.
struct Region {
  std::string name;
  Vec3 lower = Vec3::Zero();  ///< m.
  Vec3 upper = Vec3::Zero();  ///< m.
  double volume() const { return (upper - lower).prod(); }
};

/// How one species is put into the domain at the start.
struct Fill {
  enum class Amount { Count, VolumeFraction, MassFraction };
  enum class Arrangement { Random, Fcc, Cubic };
  Amount amount = Amount::Count;
  double value = 0;               ///< The count, the volume fraction of the region, or the mass fraction of all solids.
  std::size_t region = 0;         ///< Index into Scene::regions.
  Arrangement arrangement = Arrangement::Random;
  std::string where;              ///< "file:line" of the fill, for messages.
  std::string amount_key;         ///< Dotted key of the amount ("species[0].fill.count"), for messages.
  std::string amount_where;       ///< "file:line" of the amount's value.
  std::string amount_text;        ///< The amount as written ("100000000").
};

/// A particle written out in the scene.
struct ListedParticle {
  std::uint32_t species = 0;
  Vec3 position = Vec3::Zero();  ///< m.
  Vec3 velocity = Vec3::Zero();  ///< m/s.
  Vec3 spin = Vec3::Zero();      ///< rad/s.
  bool tagged = false;           ///< A tagged body: its velocity and collision force are recorded.
  std::string where;             ///< "file:line".
};

/// `[initial] from_file`: particles taken from a carom run file's snapshot or a checkpoint.
struct InitialFile {
  std::string path;            ///< As resolved (relative paths: relative to the scene file's folder).
  std::string written;         ///< As written in the scene, for messages.
  std::int64_t snapshot = -1;  ///< Run files: snapshot index, 0 first, -1 last, -2 the one before ...
  bool snapshot_given = false; ///< A checkpoint has no snapshots: giving one is an error.
  std::string where;           ///< "file:line" of from_file, for messages.
};

/// When outputs are written (s of simulated time); 0 means never (except at the end).
struct OutputSchedule {
  double snapshot_every = 0;    ///< s between particle snapshots.
  double sample_every = 0;      ///< s between time-series rows.
  double checkpoint_every = 0;  ///< s between checkpoints.
  /// Largest estimated output a run may write, bytes (output.max_bytes; run/output_estimate.hpp).
  double max_bytes = 1e10;
  bool max_bytes_given = false;  ///< output.max_bytes set in the scene: also lifts the free-space check.
  std::string max_bytes_where;   ///< "file:line" of output.max_bytes (of [output] or the scene when absent).
  /// Estimated output above which `carom run` warns before it starts, bytes (output.warn_bytes).
  double warn_bytes = 1e9;
};

/// [flight]: how particles move between events (DESIGN.md section 2).
struct FlightSettings {
  FlightModel model = FlightModel::Ballistic;  ///< ballistic, relax or kick.
  double particle_step = 0;  ///< Kick: time between drag kicks dt_p, s.
};

/// [[inflow]], [[outflow]] and [flow]: particles entering through inlet rectangles and leaving
/// through outlet planes (events/flow/; SCENES.md, "Inflow and outflow").
struct FlowSettings {
  std::vector<Inflow> inflows;    ///< [[inflow]], in scene order (depth 0: the default depth).
  std::vector<Outflow> outflows;  ///< [[outflow]], in scene order.
  /// Time between flow steps, s: flow.interval; default the gas time step with a gas (then a
  /// whole multiple of it), else 1e-3 s.
  double interval = 1e-3;
  /// True when the scene has an inflow or an outflow.
  bool any() const { return !inflows.empty() || !outflows.empty(); }
};

/// [analysis]: what a run measures beyond the standard time series (SCENES.md, "Analysis").
/// [analysis.profiles]: statistics in bins across sections at chosen heights
/// (scenarios/analysis/section_profiles.hpp).
struct ProfileSettings {
  std::vector<double> heights;  ///< Section centres along the vertical axis, m; empty: no profiles.
  double thickness = 0;         ///< Section extent along the vertical axis, m.
  int axis = 0;                 ///< Bin axis across the sections (0 x, 1 y, 2 z).
  int bins = 10;                ///< Bins across the domain along `axis`.
  double start = 0;             ///< Samples before this time are left out of the averages, s.
};

/// [analysis.plugs]: plugs in a narrow tube (scenarios/analysis/plugs.hpp).
struct PlugSettings {
  bool enabled = false;
  std::vector<double> thresholds{0.3, 0.2,
                                 0.4};  ///< The scene's threshold first, then the sensitivity ones.
  double bin = 0;             ///< Bin length along the vertical axis, m (0: the largest diameter).
  int min_bins = 2;           ///< Shortest plug, bins.
  double rate_window = 0.05;  ///< Shortest window of the bed-top speeds, s.
};

/// [analysis.bed]: bed heights, pressure drop against weight, gas pressure at probes, mid-plane
/// maps (scenarios/analysis/bed_measures.hpp); the scene reader resolves every default.
struct BedSettings {
  bool enabled = false;
  std::vector<double> height_shares{0.95, 0.99};  ///< Shares q of the share heights, in (0, 1].
  double threshold = 0.1;         ///< Solid fraction that marks the bed surface.
  double bin = 0;                 ///< Bin thickness of the solid-fraction profile, m.
  double start = 0;               ///< Samples before this time are left out of the conclusions, s.
  std::vector<Vec3> probes;       ///< Gas pressure probe points, m.
  std::vector<double> probe_heights;  ///< Heights above the floor of cross-section means, m.
  int map_axis = 0;               ///< Axis across the maps (0 x, 1 y, 2 z; not the vertical).
  std::array<int, 2> map_bins{1, 1};  ///< Map bins across and up.
  double map_centre = 0;          ///< Slab centre along the third axis, m.
  double map_thickness = 0;       ///< Slab thickness along the third axis, m.
};

struct AnalysisSettings {
  /// Mixing: the particles of this species are tagged by their height at t = 0 (lower and upper
  /// half); -1: no mixing analysis.
  std::int32_t mixing_species = -1;
  std::array<int, 3> mixing_cells{4, 1, 4};  ///< Lacey sample cells per axis over mixing_region.
  std::size_t mixing_region = 0;             ///< Index into Scene::regions (0: the whole domain).
  std::size_t min_particles = 5;             ///< Sample cells with fewer tagged-species particles are skipped.
  /// Cells per axis of the local fields (solid fraction, granular temperature, kinetic-theory
  /// collision frequency) over the whole domain; {0, 0, 0}: cells of about 4 largest diameters.
  std::array<int, 3> field_cells{0, 0, 0};
  /// Particle ids of the tagged bodies ([[particles]] entries with tagged = true).
  std::vector<std::uint64_t> tagged_bodies;
  ProfileSettings profiles;  ///< Profiles across sections (none when heights is empty).
  PlugSettings plugs;        ///< Plugs in a narrow tube.
  BedSettings bed;           ///< Fluidized-bed measures.
};

struct Scene {
  std::string file;           ///< Name used in messages.
  std::string text;           ///< Scene text as run (re-serialized when --set changed it).
  std::string name;           ///< [meta] name.
  std::string description;    ///< [meta] description.
  System system;              ///< Box, walls, species, laws, gravity; particles after build_initial_state.
  MethodSettings method;      ///< [method]; collapse remedies, grid levels (event_driven).
  std::vector<Region> regions;              ///< [regions.*]; regions[0] is the whole domain ("domain").
  std::vector<std::optional<Fill>> fills;   ///< Per species.
  std::vector<ListedParticle> listed;       ///< [[particles]].
  double temperature = 0;     ///< Granular temperature of filled particles, J (T = m <v_x^2>).
  double rms_velocity = 0;    ///< Alternative: rms velocity of filled particles, m/s.
  std::uint64_t seed = 1;     ///< Placement and velocity seed.
  std::optional<InitialFile> from_file;  ///< Particles read from an HDF5 file, placed after the listed ones.
  double settle_time = 0;     ///< Settling run before t = 0 (gravity, walls, laws, collapse settings), s; 0: none.
  bool settle_zero_velocity = false;  ///< Zero velocities and spins after settling.
  /// Settle with exact events whatever the scene's method (initial.settle_method =
  /// "event_driven"), so that every method of a comparison starts from the same bed.
  bool settle_by_events = false;
  std::string settle_where;   ///< "file:line" of initial.settle_time, for messages.
  FlightSettings flight;      ///< [flight].
  GasSettings gas;            ///< [gas]; coupling None when absent.
  FlowSettings flow;          ///< [[inflow]], [[outflow]], [flow]; none when absent.
  double end_time = 0;        ///< s.
  OutputSchedule output;
  AnalysisSettings analysis;  ///< [analysis].
};

/// The index of the species named by the string at `key` (a SceneError naming the choices if
/// none has that name); for the section readers.
std::uint32_t species_index(TableReader& t, std::string_view key, const Scene& scene);
/// The index into scene.regions of the region named at `key` ("domain" when absent).
std::size_t region_index(TableReader& t, std::string_view key, const Scene& scene);

/// Parses and validates a scene text. `overrides` are "key=value" assignments applied to the
/// table first; `seed`, when given, replaces initial.seed. `override_origins[k]`, when given and
/// not empty, says where override k was written ("sweep.toml:12"): messages about its value name
/// that place instead of "(set on the command line)". Throws SceneError (also for a sweep file).
Scene parse_scene(const std::string& text, const std::string& file,
                  const std::vector<std::string>& overrides = {},
                  std::optional<std::uint64_t> seed = std::nullopt,
                  const std::vector<std::string>& override_origins = {});
/// Reads the file and parses it (a missing or unreadable file, or a directory, is a SceneError too).
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                 std::optional<std::uint64_t> seed = std::nullopt,
                 const std::vector<std::string>& override_origins = {});

/// Places every particle (listed ones first, then those of initial.from_file, then the fills in
/// species order), gives the filled ones their velocities, validates the result (no overlaps,
/// nothing outside the walls) and, with initial.settle_time, runs the settling and takes its end
/// state as the initial state at t = 0. Throws SceneError; InterruptedBeforeStart (settling.hpp)
/// when `stop` (a signal handler's flag, may be null) is raised while it places the fills or
/// settles (placement checks it every thousand or so tries, so a long fill stops promptly).
void build_initial_state(Scene& scene, const volatile std::sig_atomic_t* stop = nullptr);

/// Number of particles each fill will create (mass fractions resolved), per species.
std::vector<std::size_t> fill_counts(const Scene& scene);

}  // namespace carom
