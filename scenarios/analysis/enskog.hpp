#pragma once
/// Enskog's collision frequencies of a homogeneous hard-sphere mixture: the reference that a
/// periodic, gravity-free run is checked against.
///
/// A particle of species s meets particles of species t at the rate
///   nu_st = n_t g_st d_st^2 sqrt(8 pi T / mu_st),   d_st = (d_s + d_t)/2,  mu_st = m_s m_t/(m_s + m_t),
/// (the Boltzmann rate n pi d^2 <|v_rel|> times the contact value g_st of the pair correlation),
/// with the Boublik-Mansoori-Carnahan-Starling-Leland contact value g_st of the mixture
/// (core/contact_value.hpp), which for one species is Carnahan-Starling's and gives the
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
