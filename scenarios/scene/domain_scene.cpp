#include "scenarios/scene/domain_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace carom {

namespace {

std::string vec_text(const Vec3& v) {
  std::string text("[");
  for (int k = 0; k < 3; ++k) {
    text += format_number(v[k]);
    text += k < 2 ? ", " : "]";
  }
  return text;
}

int axis_index(const std::string& name) { return name == "x" ? 0 : name == "y" ? 1 : 2; }

}  // namespace

void read_domain(TableReader& root, Scene& scene) {
  auto domain = root.table("domain");
  if (!domain) root.fail_table("the [domain] section is missing (keys min, max, periodic, gravity)");
  Domain& d = scene.system.domain;
  d.lower = domain->required_vector3("min", Range::any("lower corner of the box, m"));
  d.upper = domain->required_vector3("max", Range::any("upper corner of the box, m"));
  for (int k = 0; k < 3; ++k)
    if (!(d.upper[k] > d.lower[k]))
      domain->fail("max", "must exceed domain.min = " + vec_text(d.lower) + " on every axis (not on " +
                              std::string(1, "xyz"[k]) + ")");
  d.periodic = {false, false, false};
  for (const std::string& axis : domain->strings("periodic")) {
    if (axis != "x" && axis != "y" && axis != "z")
      domain->fail("periodic", "names an axis \"" + axis + "\"; allowed: any of \"x\", \"y\", \"z\"");
    if (d.periodic[axis_index(axis)]) domain->fail("periodic", "names axis \"" + axis + "\" twice");
    d.periodic[axis_index(axis)] = true;
  }
  scene.system.flight.gravity = domain->vector3("gravity", Vec3::Zero(), Range::any("gravitational acceleration, m/s^2"));
  domain->finish();
}

void read_regions(TableReader& root, Scene& scene) {
  const Domain& d = scene.system.domain;
  scene.regions.push_back(Region{"domain", d.lower, d.upper});
  auto regions = root.table("regions");
  if (!regions) return;
  for (const std::string& name : regions->keys()) {
    if (name == "domain") regions->fail(name, "is reserved for the whole domain; choose another region name");
    auto r = regions->table(name);
    Region region{name, r->required_vector3("min", Range::any("lower corner of the region, m")),
                  r->required_vector3("max", Range::any("upper corner of the region, m"))};
    for (int k = 0; k < 3; ++k) {
      if (!(region.upper[k] > region.lower[k]))
        r->fail("max", "must exceed " + r->key_path("min") + " = " + vec_text(region.lower) + " on every axis");
      if (region.lower[k] < d.lower[k] || region.upper[k] > d.upper[k])
        r->fail(region.lower[k] < d.lower[k] ? "min" : "max",
                "puts the region outside the domain [" + vec_text(d.lower) + ", " + vec_text(d.upper) + "] on axis " +
                    std::string(1, "xyz"[k]));
    }
    r->finish();
    scene.regions.push_back(region);
  }
}

}  // namespace carom
