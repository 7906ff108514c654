#include "wall_cell_cut.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

int plane_axis(const PlaneWall& wall) {
  int axis = -1;
  for (int k = 0; k < 3; ++k)
    if (std::abs(wall.normal[k]) >= 1.0 - 1e-12) axis = k;
  return axis;
}

void clip_cell(const PlaneWall& wall, CellCut& cell) {
  const int a = plane_axis(wall);
  if (a < 0) return;
  if (wall.normal[a] > 0.0)
    cell.lower[a] = std::max(cell.lower[a], wall.point[a]);
  else
    cell.upper[a] = std::min(cell.upper[a], wall.point[a]);
}

void cut_cell(const PlaneWall& wall, CellCut& cell) {
  if (plane_axis(wall) >= 0) return;
  const Vec3& lo = cell.lower;
  const Vec3& hi = cell.upper;
  const HalfSpace h{wall.normal, wall.normal.dot(wall.point)};
  double least = std::numeric_limits<double>::infinity(), most = -least;
  for (int c = 0; c < 8; ++c) {
    const Vec3 v(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
    const double d = h.normal.dot(v) - h.offset;
    least = std::min(least, d);
    most = std::max(most, d);
  }
  if (most <= 0.0)
    cell.outside = true;
  else if (least < 0.0)
    cell.cutting.push_back(h);
}

double inside_fraction(const CylinderWall& wall, const CellCut& cell) {
  const Vec3& lo = cell.lower;
  const Vec3& hi = cell.upper;
  const double rectangle = (hi.x() - lo.x()) * (hi.y() - lo.y());
  return disk_rectangle_area(wall.point.x(), wall.point.y(), wall.radius, lo.x(), hi.x(), lo.y(),
                             hi.y()) /
         rectangle;
}

}  // namespace carom
