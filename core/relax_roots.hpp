#pragma once
/// Event times for `relax` flights (see relax_flight.hpp): contact of two spheres, of a sphere
/// and a plane or a cylinder, and crossings of cell faces, all within a finite horizon (the end
/// of the current fluid step). They never miss a contact inside the horizon.
///
/// How (details in relax_roots.cpp):
/// - 1-D gaps: gap' is monotone along a relax flight, so the gap has at most one extremum,
///   known in closed form; the first closing root is bracketed and polished to round-off
///   (safeguarded Newton).
/// - Spheres and the cylinder: conservative advancement. With a lower bound on the second
///   derivative of the gap over the rest of the horizon (-K, and the exact value now minus a
///   bound on its rate of change), the step to the first root of the resulting lower bound of
///   the gap can never jump over a contact; it converges like Newton towards a hit and needs
///   few steps past a graze. A dip below contact shallower than the touching tolerance (1e-13
///   of the contact distance plus round-off of the positions) may be stepped over: such a
///   "contact" is below the precision of the positions.
#include <cstdint>

#include "relax_flight.hpp"

namespace carom {

/// Earliest s in [0, horizon] at which a gap obeying gap'' = gap_drive - rate gap' (a component
/// of a relax flight: gap(s) = gap + gap_speed s + (gap_drive - rate gap_speed) s^2 phi2(rate s))
/// falls to zero. gap in m, gap_speed = gap' at s = 0 in m/s (negative: closing), gap_drive in
/// m/s^2, rate >= 0 in 1/s, horizon >= 0 finite, in s. A gap already <= 0 (round-off) and
/// closing returns 0; one <= 0 and opening returns the time it closes again, or, if it turns
/// back before it opened, the time it turns. kNever when it does not close within the horizon.
double relax_gap_closing_time(double gap, double gap_speed, double gap_drive, double rate,
                              double horizon);

/// Earliest s in [0, horizon] at which spheres a and b, separated by dr = r_a - r_b at s = 0
/// (m), with velocities va, vb (m/s) and flights fa, fb, come to the distance `contact` (m)
/// while approaching. A pair already within contact and approaching returns 0; one within
/// contact and separating does not (it returns a later contact if the pair comes back).
/// kNever when they do not touch within the horizon (finite, s).
double relax_pair_contact_time(const Vec3& dr, const Vec3& va, const RelaxFlight& fa,
                               const Vec3& vb, const RelaxFlight& fb, double contact,
                               double horizon);

/// Earliest s in [0, horizon] at which a sphere inside a vertical cylinder touches it: the
/// horizontal distance of its centre from the axis reaches `reach` = R - a (m). `offset` is
/// the centre's position relative to a point on the axis (z ignored), v its velocity.
/// A sphere already at or beyond `reach` and moving outward returns 0. kNever when it does not
/// touch within the horizon (finite, s).
double relax_cylinder_contact_time(const Vec3& offset, const Vec3& v, const RelaxFlight& f,
                                   double reach, double horizon);

/// A contact search with its cost (for tests and benchmarks).
struct RelaxContactSearch {
  double time = kNever;  ///< the contact time (s), as the *_contact_time functions return it
  int iterations = 0;    ///< conservative-advancement steps taken (each one state evaluation)
};

/// relax_pair_contact_time with its iteration count.
RelaxContactSearch relax_pair_contact_search(const Vec3& dr, const Vec3& va, const RelaxFlight& fa,
                                             const Vec3& vb, const RelaxFlight& fb, double contact,
                                             double horizon);

/// relax_cylinder_contact_time with its iteration count.
RelaxContactSearch relax_cylinder_contact_search(const Vec3& offset, const Vec3& v,
                                                 const RelaxFlight& f, double reach,
                                                 double horizon);

/// Whether relax_pair_contact_time(dr, va, fa, vb, fb, contact, horizon) is kNever for any
/// contact, found at the search's first step with no state advanced: the pair separates
/// (dr . u > 0, u = va - vb) faster than the relative acceleration can turn it back within the
/// horizon, so the search's first step (its lower bound on the gap, G + G' h - K h^2 / 2 with
/// G' = n . u > K horizon / 2) passes the horizon. K is bounded as the search bounds it
/// (relative_acceleration_bound's difference form) with lengths as sums of magnitudes, the
/// slope with a margin of 1e-12 |dr| |u| over the round-off of either computation of it. Half
/// of a dense bed's searches are such pairs: in contact (or nearly), moving apart; this answers
/// them without the search's end states (two exponentials) and square roots.
/// tests/test_relax_roots.cpp checks it against the search.
bool relax_pair_separating(const Vec3& dr, const Vec3& va, const RelaxFlight& fa, const Vec3& vb,
                           const RelaxFlight& fb, double horizon);

/// Iterations after which a conservative-advancement search gives up (never reached in the
/// tests; see relax_contact_cap_hits).
inline constexpr int kRelaxContactMaxIterations = 1000;

/// How many searches in this process stopped at kRelaxContactMaxIterations. Such a search
/// returns the time it had reached, before which no contact is possible (the objects are then
/// within touching distance or creeping towards it): an early event rather than a missed one.
std::uint64_t relax_contact_cap_hits();

}  // namespace carom
