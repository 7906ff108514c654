// Forces on a spinning sphere (fluid/spin_forces.hpp) and their kicks (fluid/kick_scheme.hpp):
// the Oesterle & Bui Dinh lift coefficient and force, the Dennis et al. rotational coefficient
// and torque, against values computed with Python (double precision) from the published
// formulas as fluid/spin_forces.hpp writes them; their limits against independent results
// (the Stokes rotlet, Rubinow & Keller's low-Re lift); the direction of the lift; and one kick
// with spin forces against its formula, with the torque's stability limit refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fluid/kick_scheme.hpp"
#include "fluid/spin_forces.hpp"
#include "tests/assertions.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using carom::test::kPi;

using test::close;

// C_L = 0.45 + (2 Gamma - 0.45) exp(-0.075 Gamma^0.4 Re^0.7). Python: 0.45 + (2*G - 0.45) *
// math.exp(-0.075 * G**0.4 * Re**0.7). Same formula, a few roundings: 1e-12 relative.
TEST(SpinForces, LiftCoefficientAgainstHandValues) {
  EXPECT_TRUE(close(oesterle_bui_dinh_lift_coefficient(1.0, 10.0), 1.514350235768613, 1e-12));
  EXPECT_TRUE(close(oesterle_bui_dinh_lift_coefficient(2.5, 60.0), 1.1299730092221774, 1e-12));
  EXPECT_TRUE(close(oesterle_bui_dinh_lift_coefficient(6.0, 140.0), 0.5375567961708833, 1e-12));
  EXPECT_TRUE(close(oesterle_bui_dinh_lift_coefficient(0.2, 0.5), 0.40119802698478313, 1e-12));
}

// C_R = 64 pi / Re_R up to Re_R = 32, 12.9 / sqrt(Re_R) + 128.4 / Re_R above (Python, 1e-12).
// The two branches meet within 0.2 % at Re_R = 32 (6.2832 and 6.2923).
TEST(SpinForces, RotationalCoefficientAgainstHandValues) {
  EXPECT_TRUE(close(dennis_rotational_coefficient(1.0), 201.06192982974676, 1e-12));
  EXPECT_TRUE(close(dennis_rotational_coefficient(32.0), 6.283185307179586, 1e-12));
  EXPECT_TRUE(close(dennis_rotational_coefficient(100.0), 2.574, 1e-12));
  EXPECT_TRUE(close(dennis_rotational_coefficient(1000.0), 0.536333818161721, 1e-12));
  EXPECT_TRUE(close(dennis_rotational_coefficient(32.0 * (1 + 1e-12)), 6.283185307179586, 2e-3));
}

// A 3 mm sphere in air (rho_g 1.2, mu_g 1.8e-5) with slip u - v = (-0.5, 0, 0.1) m/s and
// Omega_rel = (0, 600, -50) rad/s: Gamma = 1.77116, Re = 101.980, C_L = 0.730351, Re_R = 361.25,
// C_R = 1.034149. Vectors from Python with F = pi/8 rho d^2 C_L |w| (Omega x w)/|Omega| and
// T = rho/2 (d/2)^5 C_R |Omega| Omega, 1e-12 relative per component (the zero component of T
// exactly).
TEST(SpinForces, ForceAndTorqueVectorsAgainstHandValues) {
  SpinForceInput in;
  in.slip = Vec3(-0.5, 0.0, 0.1);
  in.relative_rotation = Vec3(0.0, 600.0, -50.0);
  in.diameter = 3e-3;
  EXPECT_TRUE(close(spin_parameter(in), 1.7711632422702406, 1e-12));
  EXPECT_TRUE(close(rotational_reynolds_number(in), 361.2478373637689, 1e-12));
  const Vec3 f = oesterle_bui_dinh_lift(in);
  EXPECT_TRUE(close(f.x(), 1.5739801083303557e-07, 1e-12));
  EXPECT_TRUE(close(f.y(), 6.558250451376482e-08, 1e-12));
  EXPECT_TRUE(close(f.z(), 7.869900541651778e-07, 1e-12));
  const Vec3 t = dennis_torque(in);
  EXPECT_EQ(t.x(), 0.0);
  EXPECT_TRUE(close(t.y(), 1.702142645965152e-09, 1e-12));
  EXPECT_TRUE(close(t.z(), -1.41845220497096e-10, 1e-12));
  // The selectors give the same, or nothing.
  EXPECT_EQ(magnus_lift_force(MagnusLift::OesterleBuiDinh, in), f);
  EXPECT_EQ(rotational_torque(RotationalTorque::Dennis, in), t);
  EXPECT_EQ(magnus_lift_force(MagnusLift::None, in), Vec3::Zero());
  EXPECT_EQ(rotational_torque(RotationalTorque::None, in), Vec3::Zero());
}

