#include "scenarios/scene/particles_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace carom {

void read_listed(TableReader& root, Scene& scene) {
  for (TableReader p : root.tables("particles")) {
    ListedParticle particle;
    particle.where = p.where();
    particle.species = species_index(p, "species", scene);
    particle.position = p.required_vector3("position", Range::any("centre, m"));
    particle.velocity = p.vector3("velocity", Vec3::Zero(), Range::any("velocity, m/s"));
    particle.spin = p.vector3("spin", Vec3::Zero(), Range::any("angular velocity, rad/s"));
    particle.tagged = p.boolean("tagged", false);
    p.finish();
    // Listed particles take the ids 0, 1, ... in file order.
    if (particle.tagged) scene.analysis.tagged_bodies.push_back(scene.listed.size());
    scene.listed.push_back(particle);
  }
}

}  // namespace carom
