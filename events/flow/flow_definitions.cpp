#include "events/flow/flow_definitions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace carom {

namespace {

/// A number for a message, to 6 digits (no round-off tail as -0.0050000000000000044).
std::string text(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string interval_text(double lo, double hi) {
  return "[" + text(lo) + ", " + text(hi) + "]";
}

/// A problem of a plane on `axis` at `plane` in the domain (shared by inlets and outlets).
std::optional<FlowProblem> check_plane(int axis, double plane, int direction,
                                       const Domain& domain) {
  if (axis < 0 || axis > 2) return FlowProblem{"axis", "must be x, y or z"};
  if (domain.periodic[axis])
    return FlowProblem{"axis",
                       "is a periodic axis of the domain; a flow plane needs an axis "
                       "bounded by walls (particles crossing a periodic face come back)"};
  const double lo = domain.lower[axis], hi = domain.upper[axis];
  if (!(plane > lo && plane < hi))
    return FlowProblem{"plane", "is not strictly inside the domain on " +
                                    std::string(axis_name(axis)) + ": allowed (" + text(lo) + ", " +
                                    text(hi) + ") m"};
  if (direction != 1 && direction != -1)
    return FlowProblem{"side", "must be \"above\" (+1) or \"below\" (-1)"};
  return std::nullopt;
}

}  // namespace

double inflow_depth(const Inflow& inflow, const Species& species, double interval) {
  if (inflow.depth > 0.0) return inflow.depth;
  const double d = species.diameter;
  return std::max(2.0 * d, std::abs(inflow.velocity[inflow.axis]) * interval + d);
}

Box inflow_slab(const Inflow& inflow, double depth) {
  Box slab{inflow.lower, inflow.upper};
  const double far = inflow.plane + inflow.direction * depth;
  slab.lower[inflow.axis] = std::min(inflow.plane, far);
  slab.upper[inflow.axis] = std::max(inflow.plane, far);
  return slab;
}

Box inflow_centres(const Inflow& inflow, double depth, double radius) {
  Box box = inflow_slab(inflow, depth);
  box.lower.array() += radius;
  box.upper.array() -= radius;
  return box;
}

std::optional<FlowProblem> check_inflow(const Inflow& inflow, const System& system,
                                        double interval) {
  const Domain& domain = system.domain;
  if (inflow.species >= system.species.size())
    return FlowProblem{"species", "is not a species of the system"};
  const Species& species = system.species[inflow.species];
  if (species.fixed)
    return FlowProblem{"species",
                       "is a fixed species (obstacles never move); only moving "
                       "species can flow in"};
  if (auto problem = check_plane(inflow.axis, inflow.plane, inflow.direction, domain))
    return problem;
  if (!(inflow.mass_flow > 0.0) || !std::isfinite(inflow.mass_flow))
    return FlowProblem{"mass_flow", "must be a positive mass flow rate, kg/s: allowed (0, inf)"};
  for (int k = 0; k < 3; ++k) {
    if (!(inflow.velocity_spread[k] >= 0.0))
      return FlowProblem{"velocity_spread",
                         "must be standard deviations >= 0 m/s: allowed [0, inf) per component"};
    if (k == inflow.axis) continue;
    const std::string axis = axis_name(k);
    if (!(inflow.upper[k] > inflow.lower[k]))
      return FlowProblem{"max", "must exceed min on the plane's axes (here " + axis + ": " +
                                    text(inflow.lower[k]) + " to " + text(inflow.upper[k]) +
                                    " m): the inlet rectangle is empty"};
    if (inflow.lower[k] < domain.lower[k] || inflow.upper[k] > domain.upper[k])
      return FlowProblem{"max", "the inlet rectangle " +
                                    interval_text(inflow.lower[k], inflow.upper[k]) + " m on " +
                                    axis + " is not inside the domain " +
                                    interval_text(domain.lower[k], domain.upper[k]) + " m"};
  }
  if (inflow.attempts < 1) return FlowProblem{"attempts", "must be at least 1"};
  if (!(inflow.depth >= 0.0) || !std::isfinite(inflow.depth))
    return FlowProblem{"depth", "must be >= 0 m (0: the default depth): allowed [0, inf)"};
  if (!(interval > 0.0)) return FlowProblem{"interval", "must be a positive time, s"};
  const double depth = inflow_depth(inflow, species, interval);
  const Box slab = inflow_slab(inflow, depth);
  const int a = inflow.axis;
  if (slab.lower[a] < domain.lower[a] || slab.upper[a] > domain.upper[a])
    return FlowProblem{"depth", "gives the slab " + interval_text(slab.lower[a], slab.upper[a]) +
                                    " m on " + axis_name(a) + " (depth " + text(depth) +
                                    " m), which reaches outside the domain " +
                                    interval_text(domain.lower[a], domain.upper[a]) +
                                    " m; set a smaller depth or move the plane"};
  const Box centres = inflow_centres(inflow, depth, species.radius());
  for (int k = 0; k < 3; ++k)
    if (centres.upper[k] < centres.lower[k])
      return FlowProblem{k == a ? "depth" : "max",
                         std::string("makes the slab too thin for one particle: ") +
                             (k == a ? "depth " + text(depth)
                                     : "the rectangle's side on " + std::string(axis_name(k)) +
                                           " " + text(slab.upper[k] - slab.lower[k])) +
                             " m is less than the diameter " + text(species.diameter) +
                             " m of species \"" + species.name + "\""};
  return std::nullopt;
}

std::optional<FlowProblem> check_outflow(const Outflow& outflow, const Domain& domain) {
  return check_plane(outflow.axis, outflow.plane, outflow.direction, domain);
}

std::optional<FlowProblem> check_inflow_against_outflow(const Inflow& inflow, double depth,
                                                        const Outflow& outflow) {
  const Box slab = inflow_slab(inflow, depth);
  // The slab's extreme coordinate on the outlet's axis on the leaving side.
  const double extreme =
      outflow.direction > 0 ? slab.upper[outflow.axis] : slab.lower[outflow.axis];
  if (outflow.direction * (extreme - outflow.plane) > 0.0)
    return FlowProblem{
        "plane", "puts the inlet slab " +
                     interval_text(slab.lower[outflow.axis], slab.upper[outflow.axis]) + " m on " +
                     axis_name(outflow.axis) + " partly beyond outflow \"" + outflow.name +
                     "\" (plane " + text(outflow.plane) + " m; centres " +
                     (outflow.direction > 0 ? "above" : "below") +
                     " it leave): entering particles would leave at once"};
  return std::nullopt;
}

}  // namespace carom
