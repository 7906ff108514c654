#pragma once
/// Enskog's collision frequencies of a homogeneous hard-sphere mixture: the reference that a
/// periodic, gravity-free run is checked against.
///
/// A particle of species s meets particles of species t at the rate
///   nu_st = n_t g_st d_st^2 sqrt(8 pi T / mu_st),   d_st = (d_s + d_t)/2,  mu_st = m_s m_t/(m_s + m_t),
/// (the Boltzmann rate n pi d^2 <|v_rel|> times the contact value g_st of the pair correlation),
/// with the Boublik-Mansoori-Carnahan-Starling-Leland contact value
///   g_st = 1/(1-phi) + 3 xi2 D/(1-phi)^2 + 2 xi2^2 D^2/(1-phi)^3,  D = d_s d_t/(d_s + d_t),
///   xi2 = (pi/6) sum_k n_k d_k^2,
/// which for one species is Carnahan-Starling, g0 = (1 - phi/2)/(1 - phi)^3, and gives the
/// textbook nu = 4 n d^2 g0 sqrt(pi T / m).
#include <vector>

namespace carom {

/// One species of the mixture.
struct MixtureComponent {
  double number_density = 0;  ///< n, 1/m^3.
  double diameter = 0;        ///< d, m.
  double mass = 0;            ///< m, kg.
};

/// Contact value g_st of the pair correlation function (BMCSL).
double contact_value(const std::vector<MixtureComponent>& mixture, std::size_t s, std::size_t t);

/// Collisions per unit time of one particle of species s with particles of species t at granular
/// temperature T (J, T = m <v_x^2>), 1/s.
double enskog_frequency(const std::vector<MixtureComponent>& mixture, std::size_t s, std::size_t t, double temperature);

}  // namespace carom
