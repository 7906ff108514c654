#pragma once
/// The measured numbers of the shipped charts that back `carom check`'s recommendations
/// (scenarios/cli/recommend.cpp cites them with the chart's file) and report.md's account of what
/// its numbers depend on (report_settings.cpp). The one place they live: when a chart is run
/// again, change its block here to the numbers its record then states (the record and the
/// command that reproduces each number are named with the chart).

namespace carom::evidence {

/// A shipped chart: its file (from the repository root), the date its numbers were measured
/// and where its record is.
struct ChartSource {
  const char* file;
  const char* date;
  const char* record;
};

// ---------------------------------------------------------------------------------------------
/// The dilute elastic gas (1320 spheres, phi = 0.05, 60 s, seeds 1-4): all three methods'
/// collision frequency against event-driven (scenarios/chart/CHARTS.md, "The dilute-gas chart").
inline constexpr ChartSource kDiluteGas{"scenarios/scenes/dilute_gas_chart.toml", "2026-12-02",
                                        "scenarios/chart/CHARTS.md"};
/// Event-driven cost, CPU s per simulated second.
inline constexpr double kDiluteGasEventCost = 0.0039;
/// Monte Carlo variants' cost, in event-driven costs (lowest, highest).
inline constexpr double kDiluteGasMonteCarloCostLow = 1.3, kDiluteGasMonteCarloCostHigh = 3.4;
/// Monte Carlo variants' collision-frequency error (relative; lowest, highest).
inline constexpr double kDiluteGasMonteCarloErrorLow = 0.025, kDiluteGasMonteCarloErrorHigh = 0.058;
/// Soft-sphere variants' cost, in event-driven costs (lowest, highest).
inline constexpr double kDiluteGasSoftCostLow = 8.0, kDiluteGasSoftCostHigh = 27.0;
/// Soft-sphere variants' largest collision-frequency |error| (relative).
inline constexpr double kDiluteGasSoftErrorHigh = 0.012;

// ---------------------------------------------------------------------------------------------
/// The Monte Carlo model against solid fraction (2000 elastic spheres, 30 s, phi 0.005-0.3,
/// seeds 1-8, automatic step and cells; scenarios/scenes/STABILITY_MC_FLUID.md): where its
/// collision frequency and mean temperature leave the event-driven result by more than
/// kMonteCarloTolerance.
inline constexpr ChartSource kMonteCarloMap{"scenarios/scenes/stability_monte_carlo.toml",
                                            "2026-12-02", "scenarios/scenes/STABILITY_MC_FLUID.md"};
/// The map's tolerance (relative).
inline constexpr double kMonteCarloTolerance = 0.05;
/// Solid fraction where the plain (Boltzmann, contact_value = "none") collision frequency
/// leaves the tolerance (by more than its uncertainty; 0.0227 and 0.0244 for the two partners).
inline constexpr double kMonteCarloPlainLimit = 0.023;
/// The plain collision frequency's error at phi = 0.05 (relative; -13.4 % and -12.7 %).
inline constexpr double kMonteCarloPlainErrorAt005 = -0.13;
/// Solid fraction up to which the Enskog (contact_value = "enskog") collision frequency stayed
/// within the tolerance with either partner (it left it between 0.2 and 0.3: +11 % and +18 % at
/// 0.3).
inline constexpr double kMonteCarloEnskogLimit = 0.2;
/// The Enskog collision frequency's largest |error| up to kMonteCarloEnskogLimit (relative).
inline constexpr double kMonteCarloEnskogWorstError = 0.042;
/// Solid fraction up to which the mean temperature stayed within the tolerance with every
/// variant, and its largest |error| there (relative).
inline constexpr double kMonteCarloTemperatureLimit = 0.05;
inline constexpr double kMonteCarloTemperatureWorstError = 0.036;
/// Above it: the mean temperature with partner = "cell_particle" at phi = 0.2 and with the
/// Gaussian partners (contact_value = "none") at phi = 0.3 (relative errors).
inline constexpr double kMonteCarloCellParticleErrorAt02 = -0.081;
inline constexpr double kMonteCarloGaussianErrorAt03 = 0.109;

// ---------------------------------------------------------------------------------------------
/// The fluid step and gas cells in a small fluidized bed (400 beads of 1 mm at 1.6 m/s, relax
/// flights, seeds 1-3; STABILITY_MC_FLUID.md): errors against the finest setting (1e-4 s, cells
/// of 1 diameter), relative.
inline constexpr ChartSource kFluidMap{"scenarios/scenes/stability_fluid.toml", "2026-12-02",
                                       "scenarios/scenes/STABILITY_MC_FLUID.md"};
/// The largest fluid step of the map (s): up to it the step moved the gas force per weight (the
/// pressure drop) by at most kFluidStepForceError with cells of 1 and 2 diameters, and the
/// mixing rate by at most kFluidStepMixingError with cells of 1 diameter.
inline constexpr double kFluidLargestStep = 2e-3;
inline constexpr double kFluidStepForceError = 0.0077, kFluidStepMixingError = 0.143;
/// Gas force per weight error of cells of 2 and 4 diameters at the finest step.
inline constexpr double kFluidForceErrorCell2 = -0.0074, kFluidForceErrorCell4 = -0.047;
/// Mixing rate error of cells of 2 and 4 diameters at the finest step.
inline constexpr double kFluidMixingErrorCell2 = -0.36, kFluidMixingErrorCell4 = -0.40;
/// One-way coupling (2e-4 s, cells of 2 diameters): the gas carried only this share of the
/// bed's weight (lowest, highest over the seeds), the bed stayed packed and every run stopped
/// with lasting_contacts.
inline constexpr double kFluidOneWayForceLow = 0.43, kFluidOneWayForceHigh = 0.50;

// ---------------------------------------------------------------------------------------------
/// Kick flights (settling spheres of 0.5, 0.7 and 1 mm, 17 particle steps from 0.01 to 1.5 s,
/// gas step 0.01 s; scenarios/chart/CHARTS.md, "Stability maps"): the fall's error against the
/// exact solution of the same drag law, and where the kicks go unstable.
inline constexpr ChartSource kKickMap{"scenarios/scenes/stability_kick.toml", "2026-12-02",
                                      "scenarios/chart/CHARTS.md"};
/// The fall's error is first order: about this times dt_p / tau (1 % at tau / 30, 10 % at
/// tau / 4).
inline constexpr double kKickErrorPerStep = 0.35;
/// The largest stable step, 2 m / (dF/ds) at the terminal velocity, over 2 tau (the drag is
/// refreshed before each kick; lowest and highest over the three beads: 0.858 / 1.395 s and
/// 0.487 / 0.756 s). The measured boundaries lay just below it.
inline constexpr double kKickLimitLow = 0.615, kKickLimitHigh = 0.644;

// ---------------------------------------------------------------------------------------------
/// The soft-sphere step against the contact time (soft_column.toml, 150 Hertz beads, E = 1e7 Pa,
/// impacts up to 1.085 m/s; CHARTS.md "Stability maps").
inline constexpr ChartSource kSoftStepMap{"scenarios/scenes/stability_soft_step.toml", "2026-12-02",
                                          "scenarios/chart/CHARTS.md"};
/// Steps (in contact times of the real impacts) up to the first completed, from the second
/// stopped (the overlap or energy detector), at every declared impact speed.
inline constexpr double kSoftStepLargestCompleted = 0.41, kSoftStepFirstStopped = 0.45;
/// The peak overlap (over the radius) at the default step, 1/50 of the contact time, and at
/// 0.4 of it.
inline constexpr double kSoftStepOverlapDefault = 0.076, kSoftStepOverlapAt04 = 0.093;

/// The soft-sphere stiffness against the load (soft_column.toml, 400 beads falling onto an
/// E = 1e7 Pa floor, g = 1 to 100 m/s^2, bead modulus 1e4 to 1e8 Pa; CHARTS.md).
inline constexpr ChartSource kSoftLoadMap{"scenarios/scenes/stability_soft_load.toml", "2026-12-02",
                                          "scenarios/chart/CHARTS.md"};
/// At g = 9.81 m/s^2: the last modulus the overlap detector stopped and the first that
/// completed (Pa), against the Hertz estimate of a 0.1 R peak overlap after the scene's 59 mm
/// fall on the floor (Pa): the boundary follows the Hertz impact estimate (E ~ g over the map).
inline constexpr double kSoftLoadStopped = 3e6, kSoftLoadCompleted = 1e7,
                        kSoftLoadHertzEstimate = 4.9e6;

// ---------------------------------------------------------------------------------------------
/// The main job's bed (fines_bed.toml, 0.5 s after 0.2 s of settling, each TC time settling its
/// own bed) at TC times of 1e-4, 5e-5, 2e-5 and 1e-5 s, event-driven with relax flights
/// (scenarios/chart/CHARTS.md, "The fines bed's TC time").
inline constexpr ChartSource kFinesBedTc{"scenarios/scenes/fines_bed_tc_chart.toml", "2026-12-08",
                                         "scenarios/chart/CHARTS.md"};
inline constexpr int kFinesBedTcSeeds = 3;
/// The TC time the scene had when charted (it runs at kFinesBedTcConverged since), the shortest
/// charted (s), and the longest whose mixing rate was within the seeds' noise of the shortest's.
inline constexpr double kFinesBedTcShipped = 1e-4, kFinesBedTcShortest = 1e-5, kFinesBedTcConverged = 2e-5;
/// The large beads' mixing rate (1/s, mean of the seeds) at the scene's and the shortest TC time.
inline constexpr double kFinesBedTcMixingShipped = 0.36, kFinesBedTcMixingShortest = 0.70;
/// Their collisions with each other per large bead (1/s) at the scene's and the shortest TC time.
inline constexpr double kFinesBedTcLargeLargeShipped = 2630, kFinesBedTcLargeLargeShortest = 13200;
/// Impacts (collisions faster than 0.1 sqrt(g d_fines)) from kFinesBedTcConverged to
/// kFinesBedTcShortest, relative: large-large, large-fines and fines-fines (the first the only
/// one outside the seeds' noise).
inline constexpr double kFinesBedTcImpactLargeLarge = 0.14, kFinesBedTcImpactLargeFines = 0.05,
                        kFinesBedTcImpactFinesFines = -0.10;
/// The raw large-large collision frequency over the same step, relative.
inline constexpr double kFinesBedTcRawLargeLargeStep = -0.35;

}  // namespace carom::evidence
