#include "morsi_alexander.hpp"

#include <array>
#include <numbers>

namespace carom {

namespace {
/// One range of the fit: C_D = a1 + a2 / Re + a3 / Re^2 for Re up to `upper`.
struct Piece {
  double upper, a1, a2, a3;
};
constexpr std::array<Piece, 8> kPieces{{
    {0.1, 0.0, 24.0, 0.0},
    {1.0, 3.690, 22.73, 0.0903},
    {10.0, 1.222, 29.1667, -3.8889},
    {100.0, 0.6167, 46.50, -116.67},
    {1000.0, 0.3644, 98.33, -2778.0},
    {5000.0, 0.357, 148.62, -4.75e4},
    {10000.0, 0.46, -490.546, 5.787e5},
    {1e300, 0.5191, -1662.5, 5.4167e6},
}};

const Piece& piece_for(double reynolds) {
  for (const Piece& p : kPieces)
    if (reynolds <= p.upper) return p;
  return kPieces.back();
}
}  // namespace

double morsi_alexander_cd(double reynolds) {
  const Piece& p = piece_for(reynolds);
  return p.a1 + p.a2 / reynolds + p.a3 / (reynolds * reynolds);
}

double morsi_alexander_factor(double reynolds) {
  // C_D Re / 24 = (a1 Re + a2 + a3 / Re) / 24: finite as Re -> 0 (the first piece has a3 = 0).
  const Piece& p = piece_for(reynolds);
  const double inverse = p.a3 == 0.0 ? 0.0 : p.a3 / reynolds;
  return (p.a1 * reynolds + p.a2 + inverse) / 24.0;
}

double morsi_alexander_drag(const DragInput& in) {
  const double reynolds = in.gas_density * in.diameter * in.slip / in.gas_viscosity;
  return 3.0 * std::numbers::pi * in.gas_viscosity * in.diameter * morsi_alexander_factor(reynolds);
}

}  // namespace carom
