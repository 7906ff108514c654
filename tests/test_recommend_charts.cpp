// `carom check` cites the shipped charts (scenarios/analysis/chart_evidence.hpp): where a chart backs
// a recommendation, its reason carries the chart's measured numbers and names the chart file,
// and a chart is cited only where its topic applies. The numbers are taken from
// chart_evidence.hpp and formatted as recommend.cpp formats them (core/display_number.hpp), so
// the test checks that the output carries them, not their values (the records hold those).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/display_number.hpp"
#include "recommend_support.hpp"
#include "scenarios/analysis/chart_evidence.hpp"
#include "scenarios/cli/recommend.hpp"

namespace carom {
namespace {

using test::placed;

const Advice* find(const std::vector<Advice>& advice, const std::string& name) {
  for (const Advice& a : advice)
    if (a.topic == name) return &a;
  return nullptr;
}
// A pointer into a temporary list would dangle (ASan caught one): keep the list in a variable.
const Advice* find(std::vector<Advice>&& advice, const std::string& name) = delete;

/// recommend.cpp's number format (core/display_number.hpp).
std::string num(double x) { return display_number(x); }
std::string pct(double x) {
  return num(100.0 * x) + " %";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(RecommendCharts, DiluteGasChartBacksTheMethodAndNoFluidChartWithoutGas) {
  const Scene gas = placed("dilute_gas.toml", {});
  const std::vector<Advice> advice = recommend(gas, scene_numbers(gas));
  const std::string reason = find(advice, "method")->reason;
  EXPECT_TRUE(has(reason, evidence::kDiluteGas.file)) << reason;
  EXPECT_TRUE(has(reason, evidence::kDiluteGas.date)) << reason;
  for (double x : {evidence::kDiluteGasMonteCarloCostLow, evidence::kDiluteGasMonteCarloCostHigh,
                   evidence::kDiluteGasEventCost, evidence::kDiluteGasSoftCostLow,
                   evidence::kDiluteGasSoftCostHigh})
    EXPECT_TRUE(has(reason, num(x))) << num(x) << " not in: " << reason;
  for (double x : {evidence::kDiluteGasMonteCarloErrorLow, evidence::kDiluteGasMonteCarloErrorHigh,
                   evidence::kDiluteGasSoftErrorHigh})
    EXPECT_TRUE(has(reason, pct(x))) << pct(x) << " not in: " << reason;
  // No gas and no Monte Carlo: neither map is cited anywhere.
  const std::string text = describe_recommendation(scene_numbers(gas), advice);
  EXPECT_FALSE(has(text, evidence::kFluidMap.file)) << text;
  EXPECT_FALSE(has(text, evidence::kMonteCarloMap.file)) << text;
  EXPECT_EQ(find(advice, "monte carlo"), nullptr);
}

TEST(RecommendCharts, FluidMapBacksTheGasGridCouplingAndRelaxFlights) {
  // small_bed: a two-way bed (mass loading far above 0.1), fluid steps of 2e-4 s against a
  // relaxation time U_t / g of about 0.7 s: kick or relax flights.
  const Scene bed = placed("small_bed.toml", {});
  const SceneNumbers n = scene_numbers(bed);
  const std::vector<Advice> advice = recommend(bed, n);
  const std::string grid = find(advice, "gas grid")->reason;
  EXPECT_TRUE(has(grid, evidence::kFluidMap.file)) << grid;
  for (double x : {evidence::kFluidForceErrorCell2, evidence::kFluidForceErrorCell4,
                   evidence::kFluidMixingErrorCell2, evidence::kFluidMixingErrorCell4})
    EXPECT_TRUE(has(grid, pct(x))) << pct(x) << " not in: " << grid;
  const Advice* coupling = find(advice, "coupling");
  ASSERT_EQ(coupling->choice, "two-way");
  EXPECT_TRUE(has(coupling->reason, evidence::kFluidMap.file)) << coupling->reason;
  EXPECT_TRUE(has(coupling->reason, num(evidence::kFluidOneWayForceLow))) << coupling->reason;
  EXPECT_TRUE(has(coupling->reason, num(evidence::kFluidOneWayForceHigh))) << coupling->reason;
  EXPECT_TRUE(has(coupling->reason, "lasting_contacts")) << coupling->reason;
  // Both flight advices cite the map: kicks allowed at 2e-4 s, relax only at 0.02 s.
  const Scene coarse = placed("small_bed.toml", {"gas.time_step=0.02"});
  const SceneNumbers c = scene_numbers(coarse);
  const std::vector<Advice> coarse_advice = recommend(coarse, c);
  ASSERT_GE(n.step_ratio, kKickStepRatio);
  ASSERT_LT(c.step_ratio, kKickStepRatio);
  for (const Advice* flight : {find(advice, "flight"), find(coarse_advice, "flight")}) {
    EXPECT_TRUE(has(flight->reason, evidence::kFluidMap.file)) << flight->reason;
    EXPECT_TRUE(has(flight->reason, num(evidence::kFluidLargestStep) + " s")) << flight->reason;
    EXPECT_TRUE(has(flight->reason, pct(evidence::kFluidStepForceError))) << flight->reason;
    EXPECT_TRUE(has(flight->reason, pct(evidence::kFluidStepMixingError))) << flight->reason;
  }
  EXPECT_EQ(find(coarse_advice, "flight")->choice, "relax");
  // The whole `carom check` section carries them too.
  EXPECT_TRUE(has(describe_recommendation(n, advice), evidence::kFluidMap.date));
}

/// mc_gas.toml run by the Monte Carlo method at solid fraction phi (the box edge for 2000
/// spheres), with the scene's contact value and partner as given.
Scene mc_gas(double phi, const std::string& contact_value, const std::string& partner) {
  const double edge = std::cbrt(2000 * M_PI / 6 / phi);
  const std::string e = num(edge);
  return placed("mc_gas.toml",
                {"method.kind=monte_carlo", "domain.max=[" + e + "," + e + "," + e + "]",
                 "monte_carlo.contact_value=" + contact_value, "monte_carlo.partner=" + partner});
}

TEST(RecommendCharts, MonteCarloMapOnBothSidesOfItsLimits) {
  // The estimate is the larger of the box's solid fraction and that around a typical particle
  // (the other particles in its sample cell of 4 diameters), which scatters about the box's by
  // its sampling error: the dilute scene is the map's most dilute one, the others a factor of
  // 2-3 inside the limits.
  const double dilute = 0.005;
  const double middle =
      std::sqrt(evidence::kMonteCarloPlainLimit * evidence::kMonteCarloEnskogLimit);
  const double dense = std::min(0.3, 2 * evidence::kMonteCarloEnskogLimit);
  ASSERT_GT(middle, 2 * evidence::kMonteCarloPlainLimit);
  ASSERT_GT(dense, 1.2 * evidence::kMonteCarloEnskogLimit);

  const Scene a = mc_gas(dilute, "none", "gaussian");
  const SceneNumbers an = scene_numbers(a);
  ASSERT_LT(std::max(an.solid_fraction, an.solid_fraction_seen), evidence::kMonteCarloPlainLimit);
  const std::vector<Advice> low = recommend(a, an);
  const Advice* mc = find(low, "monte carlo");
  ASSERT_NE(mc, nullptr);
  EXPECT_EQ(mc->choice, "contact_value = none or enskog");
  EXPECT_FALSE(mc->differs);
  EXPECT_TRUE(has(mc->reason, evidence::kMonteCarloMap.file)) << mc->reason;
  EXPECT_TRUE(has(mc->reason, evidence::kMonteCarloMap.date)) << mc->reason;
  for (const std::string& part :
       {num(evidence::kMonteCarloPlainLimit), pct(evidence::kMonteCarloPlainErrorAt005),
        pct(evidence::kMonteCarloEnskogWorstError), num(evidence::kMonteCarloEnskogLimit),
        pct(evidence::kMonteCarloTemperatureWorstError), num(evidence::kMonteCarloTemperatureLimit),
        pct(evidence::kMonteCarloCellParticleErrorAt02),
        pct(evidence::kMonteCarloGaussianErrorAt03)})
    EXPECT_TRUE(has(mc->reason, part)) << part << " not in: " << mc->reason;

  const Scene b = mc_gas(middle, "enskog", "cell_particle");
  const std::vector<Advice> mid = recommend(b, scene_numbers(b));
  EXPECT_EQ(find(mid, "monte carlo")->choice, "contact_value = enskog");
  EXPECT_FALSE(find(mid, "monte carlo")->differs);
  const Scene c = mc_gas(middle, "none", "cell_particle");
  const std::vector<Advice> plain = recommend(c, scene_numbers(c));
  EXPECT_TRUE(find(plain, "monte carlo")->differs);  // Boltzmann's rate is off here

  const Scene d = mc_gas(dense, "enskog", "gaussian");
  const std::vector<Advice> high = recommend(d, scene_numbers(d));
  EXPECT_EQ(find(high, "monte carlo")->choice, "event_driven");
  EXPECT_TRUE(find(high, "monte carlo")->differs);
  EXPECT_TRUE(has(find(high, "monte carlo")->reason, evidence::kMonteCarloMap.file));
  // An event-driven scene gets no Monte Carlo advice.
  const Scene e = placed("mc_gas.toml", {});
  const std::vector<Advice> events = recommend(e, scene_numbers(e));
  EXPECT_EQ(find(events, "monte carlo"), nullptr);
}

TEST(RecommendCharts, KickMapGivesTheErrorAndTheStabilityLimitOnBothSides) {
  // small_bed's relaxation time is about 0.7 s: fluid steps of 2e-4 s (kicks fine), 0.02 s
  // (relax advised, kicks off by about 0.35 step / tau) and 2 s (beyond kKickLimitLow of 2 tau:
  // kicks unstable).
  const auto flight_of = [](const std::vector<std::string>& sets) {
    const Scene bed = placed("small_bed.toml", sets);
    const SceneNumbers n = scene_numbers(bed);
    const std::vector<Advice> advice = recommend(bed, n);
    return std::make_pair(n, *find(advice, "flight"));
  };
  const auto [fine_n, fine] = flight_of({"flight.model=kick"});
  const auto [mid_n, mid] = flight_of({"flight.model=kick", "gas.time_step=0.02"});
  const auto [coarse_n, coarse] =
      flight_of({"flight.model=kick", "gas.time_step=2.0", "time.end=20.0"});
  ASSERT_GE(fine_n.step_ratio, kKickStepRatio);
  ASSERT_LT(mid_n.step_ratio, kKickStepRatio);
  ASSERT_GT(mid_n.step_ratio, 1.0 / (2.0 * evidence::kKickLimitLow));
  ASSERT_LT(coarse_n.step_ratio, 1.0 / (2.0 * evidence::kKickLimitHigh));
  for (const Advice* a : {&fine, &mid, &coarse}) {
    EXPECT_TRUE(has(a->reason, evidence::kKickMap.file)) << a->reason;
    EXPECT_TRUE(has(a->reason, num(evidence::kKickLimitLow) + "-" + num(evidence::kKickLimitHigh) +
                                   " of 2 tau"))
        << a->reason;
  }
  EXPECT_EQ(fine.choice, "kick or relax");
  EXPECT_FALSE(fine.differs);
  EXPECT_TRUE(has(fine.reason, pct(evidence::kKickErrorPerStep / fine_n.step_ratio)))
      << fine.reason;
  EXPECT_EQ(mid.choice, "relax");
  EXPECT_TRUE(mid.differs);
  EXPECT_TRUE(
      has(mid.reason, "off by about " + pct(evidence::kKickErrorPerStep / mid_n.step_ratio)))
      << mid.reason;
  EXPECT_FALSE(has(mid.reason, "unstable")) << mid.reason;
  EXPECT_TRUE(has(coarse.reason, "would be unstable")) << coarse.reason;
}

TEST(RecommendCharts, SoftSphereMapsJudgeTheStepAndTheStiffnessOnBothSides) {
  // soft_column: Hertz beads of E = 1e7 Pa falling about 40 mm (the speed scale a fall through
  // the domain's height), step 1/50 of the contact time.
  const Scene column = placed("soft_column.toml", {});
  const SceneNumbers n = scene_numbers(column);
  ASSERT_TRUE(std::isfinite(n.peak_overlap));
  ASSERT_LT(n.peak_overlap, 0.1);
  const std::vector<Advice> advice = recommend(column, n);
  const Advice* step = find(advice, "soft-sphere step");
  const Advice* stiff = find(advice, "soft-sphere stiffness");
  ASSERT_NE(step, nullptr);
  ASSERT_NE(stiff, nullptr);
  EXPECT_FALSE(step->differs) << step->reason;
  EXPECT_FALSE(stiff->differs) << stiff->reason;
  for (const std::string& part :
       {std::string(evidence::kSoftStepMap.file), num(evidence::kSoftStepLargestCompleted),
        num(evidence::kSoftStepFirstStopped), num(evidence::kSoftStepOverlapDefault)})
    EXPECT_TRUE(has(step->reason, part)) << part << " not in: " << step->reason;
  for (const std::string& part :
       {std::string(evidence::kSoftLoadMap.file), num(evidence::kSoftLoadStopped),
        num(evidence::kSoftLoadCompleted), num(evidence::kSoftLoadHertzEstimate)})
    EXPECT_TRUE(has(stiff->reason, part)) << part << " not in: " << stiff->reason;

  // A step of half the contact time, beyond the map's first stopped step.
  const Scene long_step = placed("soft_column.toml", {"soft_sphere.step_fraction=0.5"});
  const std::vector<Advice> a = recommend(long_step, scene_numbers(long_step));
  EXPECT_TRUE(find(a, "soft-sphere step")->differs);
  EXPECT_EQ(find(a, "soft-sphere step")->choice, "step_fraction = 0.02");

  // Beads 1e4 times softer overlap 1e4^(2/5) = 40 times deeper: beyond max_overlap = 0.1.
  const Scene soft = placed("soft_column.toml", {"species.bead.young_modulus=1e3"});
  const SceneNumbers sn = scene_numbers(soft);
  EXPECT_NEAR(sn.peak_overlap / n.peak_overlap, std::pow(1e4, 0.4), 1e-9 * std::pow(1e4, 0.4));
  ASSERT_GT(sn.peak_overlap, 0.1);
  const std::vector<Advice> soft_advice = recommend(soft, sn);
  const Advice* too_soft = find(soft_advice, "soft-sphere stiffness");
  EXPECT_TRUE(too_soft->differs);
  EXPECT_TRUE(has(too_soft->reason, "overlap detector will stop the run")) << too_soft->reason;

  // An event-driven scene that needs no soft spheres gets neither advice.
  const Scene gas = placed("dilute_gas.toml", {});
  const std::vector<Advice> events = recommend(gas, scene_numbers(gas));
  EXPECT_EQ(find(events, "soft-sphere step"), nullptr);
  EXPECT_EQ(find(events, "soft-sphere stiffness"), nullptr);
}

}  // namespace
}  // namespace carom
