// The cost of a polygon wall's ballistic contact prediction (core/walls/polygon_ballistic.cpp)
// on duct-like states: a square plate of side 0.1 m, vertical (normal x) or inclined at 30
// degrees to the vertical, gravity -z, sphere radius 1.5 mm, 2e5 centres uniform in a box
// 0.3 x 0.3 x 0.3 m about it with random directions at 0-3 m/s. Prints ns per call, the
// fraction that never touch and a checksum of the times (equal checksums: equal answers).
#include <chrono>
#include <cstdio>
#include <vector>

#include "core/rng.hpp"
#include "core/walls/polygon.hpp"

using namespace carom;

int main() {
  const PolygonWall vertical(
      {Vec3(0, -0.05, 0), Vec3(0, 0.05, 0), Vec3(0, 0.05, 0.1), Vec3(0, -0.05, 0.1)});
  const PolygonWall inclined(
      {Vec3(0, -0.05, 0), Vec3(0, 0.05, 0), Vec3(0.05, 0.05, 0.0866), Vec3(0.05, -0.05, 0.0866)});
  Rng rng(1);
  const int n = 200000;
  std::vector<Vec3> r(n), v(n);
  for (int i = 0; i < n; ++i) {
    r[i] = Vec3(rng.uniform(-0.15, 0.15), rng.uniform(-0.15, 0.15), rng.uniform(-0.1, 0.2));
    v[i] = rng.uniform(0, 3) * rng.normal3().normalized();
  }
  for (const PolygonWall* plate : {&vertical, &inclined}) {
    for (int repeat = 0; repeat < 3; ++repeat) {
      int never = 0;
      double sum = 0;
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < n; ++i) {
        const double s = plate->ballistic_contact_time(r[i], v[i], 0.0015, Vec3(0, 0, -9.81));
        if (s == kNever)
          ++never;
        else
          sum += s;
      }
      const double ns =
          1e9 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / n;
      std::printf("%s plate: %.0f ns per call, %.1f %% never touch (checksum %.9g)\n",
                  plate == &vertical ? "vertical" : "inclined", ns, 100.0 * never / n, sum);
    }
  }
}
