#pragma once
/// How each wall shape cuts a gas cell, for the cells' open volumes (porosity.hpp, open_volume).
///
/// open_volume makes three passes over the walls, each a visit over the shapes (every shape
/// provides all three, so a new shape cannot be forgotten):
///   1. clip_cell: axis-aligned planes clip the cell's box;
///   2. cut_cell: oblique planes that cut the clipped box are collected as half-spaces (the box
///      is then clipped by all of them at once), or mark the cell as wholly outside;
///   3. inside_fraction: the fraction of the clipped box inside a curved wall (a cylinder, a
///      cone) or outside a solid mesh, which multiplies the volume; 1 for planes, polygons and
///      open meshes.
/// The passes run in this order whatever the order of the walls.
#include <vector>

#include "core/vec3.hpp"
#include "core/wall.hpp"
#include "fluid/overlap.hpp"

namespace carom {

/// One gas cell while the walls cut it.
struct CellCut {
  Vec3 lower = Vec3::Zero();       ///< Lower corner of the box, clipped by pass 1, m.
  Vec3 upper = Vec3::Zero();       ///< Upper corner of the box, clipped by pass 1, m.
  std::vector<HalfSpace> cutting;  ///< Oblique planes that cut the box (pass 2).
  bool outside = false;            ///< The box lies wholly outside some wall (pass 2).
};

/// The axis (0, 1, 2) a plane's normal lies along (within 1e-12), or -1 for an oblique plane.
int plane_axis(const PlaneWall& wall);

/// Pass 1: an axis-aligned plane moves the box's face on its axis onto the plane.
void clip_cell(const PlaneWall& wall, CellCut& cell);
/// Pass 1: a cylinder does not clip the box.
inline void clip_cell(const CylinderWall& /*wall*/, CellCut& /*cell*/) {}
/// Pass 1: a cone does not clip the box.
inline void clip_cell(const ConeWall& /*wall*/, CellCut& /*cell*/) {}
/// Pass 1: a polygon (a plate of zero thickness) does not clip the box.
inline void clip_cell(const PolygonWall& /*wall*/, CellCut& /*cell*/) {}

/// Pass 1: a mesh does not clip the box.
inline void clip_cell(const MeshWall& /*wall*/, CellCut& /*cell*/) {}

/// Pass 2: an oblique plane wholly past the box marks it outside; one through it is collected.
void cut_cell(const PlaneWall& wall, CellCut& cell);
/// Pass 2: a cylinder is no half-space.
inline void cut_cell(const CylinderWall& /*wall*/, CellCut& /*cell*/) {}
/// Pass 2: a cone is no half-space.
inline void cut_cell(const ConeWall& /*wall*/, CellCut& /*cell*/) {}
/// Pass 2: a polygon is no half-space.
inline void cut_cell(const PolygonWall& /*wall*/, CellCut& /*cell*/) {}

/// Pass 2: a mesh is no half-space.
inline void cut_cell(const MeshWall& /*wall*/, CellCut& /*cell*/) {}

/// Pass 3: a plane has been applied by passes 1 and 2: fraction 1.
inline double inside_fraction(const PlaneWall& /*wall*/, const CellCut& /*cell*/) {
  return 1.0;
}
/// Pass 3: the fraction of the box's cross-section inside the cylinder (exact, disk-rectangle
/// area).
double inside_fraction(const CylinderWall& wall, const CellCut& cell);
/// Pass 3: the fraction of the box's volume inside the cone: the integral over z of the exact
/// disk-rectangle area at radius max(R(z), 0), by adaptive Gauss-Legendre quadrature on the
/// pieces between the heights where the disk's edge meets a corner or an edge line of the box
/// (there the area has a (R - R_c)^{3/2} kink, removed by a substitution); to about 1e-13 of
/// the box volume.
double inside_fraction(const ConeWall& wall, const CellCut& cell);
/// Pass 3: a polygon is a plate of zero thickness with particles on both sides: it takes no
/// volume from the cell, fraction 1 (the gas does not see it: it neither blocks nor guides the
/// flow).
inline double inside_fraction(const PolygonWall& /*wall*/, const CellCut& /*cell*/) {
  return 1.0;
}

/// Pass 3: an open mesh (plates) takes no volume, fraction 1; a solid mesh removes the clipped
/// box's part inside the solid (exact tetrahedron decomposition, fluid/mesh_solid_volume.hpp):
/// the fraction 1 - solid / clipped box.
double inside_fraction(const MeshWall& wall, const CellCut& cell);

}  // namespace carom
