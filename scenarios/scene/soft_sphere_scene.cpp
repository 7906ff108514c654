#include "scenarios/scene/soft_sphere_scene.hpp"

#include <string>

namespace carom {

void read_soft_sphere(TableReader& root, Scene& scene) {
  SoftSphereOptions& o = scene.method.soft_sphere;
  auto t = root.table("soft_sphere");
  const bool used = scene.method.kind == MethodKind::SoftSphere;
  if (t) {
    // Read and checked with any method, used only by soft spheres: one scene file switches
    // between methods with [method] kind alone.
    const std::string model = t->string("contact_model", "hertz_mindlin", {"hertz_mindlin", "linear"});
    o.model = model == "linear" ? ContactModel::Linear : ContactModel::HertzMindlin;
    const std::string damping = t->string("damping", "exact", {"exact", "liggghts"});
    o.damping = damping == "liggghts" ? HertzDamping::Liggghts : HertzDamping::Exact;
    if (o.model == ContactModel::Linear && t->has("damping"))
      t->fail("damping", "chooses the Hertz damping; the linear model's damping is exact by construction");
    o.stiffness = t->number("stiffness", 0.0, Range::non_negative("linear normal stiffness k, N/m (0: from contact_time)"));
    o.contact_time = t->number("contact_time", 0.0, Range::non_negative("linear model: binary contact time of every pair, s"));
    if (o.model == ContactModel::HertzMindlin)
      for (const char* key : {"stiffness", "contact_time", "tangential_stiffness_ratio"})
        if (t->has(key)) t->fail(key, "is a linear-model key; contact_model is \"hertz_mindlin\" (stiffness comes from young_modulus)");
    if (o.model == ContactModel::Linear) {
      if (o.stiffness > 0.0 && o.contact_time > 0.0)
        t->fail("contact_time", "give stiffness or contact_time, not both");
      if (o.stiffness == 0.0 && o.contact_time == 0.0)
        t->fail_table("the linear model needs stiffness (N/m) or contact_time (s)");
    }
    o.tangential_stiffness_ratio = t->number("tangential_stiffness_ratio", o.tangential_stiffness_ratio,
                                             Range{0.0, 1.0, true, false, "linear model: k_t / k_n"});
    o.rolling_friction = t->number("rolling_friction", 0.0, Range::non_negative("rolling resistance mu_r (constant directional torque)"));
    o.time_step = t->number("time_step", 0.0, Range::non_negative("time step, s (0: step_fraction x the shortest contact time)"));
    o.step_fraction = t->number("step_fraction", o.step_fraction, Range{0.0, 0.5, true, false, "default step / shortest contact time"});
    if (o.time_step > 0.0 && t->has("step_fraction")) t->fail("step_fraction", "is not used when time_step is given");
    o.impact_speed = t->number("impact_speed", 0.0, Range::non_negative("largest impact speed expected, m/s (0: estimated)"));
    o.skin = t->number("skin", o.skin, Range{0.0, 2.0, true, false, "Verlet skin / smallest diameter"});
    o.max_overlap = t->number("max_overlap", o.max_overlap, Range{0.0, 1.0, true, false, "largest overlap / smaller radius before the run stops"});
    o.max_energy_drift = t->number("max_energy_drift", o.max_energy_drift, Range::positive("energy drift / largest kinetic + elastic energy before the run stops"));
    if (t->has("wall_young_modulus")) {
      ElasticMaterial wall;
      wall.young_modulus = t->number("wall_young_modulus", Range::positive("Young's modulus of the walls without their own, Pa"));
      wall.poisson_ratio = t->number("wall_poisson_ratio", 0.3, Range{0.0, 0.5, false, true, "Poisson ratio of those walls"});
      for (auto& m : o.wall_materials)
        if (!m) m = wall;
    } else if (t->has("wall_poisson_ratio")) {
      t->fail("wall_poisson_ratio", "needs wall_young_modulus beside it");
    }
    t->finish();
  }
  if (!used) return;
  if (o.model == ContactModel::HertzMindlin)
    for (std::size_t s = 0; s < scene.system.species.size(); ++s)
      if (!(o.species_materials[s].young_modulus > 0.0))
        root.fail_table("[method] kind = \"soft_sphere\" with the Hertz–Mindlin contact model needs "
                        "young_modulus (Pa) and poisson_ratio in [[species]] \"" +
                        scene.system.species[s].name +
                        "\" (or [soft_sphere] contact_model = \"linear\" with stiffness or contact_time)");
  if (scene.flight.model == FlightModel::Kick)
    root.fail_table("flight.model = \"kick\" is an event-driven scheme; the soft-sphere method applies "
                    "the drag at every step: use flight.model = \"relax\" (or leave it out)");
}

}  // namespace carom
