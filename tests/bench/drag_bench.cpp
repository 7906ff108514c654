// The cost of one drag coefficient K per particle for the closures the coupling calls most (it
// calls K twice per particle per fluid step): 0.5 mm glass in air at porosity 0.5, nanoseconds per
// call, printed per closure. A measurement, not a test: compare builds on one host.
#include <chrono>
#include <cstdio>
#include <string>

#include "fluid/drag.hpp"

int main() {
  using namespace carom;
  for (DragClosureKind kind : {DragClosureKind::SchillerNaumann, DragClosureKind::GidaspowBlend,
                               DragClosureKind::Beetstra, DragClosureKind::DiFelice}) {
    const DragClosure closure(kind);
    DragInput in;
    in.porosity = 0.5;
    in.diameter = 0.5e-3;
    in.gas_density = 1.2;
    in.gas_viscosity = 1.8e-5;
    in.particle_density = 2500.0;
    const int calls = 2000000;
    double sum = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < calls; ++i) {
      in.slip = 0.2 + 1e-8 * i;
      sum += closure.drag_coefficient(in);
    }
    const double ns =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / calls;
    std::printf("%s: %.1f ns per K (sum %.6g)\n", std::string(drag_closure_name(kind)).c_str(), ns, sum);
  }
}
