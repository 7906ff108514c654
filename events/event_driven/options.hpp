#pragma once
/// The settings of the event-driven engine that a scene gives ([flight], [collisions] collapse,
/// [engine]).
#include <cstddef>

#include "core/flight_model.hpp"
#include "events/laws/collapse.hpp"

namespace carom {

struct EventDrivenOptions {
  /// How particles move between events: Ballistic or Relax. (Kick flights are ballistic here;
  /// the kicks are the gas coupling's synchronising action, fluid/kick_scheme.hpp.)
  FlightModel flight_model = FlightModel::Ballistic;
  CollapseOptions collapse;   ///< TC model, low-speed elasticity, stall detector.
  /// How species are split into grid levels: < 0 picks the split with the least expected
  /// prediction work (default); > 0 gives a size its own level when it is below this ratio of
  /// the level above; 0 puts everything in one grid.
  double grid_level_ratio = -1.0;
  /// Grid cells per largest diameter of a level (1..3): smaller cells mean fewer candidate
  /// partners per prediction but more cell crossings and cell visits. 0 (default): chosen per
  /// level by the grid's cost model (1 for a monodisperse system; the finer levels of a mixture
  /// may get one cell of 1.5-4 of their diameters: fast fines then cross fewer cells).
  int grid_subdivision = 0;
  /// Threads of one run (`[engine] threads`): with relax flights, the predictions of every
  /// particle after a fluid step are shared among them (the calendar is then filled in particle
  /// order), and from 2 on a collision's two predictions are made at once, one on a side thread
  /// (core/side_thread.hpp; scheduled in the same order), so results are the same bit for bit
  /// for any count. 0 (default): CAROM_THREADS when set, else the cores this process may run on
  /// (core/worker_pool.hpp).
  int threads = 0;
  /// Relax predictions skip the cells of their block that no particle there can reach in time
  /// (from a bound on the speeds in each cell); the full predictions of straight flights skip
  /// the cells of finer levels that can hold no contact before the earliest one found so far
  /// (from a bound on each level's speeds: large spheres among fines). The events are the same
  /// bit for bit either way: off only to check that (the tests' oracle) or to measure what it
  /// saves.
  bool skip_unreachable_cells = true;
  /// Relax pair predictions end pairs by two cheap, sound tests before the exact ones: the
  /// straight lines of the two stored states keep them apart (lines_apart in pair_batch.hpp: no
  /// exponential, no square root, no flight read), or they separate faster than any
  /// acceleration can turn them back (relax_pair_separating in core/relax_roots.hpp). The events
  /// are the same bit for bit either way: off only to check that (the tests' oracle) or to
  /// measure what it saves.
  bool relax_pair_shortcuts = true;
  /// Particles from which the engine asks the CPU to start loading what an event reads late
  /// (the partner's records, the cells' first particles, the candidates' records, calendar
  /// blocks): hints, so the events are the same bit for bit for any value (the tests' oracle
  /// sets 0). Below it the records stay in the caches and the hints only add instructions. On
  /// the machine carom is measured on (a core that can count on 4-8 MiB of L3) the hints of the
  /// monodisperse fluid at phi = 0.40 break even at about 13 500 particles, pay 1.04-1.42 times
  /// at 32 000 (the less of its L3 the host leaves the core, the more) and 1.5 times at 1e5, and
  /// cost 8 % at 1e4 (tests/bench/README.md, "Loading hints from 16 000 particles").
  std::size_t prefetch_from = 16000;
  /// Check the invariants at every collision (no overlap, momentum balance). On by default in
  /// debug builds; costs a few percent.
#ifdef NDEBUG
  bool check_invariants = false;
#else
  bool check_invariants = true;
#endif
};

}  // namespace carom
