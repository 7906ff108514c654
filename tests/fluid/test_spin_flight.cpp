// Spin forces end to end (scene -> method -> gas coupling -> kicks): a sphere spinning in still
// air slows down as the Dennis et al. torque says, and a sphere launched with backspin curves
// upwards as the Oesterle & Bui Dinh lift says, both against an independent RK4 integration of
// the same ODE, with the event-driven method and with the Monte Carlo method (kick flights; one
// particle, so no collisions). The kick scheme is first order in dt_p: the error halves when
// dt_p halves, and the Richardson extrapolation of two runs lands on the reference. Scene
// errors: spin forces with relax flights and unknown model names are refused with file, line,
// key and the remedy or the choices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "events/method_factory.hpp"
#include "fluid/morsi_alexander.hpp"
#include "fluid/spin_forces.hpp"
#include "scenarios/run/gas_run.hpp"
#include "scenarios/run/run_output.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {
namespace {

constexpr double kPi = std::numbers::pi;
// A 3 mm light bead (100 kg/m^3, expanded polystyrene) in air: light enough that the lift is a
// fifth of its weight or more, so the curve is large against the scheme's error.
constexpr double kDiameter = 3e-3, kDensity = 100.0, kGasDensity = 1.2, kGasViscosity = 1.8e-5;

struct Launch {
  std::string method = "event_driven";
  double particle_step = 1e-3;   // dt_p = the fluid step, s
  double gravity = 9.81;         // m/s^2 along -z
  Vec3 velocity = Vec3::Zero();  // m/s
  Vec3 spin = Vec3::Zero();      // rad/s
  std::string lift = "oesterle_bui_dinh";
  std::string torque = "dennis";
  std::string flight = "kick";
  double updraft = 0.0;  // superficial gas velocity in through z_low and out at z_high, m/s
};

std::string vec(const Vec3& v) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%.17g, %.17g, %.17g]", v.x(), v.y(), v.z());
  return buffer;
}

/// One bead in a closed box of still air (0.6 x 0.02 x 0.35 m: room for the 0.2 s throw, small
/// enough for the event-driven neighbour grid; gas at rest, its pressure hydrostatic, 8 cells
/// along z so the coupling resolves that gradient), one-way coupling, Morsi-Alexander drag.
std::string scene_text(const Launch& l) {
  const std::string step = std::to_string(l.particle_step);
  return "[domain]\nmin = [-0.55, -0.01, 0.22]\nmax = [0.05, 0.01, 0.57]\ngravity = [0.0, 0.0, " +
         std::to_string(-l.gravity) +
         "]\n\n[[species]]\nname = \"bead\"\ndiameter = 3.0e-3\ndensity = 100.0\n\n"
         "[[particles]]\nspecies = \"bead\"\nposition = [-0.5, 0.0, 0.5]\nvelocity = " +
         vec(l.velocity) + "\nspin = " + vec(l.spin) +
         "\n\n[collisions]\ndefault = { e = 0.9, mu = 0.1, beta0 = 0.3 }\n"
         "walls = { e = 0.9, mu = 0.1, beta0 = 0.3 }\n\n[method]\nkind = \"" +
         l.method + "\"\n" +
         (l.method == "soft_sphere"
              ? "[soft_sphere]\ncontact_model = \"linear\"\ncontact_time = 1e-4\n"
              : "") +
         // A bead at rest without gravity leaves the Monte Carlo method no speed to size its step
         // by; the kicks cut its steps to dt_p anyway.
         (l.method == "monte_carlo" ? "[monte_carlo]\ntime_step = 0.01\n" : "") +
         "\n[flight]\nmodel = \"" + l.flight + "\"\n" +
         (l.flight == "kick" ? "particle_step = " + step + "\n" : std::string()) +
         "\n[gas]\ncoupling = \"one_way\"\ndensity = 1.2\nviscosity = 1.8e-5\n"
         "cells = [1, 1, 8]\ntime_step = " +
         step + "\ndrag = \"morsi_alexander\"\nmagnus_lift = \"" + l.lift +
         "\"\nrotational_torque = \"" + l.torque + "\"\n" +
         (l.updraft != 0.0 ? "[gas.boundaries]\nz_low = { type = \"inlet\", velocity = " +
                                 std::to_string(l.updraft) +
                                 " }\nz_high = { type = \"outlet\", pressure = 0.0 }\n"
                           : std::string()) +
         "\n[time]\nend = 1.0\n";
}

struct CoupledRun {
  Scene scene;
  std::unique_ptr<CollisionMethod> sim;
  std::unique_ptr<GasCoupling> gas;
};

