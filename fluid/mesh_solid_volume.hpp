#pragma once
/// The volume of a gas cell inside a solid mesh (walls/mesh.hpp), for the cells' open volumes.
///
/// Exact decomposition: for a closed, consistently oriented surface and any point O, the
/// indicator of the enclosed solid equals, almost everywhere, the signed sum over the triangles
/// t of the indicators of the tetrahedra (O, t), each signed by its orientation seen from O
/// (a ray from O crosses the surface out - in - out ..., and the tetrahedra it passes through
/// count +1, -1, +1 ...). So
///   vol(region inside solid) = sum_t sign_t vol(region inside tet(O, t)),
/// and each term is a convex polytope (the cell's box with its cutting half-spaces and the
/// tetrahedron's four) that box_halfspaces_volume computes exactly (fluid/overlap.hpp). O is the
/// mesh's mean vertex; tetrahedra whose bounding box misses the cell's box are skipped.
#include "core/walls/mesh.hpp"
#include "fluid/overlap.hpp"

namespace carom {

/// Volume of the box [lower, upper] inside all `cutting` half-spaces and inside the solid
/// enclosed by the mesh (0 for an open mesh), m^3; to round-off of the box volume times the
/// number of tetrahedra that meet it.
double mesh_solid_volume(const MeshWall& mesh, const Vec3& lower, const Vec3& upper,
                         const std::vector<HalfSpace>& cutting);

}  // namespace carom
