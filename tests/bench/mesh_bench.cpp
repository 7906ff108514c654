// The cost of a mesh wall's ballistic contact prediction (core/walls/mesh_contact.cpp) against
// the same triangles as separate polygon walls (what the event-driven engine would do with one
// wall per triangle: every wall predicted after every event of the particle). Meshes: the
// polygon bench's inclined square plate as 2 triangles; a 0.3 x 0.3 m height field of 16 x 16
// squares (512 triangles, heights 0-2 cm) under the particles; a closed sphere of radius 5 cm
// of 480 triangles. States as polygon_bench: 2e5 centres uniform in a 0.3 m box about the mesh,
// random directions at 0-3 m/s, gravity -z, a = 1.5 mm. Prints ns per call for the mesh and
// the sum over the separate triangles, and checksums (equal: equal answers).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/rng.hpp"
#include "core/walls/mesh.hpp"

using namespace carom;

namespace {

std::vector<Triangle> inclined_square() {
  const Vec3 a(0, -0.05, 0), b(0, 0.05, 0), c(0.05, 0.05, 0.0866), d(0.05, -0.05, 0.0866);
  return {{a, b, c}, {a, c, d}};
}

std::vector<Triangle> height_field(Rng& rng) {
  constexpr int n = 16;
  Vec3 p[n + 1][n + 1];
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      p[i][j] = Vec3(0.3 * i / n - 0.15, 0.3 * j / n - 0.15, 0.02 * rng.uniform());
  std::vector<Triangle> mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      mesh.push_back({p[i][j], p[i + 1][j], p[i + 1][j + 1]});
      mesh.push_back({p[i][j], p[i + 1][j + 1], p[i][j + 1]});
    }
  return mesh;
}

/// A UV sphere of radius 0.05 m about (0, 0, 0.05): 24 longitudes x 11 latitude bands
/// (the two polar bands fans): 24 * 2 + 24 * 9 * 2 = 480 triangles.
std::vector<Triangle> sphere() {
  constexpr int lon = 24, lat = 11;
  const double pi = 3.14159265358979323846;
  auto at = [&](int i, int j) {
    if (j == 0 || j == lat) return Vec3(0, 0, j == 0 ? 0.1 : 0.0);  // the poles, exactly
    const double theta = pi * j / lat, phi = 2 * pi * (i % lon) / lon;
    return Vec3(0.05 * std::sin(theta) * std::cos(phi), 0.05 * std::sin(theta) * std::sin(phi),
                0.05 + 0.05 * std::cos(theta));
  };
  std::vector<Triangle> mesh;
  for (int i = 0; i < lon; ++i)
    for (int j = 0; j < lat; ++j) {
      const Vec3 a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
      if (j > 0) mesh.push_back({a, b, d});
      if (j < lat - 1) mesh.push_back({b, c, d});
    }
  return mesh;
}

}  // namespace

int main() {
  Rng rng(1);
  const int n = 200000;
  std::vector<Vec3> r(n), v(n);
  for (int i = 0; i < n; ++i) {
    r[i] = Vec3(rng.uniform(-0.15, 0.15), rng.uniform(-0.15, 0.15), rng.uniform(-0.1, 0.2));
    v[i] = rng.uniform(0, 3) * rng.normal3().normalized();
  }
  const Vec3 g(0, 0, -9.81);
  const double a = 0.0015;
  struct Case {
    const char* name;
    MeshWall mesh;
  };
  const Case cases[] = {{"inclined square, 2 triangles", MeshWall(inclined_square(), false)},
                        {"height field, 512 triangles", MeshWall(height_field(rng), false)},
                        {"closed sphere, 480 triangles", MeshWall(sphere(), true)}};
  for (const Case& c : cases) {
    for (int repeat = 0; repeat < 2; ++repeat) {
      double sum = 0;
      int never = 0;
      auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < n; ++i) {
        const double s = c.mesh.ballistic_contact_time(r[i], v[i], a, g);
        s == kNever ? ++never : (sum += s, 0);
      }
      const double mesh_ns =
          1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / n;
      // The same triangles as separate walls; fewer states for the big meshes (same ns/call).
      const int m = c.mesh.triangles().size() > 10 ? n / 20 : n;
      double sum_separate = 0, sum_mesh_m = 0;
      start = std::chrono::steady_clock::now();
      for (int i = 0; i < m; ++i) {
        double best = kNever;
        for (const PolygonWall& t : c.mesh.triangles())
          best = std::min(best, t.ballistic_contact_time(r[i], v[i], a, g));
        if (best != kNever) sum_separate += best;
      }
      const double separate_ns =
          1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / m;
      for (int i = 0; i < m; ++i) {
        const double s = c.mesh.ballistic_contact_time(r[i], v[i], a, g);
        if (s != kNever) sum_mesh_m += s;
      }
      std::printf(
          "%s: mesh %.0f ns per call (%.1f %% never touch), as separate walls %.0f ns "
          "(checksums over %d states: %.12g mesh, %.12g separate)\n",
          c.name, mesh_ns, 100.0 * never / n, separate_ns, m, sum_mesh_m, sum_separate);
    }
  }
}
