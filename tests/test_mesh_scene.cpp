// Mesh walls in scenes: [[walls]] type = "mesh" with `file` (relative to the scene's folder),
// `scale`, `translate` and `solid`, and its errors (file, line, key; the STL file's own fault).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "scenarios/scene/scene.hpp"

using namespace carom;

namespace {

/// A folder of its own under the test's temporary directory.
std::string folder() {
  const std::string dir = testing::TempDir() + "carom_mesh_scene";
  std::filesystem::create_directories(dir);
  return dir;
}

/// A cube of side 10 (file units) at the origin, outward, as ASCII STL; `drop` triangles left out.
void write_cube(const std::string& path, int drop = 0) {
  const auto corner = [](int i) {
    return std::to_string(10 * (i & 1)) + " " + std::to_string(10 * ((i >> 1) & 1)) + " " +
           std::to_string(10 * ((i >> 2) & 1));
  };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::ofstream out(path);
  out << "solid cube\n";
  int written = 0;
  for (const auto& q : quads)
    for (const auto& t :
         {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}})
      if (written++ < 12 - drop)
        out << "facet normal 0 0 0\nouter loop\nvertex " << corner(t[0]) << "\nvertex "
            << corner(t[1]) << "\nvertex " << corner(t[2]) << "\nendloop\nendfacet\n";
  out << "endsolid cube\n";
}

/// A walled box with a mesh wall; `keys` are its extra lines. Line numbers: [[walls]] is 5.
std::string scene_with(const std::string& keys) {
  return "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [0.1, 0.1, 0.1]\ngravity = [0.0, 0.0, -9.81]\n"
         "[[walls]]\nname = \"block\"\ntype = \"mesh\"\n" +
         keys +
         "[[species]]\nname = \"bead\"\ndiameter = 2.0e-3\ndensity = 2500.0\n"
         "[time]\nend = 0.1\n";
}

std::string error_of(const std::string& text) {
  try {
    Scene scene = parse_scene(text, folder() + "/scene.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshScene, ReadsTheFileRelativeToTheSceneWithUnits) {
  write_cube(folder() + "/cube.stl");
  const Scene scene = parse_scene(
      scene_with(
          "file = \"cube.stl\"\nscale = 0.001\ntranslate = [0.04, 0.05, 0.0]\nsolid = true\n"),
      folder() + "/scene.toml");
  ASSERT_EQ(scene.system.walls.size(), 7u);  // six box walls and the mesh: one wall
  const Wall& wall = scene.system.walls.back();
  EXPECT_EQ(wall.name, "block");
  const MeshWall& mesh = std::get<MeshWall>(wall.shape);
  EXPECT_EQ(mesh.triangles().size(), 12u);
  EXPECT_TRUE(mesh.solid());
  EXPECT_NEAR(mesh.enclosed_volume(), 1e-6, 1e-18);  // (10 mm)^3
  EXPECT_NEAR(mesh.bounds().lower.x(), 0.04, 1e-15);
  EXPECT_NEAR(mesh.bounds().upper.y(), 0.06, 1e-15);
}

TEST(MeshScene, ErrorsNameTheKeyAndTheFile) {
  write_cube(folder() + "/open.stl", 1);
  write_cube(folder() + "/cube.stl");
  {
    const std::string m = error_of(scene_with("file = \"missing.stl\"\n"));
    EXPECT_NE(m.find("walls[0].file"), std::string::npos) << m;
    EXPECT_NE(m.find("missing.stl: cannot be opened"), std::string::npos) << m;
  }
  {
    const std::string m = error_of(scene_with("file = \"open.stl\"\nsolid = true\n"));
    EXPECT_NE(m.find("walls[0].solid"), std::string::npos) << m;
    EXPECT_NE(m.find("open.stl"), std::string::npos) << m;
    EXPECT_NE(m.find("belongs to one triangle only"), std::string::npos) << m;
  }
  EXPECT_EQ(error_of(scene_with("file = \"open.stl\"\nscale = 0.001\n")), "");  // plates: fine
  {
    const std::string m = error_of(scene_with("file = \"cube.stl\"\nscale = 0.0\n"));
    EXPECT_NE(m.find("walls[0].scale"), std::string::npos) << m;
  }
  {
    std::ofstream(folder() + "/broken.stl")
        << "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n";
    const std::string m = error_of(scene_with("file = \"broken.stl\"\n"));
    EXPECT_NE(m.find("broken.stl:4: 'vertex' needs three numbers"), std::string::npos) << m;
  }
  {
    std::string text = scene_with("file = \"cube.stl\"\nscale = 0.001\n");
    text.replace(text.find("gravity"), 0, "periodic = [\"x\"]\n");
    const std::string m = error_of(text);
    EXPECT_NE(m.find("a mesh needs walled axes"), std::string::npos) << m;
  }
}
