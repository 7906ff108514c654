#include "scenarios/scene/walls_scene.hpp"

#include <string>

namespace carom {

void read_walls(TableReader& root, Scene& scene) {
  scene.system.walls = box_walls(scene.system.domain);
  for (TableReader w : root.tables("walls")) {
    const std::string name = w.required_string("name");
    for (const Wall& other : scene.system.walls)
      if (other.name == name)
        w.fail("name", "is already the name of a wall (box walls are x_low, x_high, y_low, ...)");
    const std::string type = w.required_string("type", {"plane", "cylinder"});
    if (type == "plane") {
      const Vec3 point = w.required_vector3("point", Range::any("a point on the plane, m"));
      const Vec3 normal =
          w.required_vector3("normal", Range::any("normal pointing into the particles' side"));
      if (!(normal.norm() > 0.0)) w.fail("normal", "must not be the zero vector");
      scene.system.walls.push_back(Wall::plane(name, point, normal));
    } else {
      const Vec3 axis = w.required_vector3(
          "axis", Range::any("a point on the cylinder's axis (along z); z is ignored, m"));
      const double radius = w.number("radius", Range::positive("inner radius of the cylinder, m"));
      scene.system.walls.push_back(Wall::cylinder(name, axis.x(), axis.y(), radius));
    }
    w.finish();
  }
}

}  // namespace carom