CoupledRun start(const Launch& l) {
  CoupledRun run;
  run.scene = parse_scene(scene_text(l), "spin.toml");
  build_initial_state(run.scene);
  run.sim = make_method(run.scene.system, run.scene.method);
  run.gas = attach_gas(*run.sim, run.scene);
  return run;
}

/// State of the reference ODE: position, velocity, spin.
struct State {
  Vec3 r, v, w;
};

/// m dv/dt = (m - rho_g V) g + F_drag + F_lift, I dw/dt = T (still air: u = 0, Omega_rel = -w),
/// with Morsi-Alexander drag, Oesterle-Bui Dinh lift, Dennis torque (each checked against hand
/// values in tests/fluid), integrated by classic RK4 with a 1e-5 s step: its error (h^4) is
/// below 1e-12 of the quantities compared, far below the kick scheme's.
State reference(const Launch& l, double t_end) {
  const double a = 0.5 * kDiameter;
  const double volume = 4.0 / 3.0 * kPi * a * a * a, m = kDensity * volume;
  const double inertia = 0.4 * m * a * a;
  const Vec3 g(0, 0, -l.gravity);
  const bool lift = l.lift != "none", torque = l.torque != "none";
  auto rate = [&](const State& s) {
    SpinForceInput in;
    in.slip = -s.v;
    in.relative_rotation = -s.w;
    in.diameter = kDiameter;
    in.gas_density = kGasDensity;
    in.gas_viscosity = kGasViscosity;
    const double re = kGasDensity * kDiameter * s.v.norm() / kGasViscosity;
    const Vec3 drag = 3.0 * kPi * kGasViscosity * kDiameter * morsi_alexander_factor(re) * in.slip;
    Vec3 force = drag + (m - kGasDensity * volume) * g;
    if (lift) force += oesterle_bui_dinh_lift(in);
    State d;
    d.r = s.v;
    d.v = force / m;
    d.w = torque ? Vec3(dennis_torque(in) / inertia) : Vec3(Vec3::Zero());
    return d;
  };
  auto step = [](const State& s, const State& d, double h) {
    return State{s.r + h * d.r, s.v + h * d.v, s.w + h * d.w};
  };
  State s{Vec3(-0.5, 0.0, 0.5), l.velocity, l.spin};
  const double h = 1e-5;
  const int n = static_cast<int>(std::lround(t_end / h));
  const double last = t_end - n * h;  // t_end need not be a multiple of h
  auto rk4 = [&](State& x, double dt) {
    const State k1 = rate(x), k2 = rate(step(x, k1, dt / 2)), k3 = rate(step(x, k2, dt / 2)),
                k4 = rate(step(x, k3, dt));
    x.r += dt / 6 * (k1.r + 2 * k2.r + 2 * k3.r + k4.r);
    x.v += dt / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
    x.w += dt / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w);
  };
  for (int i = 0; i < n; ++i) rk4(s, h);
  if (last > 0) rk4(s, last);
  return s;
}

// Times between kicks for dt_p = 2, 1 and 0.5 ms (0.25 ms past a multiple of 1 ms), so that
// "the state at t" never depends on whether a kick at t has been applied yet.
const double kSampleTimes[] = {0.05025, 0.10025, 0.20025};

/// Spin and position of a carom run at kSampleTimes.
std::vector<State> carom_history(const Launch& l) {
  CoupledRun run = start(l);
  std::vector<State> out;
  for (double t : kSampleTimes) {
    run.sim->run_until(t);
    out.push_back(State{run.sim->position(0), run.sim->velocity(0), run.sim->spin(0)});
  }
  return out;
}

// A sphere spinning at 600 rad/s in still air without gravity (it stays where it is: no slip,
// no lift): its spin decays as I dw/dt = T(w) with Re_R from 360 down to ~260. The kick scheme
// is explicit Euler on this ODE, and its spin is piecewise constant: after the kick at t_k it
// holds Euler's estimate of w(t_k + dt_p), so the error at a time between kicks depends on where
// between them it is sampled. Sampled half-way (at T + dt_p / 2, the reference at the same time),
// the error is C dt_p: at each T it halves with dt_p (ratio within 1.8 to 2.2 at 1 -> 0.5 ms),
// the finest stays below 1e-2 of the spin lost by T, and the Richardson combination of the
// signed errors, 2 e(dt/2) - e(dt), is below a fifth of the finest error (what is left is second
// order). Same for both methods that offer the spin forces.
class SpinningSphere : public ::testing::TestWithParam<const char*> {};

