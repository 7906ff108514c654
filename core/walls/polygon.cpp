// The polygon wall: construction checks, the closest point, validation.
#include "core/walls/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace carom {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Mean of the vertices, m.
Vec3 mean(const std::vector<Vec3>& vertices) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : vertices) sum += p;
  return sum / static_cast<double>(vertices.size());
}

/// Newell's area vector: normal times twice the area, right-handed with the order, m^2.
Vec3 newell(const std::vector<Vec3>& vertices, const Vec3& centre) {
  Vec3 sum = Vec3::Zero();
  const std::size_t n = vertices.size();
  for (std::size_t k = 0; k < n; ++k)
    sum += (vertices[k] - centre).cross(vertices[(k + 1) % n] - centre);
  return sum;
}

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace

std::string PolygonWall::problem(const std::vector<Vec3>& vertices) {
  const std::size_t n = vertices.size();
  if (n < 3) return "has " + std::to_string(n) + " vertices; a polygon needs at least 3";
  for (std::size_t k = 0; k < n; ++k)
    if (!vertices[k].allFinite())
      return "has a vertex that is not finite (vertex " + std::to_string(k + 1) + ")";
  const Vec3 centre = mean(vertices);
  double size = 0.0;
  for (const Vec3& p : vertices) size = std::max(size, (p - centre).norm());
  if (!(size > 0.0)) return "has all its vertices at one point";
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j + 1; k < n; ++k)
      if ((vertices[j] - vertices[k]).norm() <= 1e-9 * size)
        return "repeats a vertex: vertices " + std::to_string(j + 1) + " and " +
               std::to_string(k + 1) + " coincide (closer than 1e-9 of the polygon's size, " +
               number(size) + " m)";
  const Vec3 area_vector = newell(vertices, centre);
  if (!(area_vector.norm() > 1e-12 * size * size))
    return "encloses no area (its vertices are collinear)";
  const Vec3 normal = area_vector.normalized();
  std::size_t farthest = 0;
  double off = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double here = std::abs((vertices[k] - centre).dot(normal));
    if (here > off) off = here, farthest = k;
  }
  if (off > kPlaneTolerance * size)
    return "is not flat: vertex " + std::to_string(farthest + 1) + " lies " + number(off) +
           " m off the polygon's best plane (allowed: 1e-6 of its size, " + number(size) + " m)";
  // Convex in this order: every corner turns the same way as the area vector, and the turns
  // add up to one full turn (a star winds twice).
  double turning = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 before = vertices[k] - vertices[(k + n - 1) % n];
    const Vec3 after = vertices[(k + 1) % n] - vertices[k];
    const double turn = before.cross(after).dot(normal);
    if (!(turn > 1e-12 * before.norm() * after.norm()))
      return "is not convex in this order: the corner at vertex " + std::to_string(k + 1) +
             " is reflex or straight (give the vertices of a convex polygon in order around "
             "it, without vertices in the middle of an edge)";
    turning += std::atan2(turn, before.dot(after));
  }
  if (turning > 3.0 * kPi)
    return "winds around more than once (a star): give the vertices in order around the "
           "polygon";
  return "";
}

PolygonWall::PolygonWall(std::vector<Vec3> vertices) {
  if (const std::string why = problem(vertices); !why.empty())
    throw std::invalid_argument("the polygon " + why);
  centre_ = mean(vertices);
  const Vec3 area_vector = newell(vertices, centre_);
  normal_ = area_vector.normalized();
  area_ = 0.5 * area_vector.norm();
  // Onto the plane through the centre, so that face, edges and vertices meet exactly (to
  // round-off) and the distance is continuous.
  for (Vec3& p : vertices) p -= (p - centre_).dot(normal_) * normal_;
  vertices_ = std::move(vertices);
  size_ = 0.0;
  for (const Vec3& p : vertices_) size_ = std::max(size_, (p - centre_).norm());
  const std::size_t n = vertices_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 along = vertices_[(k + 1) % n] - vertices_[k];
    const Vec3 direction = along.normalized();
    edges_.push_back(
        Edge{vertices_[k], direction, direction.cross(normal_).normalized(), along.norm()});
  }
}

PolygonWall::Closest PolygonWall::closest(const Vec3& r) const {
  bool inside = true;
  for (const Edge& e : edges_)
    if ((r - e.start).dot(e.outward) > 0.0) {
      inside = false;
      break;
    }
  if (inside) {
    const double h = (r - centre_).dot(normal_);
    return {r - h * normal_, std::abs(h), -1};
  }
  const int n = static_cast<int>(edges_.size());
  Closest best{Vec3::Zero(), kNever, 0};
  for (int k = 0; k < n; ++k) {
    const Edge& e = edges_[static_cast<std::size_t>(k)];
    const Vec3 d = r - e.start;
    const double u = d.dot(e.direction);
    Closest here;
    if (u <= 0.0) {
      here = {e.start, d.norm(), n + k};
    } else if (u >= e.length) {
      const int next = (k + 1) % n;
      const Vec3& end = vertices_[static_cast<std::size_t>(next)];
      here = {end, (r - end).norm(), n + next};
    } else {
      here = {e.start + u * e.direction, (d - u * e.direction).norm(), k};
    }
    if (here.distance < best.distance) best = here;
  }
  return best;
}

Vec3 PolygonWall::contact_normal(const Vec3& r) const {
  const Closest c = closest(r);
  if (c.feature < 0) return (r - centre_).dot(normal_) >= 0.0 ? normal_ : Vec3(-normal_);
  if (!(c.distance > 0.0)) return normal_;  // a centre on the rim: any normal will do
  return (r - c.point).normalized();
}

void PolygonWall::validate(const std::string& name, const Vec3& /*gravity*/,
                           const Domain& domain) const {
  for (int k = 0; k < 3; ++k) {
    if (!domain.periodic[k]) continue;
    const double lo = domain.lower[k], hi = domain.upper[k], period = hi - lo;
    const double tolerance = 1e-9 * std::max(period, size_);
    bool strip = std::abs(normal_[k]) <= 1e-9;
    std::vector<Vec3> low, high;
    for (const Vec3& p : vertices_) {
      if (std::abs(p[k] - lo) <= tolerance)
        low.push_back(p);
      else if (std::abs(p[k] - hi) <= tolerance)
        high.push_back(p);
      else
        strip = false;
    }
    strip = strip && !low.empty() && low.size() == high.size();
    for (const Vec3& p : low) {
      Vec3 moved = p;
      moved[k] += period;
      strip = strip && std::any_of(high.begin(), high.end(),
                                   [&](const Vec3& q) { return (q - moved).norm() <= tolerance; });
    }
    if (!strip) {
      const std::string axis(1, "xyz"[k]);
      throw std::invalid_argument(
          "wall '" + name + "': " + axis +
          " is periodic, and particles see a wall only in the domain's own copy, so a polygon "
          "must be a strip across the period: its plane parallel to " +
          axis + ", every vertex on the face " + axis + " = " + number(lo) + " or " + axis + " = " +
          number(hi) +
          " m, those on the upper face the lower face's moved by the "
          "period (make " +
          axis + " walled to place a polygon freely)");
    }
  }
}

std::string PolygonWall::description() const {
  std::ostringstream out;
  out << "polygon of " << vertices_.size() << " vertices, area " << area_ << " m^2, normal ("
      << normal_.x() << ", " << normal_.y() << ", " << normal_.z() << "), centre (" << centre_.x()
      << ", " << centre_.y() << ", " << centre_.z() << ")";
  return out.str();
}

}  // namespace carom
