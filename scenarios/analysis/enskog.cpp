#include "scenarios/analysis/enskog.hpp"

#include <cmath>
#include <numbers>

#include "core/contact_value.hpp"

namespace carom {

double contact_value(const std::vector<MixtureComponent>& mixture, std::size_t s, std::size_t t) {
  double phi = 0.0, xi2 = 0.0;
  for (const MixtureComponent& c : mixture) {
    phi += std::numbers::pi / 6.0 * c.number_density * c.diameter * c.diameter * c.diameter;
    xi2 += std::numbers::pi / 6.0 * c.number_density * c.diameter * c.diameter;
  }
  return bmcsl_contact_value(phi, xi2, mixture[s].diameter, mixture[t].diameter);
}

double enskog_frequency(const std::vector<MixtureComponent>& mixture, std::size_t s, std::size_t t, double temperature) {
  const MixtureComponent& a = mixture[s];
  const MixtureComponent& b = mixture[t];
  const double d = 0.5 * (a.diameter + b.diameter);
  const double reduced_mass = a.mass * b.mass / (a.mass + b.mass);
  return b.number_density * contact_value(mixture, s, t) * d * d *
         std::sqrt(8.0 * std::numbers::pi * temperature / reduced_mass);
}

}  // namespace carom