// Independent physics: below Re_R = 32 the torque is the Stokes rotlet T = 8 pi mu a^3 Omega
// (Lamb), exactly (the coefficient 64 pi / Re_R is that rotlet written in C_R); to round-off.
TEST(SpinForces, SlowSpinIsTheStokesRotlet) {
  SpinForceInput in;
  in.diameter = 1e-4;
  in.relative_rotation = Vec3(3.0, -4.0, 12.0);  // Re_R = 1.2 * 1e-8 * 13 / 1.8e-5 = 0.0087
  const double a = 0.5 * in.diameter;
  const Vec3 t = dennis_torque(in);
  for (int k = 0; k < 3; ++k)
    EXPECT_TRUE(
        close(t[k], 8.0 * kPi * in.gas_viscosity * a * a * a * in.relative_rotation[k], 1e-13));
}

// Independent physics: at low Re and Gamma the lift tends to Rubinow & Keller's
// F = pi rho_g a^3 Omega x (u - v); here Re = 1e-7 and Gamma = 0.01, so the exponent is
// x = 0.075 Gamma^0.4 Re^0.7 = 1.5e-7 and C_L / (2 Gamma) - 1 = (0.45 / (2 Gamma) - 1) x =
// 3.2e-6 (Python): the tolerance 1e-5 holds it, a wrong prefactor or power would not.
TEST(SpinForces, LowReynoldsLiftIsRubinowKeller) {
  SpinForceInput in;
  in.diameter = 1e-6;
  in.slip = Vec3(1.5e-6, 0.0, 0.0);             // Re = 1e-7
  in.relative_rotation = Vec3(0.0, 0.0, 0.03);  // Gamma = 0.01
  const double a = 0.5 * in.diameter;
  const Vec3 expected = kPi * in.gas_density * a * a * a * in.relative_rotation.cross(in.slip);
  const Vec3 f = oesterle_bui_dinh_lift(in);
  EXPECT_TRUE(close(f.y(), expected.y(), 1e-5));
  EXPECT_NEAR(f.x(), 0.0, 1e-30);
  EXPECT_NEAR(f.z(), 0.0, 1e-30);
}

// A sphere moving along +x through still air with backspin (its top surface moving backwards:
// w = -|w| y) is lifted (+z); topspin pushes it down; spin along the motion gives no lift. The
// torque opposes the spin in all cases.
TEST(SpinForces, BackspinLiftsTopspinPressesDown) {
  SpinForceInput in;
  in.diameter = 3e-3;
  const Vec3 v(2.0, 0.0, 0.0), backspin(0.0, -300.0, 0.0);
  in.slip = -v;  // still air
  in.relative_rotation = -backspin;
  EXPECT_GT(oesterle_bui_dinh_lift(in).z(), 0.0);
  EXPECT_NEAR(oesterle_bui_dinh_lift(in).x(), 0.0, 1e-20);
  EXPECT_LT(dennis_torque(in).dot(backspin), 0.0);
  in.relative_rotation = backspin;  // topspin
  EXPECT_LT(oesterle_bui_dinh_lift(in).z(), 0.0);
  in.relative_rotation = Vec3(-300.0, 0.0, 0.0);  // spin about the direction of motion
  EXPECT_EQ(oesterle_bui_dinh_lift(in).norm(), 0.0);
  in.slip = Vec3::Zero();  // no slip: no lift, torque still
  EXPECT_EQ(oesterle_bui_dinh_lift(in).norm(), 0.0);
  EXPECT_GT(dennis_torque(in).norm(), 0.0);
}