TEST_P(SpinningSphere, SpinDecaysAsTheDennisTorqueSays) {
  Launch l;
  l.method = GetParam();
  l.gravity = 0.0;
  l.spin = Vec3(0.0, 200.0, -565.685424949238);  // |w| = 600 rad/s
  const double steps[] = {1e-3, 5e-4};
  const double times[] = {0.05, 0.1, 0.2};
  Vec3 error[2][3];
  for (int j = 0; j < 2; ++j) {
    l.particle_step = steps[j];
    CoupledRun run = start(l);
    for (int k = 0; k < 3; ++k) {
      const double t = times[k] + 0.5 * steps[j];
      run.sim->run_until(t);
      error[j][k] = run.sim->spin(0) - reference(l, t).w;
      EXPECT_LT(run.sim->velocity(0).norm(), 1e-12);  // still at rest
      EXPECT_LT(run.sim->spin(0).cross(l.spin).norm(),
                1e-9 * l.spin.norm() * run.sim->spin(0).norm());
    }
  }
  for (int k = 0; k < 3; ++k) {
    const double lost = l.spin.norm() - reference(l, times[k]).w.norm();
    const double coarse = error[0][k].norm(), fine = error[1][k].norm();
    const double richardson = (2.0 * error[1][k] - error[0][k]).norm();
    std::printf(
        "%s T = %.3f s: spin lost %.4f rad/s, error %.3e (1 ms) %.3e (0.5 ms), ratio %.3f, "
        "Richardson %.2e\n",
        GetParam(), times[k], lost, coarse, fine, coarse / fine, richardson);
    EXPECT_GT(lost, 0.1 * l.spin.norm() * times[k]);  // it does slow down (~2 /s)
    EXPECT_NEAR(coarse / fine, 2.0, 0.2) << times[k];
    EXPECT_LT(fine, 1e-2 * lost) << times[k];
    EXPECT_LT(richardson, 0.2 * fine) << times[k];
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, SpinningSphere, ::testing::Values("event_driven", "monte_carlo"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

// A sphere thrown along +x at 1.2 m/s with 600 rad/s of backspin (w along -y) under gravity:
// Re 240 -> 300, Gamma 0.75 -> 0.39 (C_L 0.50 -> 0.47), the lift 0.22 -> 0.33 of the weight
// (Python, explicit Euler at 1e-5 s). That is outside Oesterle & Bui Dinh's measured range
// (Re < 140, Gamma > 1): this checks that carom integrates the formula, not the formula. Its
// trajectory against RK4 of drag + lift + buoyancy + gravity + torque: the position error halves
// with dt_p (2 -> 1 -> 0.5 ms, ratios within 1.8 to 2.2 at the last sample), the Richardson
// extrapolation of the two finest runs lands within a fifth of the finest error, and the lift
// is resolved: at 0.2 s the bead is higher than the same throw without lift by a height the
// finest error is under 2 % of. Backspin lifts: that height is positive.
class BackspinThrow : public ::testing::TestWithParam<const char*> {};

TEST_P(BackspinThrow, CurvesAsTheLiftSays) {
  Launch l;
  l.method = GetParam();
  l.velocity = Vec3(1.2, 0.0, 0.0);
  l.spin = Vec3(0.0, -600.0, 0.0);
  std::vector<std::vector<State>> runs;
  for (double dt : {2e-3, 1e-3, 5e-4}) {
    l.particle_step = dt;
    runs.push_back(carom_history(l));
  }
  Launch no_lift = l;
  no_lift.lift = "none";
  const std::size_t last = std::size(kSampleTimes) - 1;
  const double rise =
      reference(l, kSampleTimes[last]).r.z() - reference(no_lift, kSampleTimes[last]).r.z();
  std::printf("%s: the lift raises the bead by %.4e m at t = %.5f s\n", GetParam(), rise,
              kSampleTimes[last]);
  EXPECT_GT(rise, 1e-3);
  for (std::size_t k = 0; k < std::size(kSampleTimes); ++k) {
    const State ref = reference(l, kSampleTimes[k]);
    double error[3];
    for (int j = 0; j < 3; ++j) error[j] = (runs[j][k].r - ref.r).norm();
    const Vec3 extrapolated = 2.0 * runs[2][k].r - runs[1][k].r;
    std::printf(
        "%s t = %.5f s: r = %s (reference %s), errors %.3e %.3e %.3e, ratios %.3f %.3f, "
        "Richardson %.2e\n",
        GetParam(), kSampleTimes[k], vec(runs[2][k].r).c_str(), vec(ref.r).c_str(), error[0],
        error[1], error[2], error[0] / error[1], error[1] / error[2],
        (extrapolated - ref.r).norm());
    EXPECT_NEAR(error[1] / error[2], 2.0, 0.2) << kSampleTimes[k];
    EXPECT_LT((extrapolated - ref.r).norm(), 0.2 * error[2]) << kSampleTimes[k];
    EXPECT_LT(std::abs(runs[2][k].r.y()), 1e-12);  // no sideways force
  }
  EXPECT_LT((runs[2][last].r - reference(l, kSampleTimes[last]).r).norm(), 0.02 * rise);
}

INSTANTIATE_TEST_SUITE_P(Methods, BackspinThrow, ::testing::Values("event_driven", "monte_carlo"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

// A checkpoint in the middle of a throw into a 0.5 m/s updraft (at a kick and fluid step time,
// t = 0.1 s, and between kicks, t = 0.10025 s) resumes bit for bit: position, velocity and spin
// at 0.2 s equal the uninterrupted run's exactly. The gas velocity at each particle, which the
// spin kicks read until the next fluid step, travels in the gas checkpoint
// (particle_gas_velocity); with the updraft it is not zero, so a wrong one would show.
class SpinForceResume : public ::testing::TestWithParam<const char*> {};

TEST_P(SpinForceResume, CheckpointResumesBitForBit) {
  Launch l;
  l.method = GetParam();
  l.velocity = Vec3(1.2, 0.0, 0.0);
  l.spin = Vec3(0.0, -600.0, 0.0);
  l.updraft = 0.5;
  CoupledRun straight = start(l);
  straight.sim->run_until(0.2);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("carom_spin_resume_" + std::string(GetParam()));
  std::filesystem::create_directories(dir);
  for (double save_at : {0.1, 0.10025}) {
    const std::string path = (dir / "checkpoint.h5").string();
    {
      CoupledRun first = start(l);
      first.sim->run_until(save_at);
      write_checkpoint(path, *first.sim, RunInfo{first.scene.text, "spin", first.scene.seed},
                       first.gas.get());
    }
    const Checkpoint checkpoint = read_checkpoint(path);
    Scene scene = parse_scene(checkpoint.info.scene_text, "spin.toml");
    std::unique_ptr<CollisionMethod> sim =
        restore_method(scene.system, scene.method, checkpoint.method_state());
    const h5::Group gas_state = checkpoint.gas_state();
    std::unique_ptr<GasCoupling> gas = attach_gas(*sim, scene, &gas_state);
    ASSERT_GT(gas->gas_velocity_at_particles().at(0).z(), 0.4) << "the updraft reaches the bead";
    sim->run_until(0.2);
    EXPECT_EQ(sim->position(0), straight.sim->position(0)) << save_at;
    EXPECT_EQ(sim->velocity(0), straight.sim->velocity(0)) << save_at;
    EXPECT_EQ(sim->spin(0), straight.sim->spin(0)) << save_at;
  }
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Methods, SpinForceResume, ::testing::Values("event_driven", "monte_carlo"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

/// The message of the SceneError that parsing `l`'s scene throws ("" when it parses).
std::string scene_error(const Launch& l) {
  try {
    parse_scene(scene_text(l), "spin.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Relax flights are exact because the force is linear in v; the lift is not, so spin forces
// with relax flights are refused, naming the file and line of the key, the key, why, and what
// to use instead.
TEST(SpinForceScene, RelaxFlightsWithSpinForcesAreRefused) {
  Launch l;
  l.flight = "relax";
  std::string message = scene_error(l);
  EXPECT_NE(message.find("spin.toml:"), std::string::npos) << message;
  EXPECT_NE(message.find("gas.magnus_lift"), std::string::npos) << message;
  EXPECT_NE(message.find("non-analytic"), std::string::npos) << message;
  EXPECT_NE(message.find("model = \"kick\""), std::string::npos) << message;
  l.lift = "none";  // the torque alone is refused as well
  message = scene_error(l);
  EXPECT_NE(message.find("gas.rotational_torque"), std::string::npos) << message;
  l.torque = "none";  // and without spin forces relax flights are fine
  EXPECT_EQ(scene_error(l), "");
}

// Unknown names: the key, its place and the allowed choices.
TEST(SpinForceScene, UnknownModelsAreRefusedWithTheChoices) {
  Launch l;
  l.lift = "saffman";
  std::string message = scene_error(l);
  EXPECT_NE(message.find("spin.toml:"), std::string::npos) << message;
  EXPECT_NE(message.find("magnus_lift"), std::string::npos) << message;
  EXPECT_NE(message.find("oesterle_bui_dinh"), std::string::npos) << message;
  l.lift = "none";
  l.torque = "stokes";
  message = scene_error(l);
  EXPECT_NE(message.find("rotational_torque"), std::string::npos) << message;
  EXPECT_NE(message.find("dennis"), std::string::npos) << message;
}

// The soft-sphere method takes no kick flights, so no spin forces either (it says so).
TEST(SpinForceScene, SoftSpheresRefuseThem) {
  Launch l;
  l.method = "soft_sphere";
  EXPECT_NE(scene_error(l).find("kick"), std::string::npos) << scene_error(l);
}

}  // namespace
}  // namespace carom
