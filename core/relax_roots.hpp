#pragma once
/// Event times for `relax` flights (see relax_flight.hpp): contact of two spheres, of a sphere
/// and a plane or a cylinder, and crossings of cell faces, all within a finite horizon (the end
/// of the current fluid step). They never miss a contact inside the horizon.
#include "relax_flight.hpp"

namespace carom {

/// Earliest s in [0, horizon] at which a gap obeying gap'' = gap_drive - rate gap' (a component
/// of a relax flight: gap(s) = gap + gap_speed s + (gap_drive - rate gap_speed) s^2 phi2(rate s))
/// falls to zero. A gap already <= 0 and closing returns 0. kNever when it does not close
/// within the horizon.
double relax_gap_closing_time(double gap, double gap_speed, double gap_drive, double rate,
                              double horizon);

/// Earliest s in [0, horizon] at which spheres a and b, separated by dr = r_a - r_b at s = 0
/// (m), with velocities va, vb (m/s) and flights fa, fb, come to the distance `contact` (m)
/// while approaching. A pair already within contact and approaching returns 0. kNever when
/// they do not touch within the horizon.
double relax_pair_contact_time(const Vec3& dr, const Vec3& va, const RelaxFlight& fa,
                               const Vec3& vb, const RelaxFlight& fb, double contact,
                               double horizon);

/// Earliest s in [0, horizon] at which a sphere inside a vertical cylinder touches it: the
/// horizontal distance of its centre from the axis reaches `reach` = R - a (m). `offset` is
/// the centre's position relative to a point on the axis (z ignored), v its velocity.
double relax_cylinder_contact_time(const Vec3& offset, const Vec3& v, const RelaxFlight& f,
                                   double reach, double horizon);

}  // namespace carom
