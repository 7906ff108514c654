#pragma once
/// The gas pressure where a probe reads it (scene [analysis.bed] probes and probe_heights): from
/// the gas solver's cell-centred pressure field (x fastest, then y, z; GasCoupling::
/// pressure_field), at a point or averaged across the domain at a level. Linear between cell
/// centres, so a pressure field linear in space is read exactly between them; beyond the
/// outermost centres the outermost values hold (the solver has no value nearer the walls).
#include <array>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

/// Gas pressure at point r (m): trilinear between the centres of the gas cells (`cells` per
/// axis from `lower`, cells of `size`), each axis clamped to its outermost centres, Pa.
double pressure_at_point(const std::vector<double>& pressure, const std::array<int, 3>& cells,
                         const Vec3& lower, const Vec3& size, const Vec3& r);

/// Mean gas pressure across the domain at coordinate `level` (m) along `axis`: each layer of
/// cells averaged with the weights `open_volume` (a cell cut by a wall holds less gas), linear
/// between layer centres, clamped to the outermost layers, Pa; NaN for a layer with no gas.
double pressure_at_level(const std::vector<double>& pressure, const std::vector<double>& open_volume,
                         const std::array<int, 3>& cells, const Vec3& lower, const Vec3& size,
                         int axis, double level);

}  // namespace carom