TEST(SpinForces, NamesRoundTripAndBadNamesRejected) {
  for (std::size_t i = 0; i < magnus_lift_names().size(); ++i)
    EXPECT_EQ(static_cast<std::size_t>(parse_magnus_lift(magnus_lift_names()[i])), i);
  for (std::size_t i = 0; i < rotational_torque_names().size(); ++i)
    EXPECT_EQ(static_cast<std::size_t>(parse_rotational_torque(rotational_torque_names()[i])), i);
  try {
    parse_magnus_lift("saffman");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("oesterle_bui_dinh"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_rotational_torque("Dennis"), std::invalid_argument);
}

// One kick with lift and torque: v' = v + dt_p (rate (u - v) + F_L / m), w' = w + dt_p T / I,
// all from the state before the kick (gravity is the flight's, not the kick's).
TEST(SpinForces, OneKickAddsLiftAndTorqueImpulses) {
  const Vec3 g(0, 0, -9.81), u(0.2, 0.0, -0.1), v0(1.0, 0.0, 0.3), w0(0.0, -500.0, 40.0);
  const double a = 1.5e-3, m = 1.4e-6, inertia = 0.4 * m * a * a, rate = 1.5, dt = 1e-4;
  ParticleStore p;
  p.add(Vec3::Zero(), v0, w0, a, m, inertia, 0, 7);
  std::vector<RelaxFlight> flights{RelaxFlight{rate, g + rate * u}};
  const SpinForceKicks spin{{MagnusLift::OesterleBuiDinh, RotationalTorque::Dennis}, 1.2, 1.8e-5};
  const std::vector<Vec3> gas{u};
  KickScheme(dt, g, spin).kick(p, flights, &gas);
  SpinForceInput in;
  in.slip = u - v0;
  in.relative_rotation = -w0;
  in.diameter = 2 * a;
  const Vec3 v_expected = v0 + dt * (rate * (u - v0) + oesterle_bui_dinh_lift(in) / m);
  const Vec3 w_expected = w0 + dt / inertia * dennis_torque(in);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p.velocity[0][k], v_expected[k], 1e-15 * v_expected.norm()) << k;
    EXPECT_NEAR(p.spin[0][k], w_expected[k], 1e-15 * w_expected.norm()) << k;
  }
  EXPECT_LT(p.spin[0].norm(), w0.norm());  // the torque slows the spin
  // Spin forces without the gas velocity at the particles are a programming error.
  EXPECT_THROW(KickScheme(dt, g, spin).kick(p, flights, nullptr), std::logic_error);
}

// The torque kick's limit: dt_p |T| / (I |w|) <= 2. A fine 0.1 mm sphere spinning slowly in the
// Stokes regime decays at the rate 8 pi mu a^3 / I = 20 pi mu a / m; a step 10 % above 2 / rate
// is refused before any change, with the particle, the rate and the remedy named.
TEST(SpinForces, KickRefusesTorqueStepsBeyondTheSpinDecayLimit) {
  const double a = 5e-5, m = 2500.0 * 4.0 / 3.0 * kPi * a * a * a, inertia = 0.4 * m * a * a;
  const double rate = 20.0 * kPi * 1.8e-5 * a / m;
  ParticleStore p;
  p.add(Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, 10.0), a, m, inertia, 0, 31);
  std::vector<RelaxFlight> flights{RelaxFlight{0.0, Vec3::Zero()}};
  const std::vector<Vec3> gas{Vec3::Zero()};
  const SpinForceKicks torque_only{{MagnusLift::None, RotationalTorque::Dennis}, 1.2, 1.8e-5};
  EXPECT_NO_THROW(KickScheme(1.9 / rate, Vec3::Zero(), torque_only).check_stability(p, flights));
  try {
    KickScheme(2.2 / rate, Vec3::Zero(), torque_only).kick(p, flights, &gas);
    FAIL() << "accepted an unstable torque kick";
  } catch (const KickUnstable& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("particle 31"), std::string::npos) << message;
    EXPECT_NE(message.find("flight.particle_step"), std::string::npos) << message;
    EXPECT_NE(message.find("rotational_torque"), std::string::npos) << message;
  }
  EXPECT_EQ(p.spin[0], Vec3(0, 0, 10.0));
}

}  // namespace
}  // namespace carom
