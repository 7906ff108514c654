#pragma once
/// The contact value of the pair correlation of a hard-sphere mixture: how much more often two
/// spheres meet in a dense gas than in a dilute one. Boublik, Mansoori, Carnahan, Starling and
/// Leland (BMCSL; tests/VALIDATION.md, "Mixtures"):
///   g(d1, d0) = 1/(1-phi) + 3 h xi2/(1-phi)^2 + 2 h^2 xi2^2/(1-phi)^3,  h = d1 d0/(d1 + d0),
///   xi2 = (pi/6) sum_k n_k d_k^2  (1/m),  phi = (pi/6) sum_k n_k d_k^3,
/// which for one size (h xi2 = phi/2) is Carnahan-Starling's (1 - phi/2)/(1 - phi)^3.
/// The one home of this formula: the Monte Carlo method's partners, the Enskog references of the
/// analysis and `carom check`'s mean free time all call it.

namespace carom {

/// g for spheres of diameters d1 and d0 (m) at solid fraction phi < 1 and size moment xi2 (1/m).
inline double bmcsl_contact_value(double phi, double xi2, double d1, double d0) {
  const double h = d1 * d0 / (d1 + d0);
  const double free = 1.0 - phi;
  return 1.0 / free + 3.0 * h * xi2 / (free * free) + 2.0 * h * h * xi2 * xi2 / (free * free * free);
}

/// g of one size at solid fraction phi < 1 (Carnahan-Starling).
inline double carnahan_starling_contact_value(double phi) { return bmcsl_contact_value(phi, phi, 1.0, 1.0); }

}  // namespace carom
