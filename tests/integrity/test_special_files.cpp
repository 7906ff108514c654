// Special files are refused before anything reads them, naming the file and the key: a device
// (/dev/zero, which would be read until memory runs out), a FIFO with no writer (whose open
// would block forever) and a directory, given as the scene, as a mesh, as initial.from_file and
// as a sweep file. Also: a UTF-8 byte-order mark before an ASCII STL's "solid" is read as ASCII;
// an error quotes at most a short excerpt of a huge token; a mesh wholly outside the domain is
// an error naming the axis and the keys that place it.
#include <sys/stat.h>

#include "tests/integrity/integrity_support.hpp"

namespace {

using namespace carom_integrity_test;

class SpecialFiles : public IntegrityCli {
 protected:
  void SetUp() override {
    IntegrityCli::SetUp();
    ASSERT_EQ(mkfifo((dir_ / "fifo").c_str(), 0644), 0);
    fs::create_directories(dir_ / "folder");
  }
  /// A small box whose scene adds `extra` (a [[walls]] or [initial] table).
  std::string box(const std::string& name, const std::string& extra) {
    return scene(name,
                 "[domain]\nmin = [0, 0, 0]\nmax = [4, 4, 4]\n[[species]]\nname = \"a\"\ndiameter = 0.5\n"
                 "density = 1000\nfill = { count = 10 }\n" + extra + "[time]\nend = 0.1\n");
  }
  /// `carom ARGS` must exit 2 within the test's timeout with a message holding every one of `parts`.
  void expect_refused(const std::string& args, const std::vector<std::string>& parts) {
    EXPECT_EQ(carom(args), 2) << args << "\n" << out_;
    for (const std::string& part : parts) EXPECT_NE(out_.find(part), std::string::npos) << part << "\n" << out_;
  }
};

const std::vector<std::pair<std::string, std::string>> kSpecial = {
    {"/dev/zero", "a character device"}, {"fifo", "a FIFO"}, {"folder", "a directory"}};

TEST_F(SpecialFiles, AreRefusedAsTheSceneAMeshAFromFileAndASweepFile) {
  for (const auto& [path, kind] : kSpecial) {
    SCOPED_TRACE(path);
    if (path != "folder") expect_refused("check " + path, {path, kind});  // a folder has its own message
    box("mesh.toml", "[[walls]]\nname = \"m\"\ntype = \"mesh\"\nfile = \"" + path + "\"\n");
    expect_refused("check mesh.toml", {"mesh.toml:", "walls[0].file", path, kind});
    box("from.toml", "[initial]\nfrom_file = { path = \"" + path + "\" }\n");
    expect_refused("check from.toml", {"from.toml:", "initial.from_file.path", path, kind});
    expect_refused("sweep " + path + " --dry-run", {path, kind});
  }
}

TEST_F(SpecialFiles, AnAsciiStlWithAByteOrderMarkIsReadAsAscii) {
  const std::string facet =
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1\nvertex 4 0 1\nvertex 0 4 1\nendloop\nendfacet\n"
      "endsolid t\n";
  std::ofstream(dir_ / "bom.stl") << "\xEF\xBB\xBF" << facet;
  box("bom.toml", "[[walls]]\nname = \"m\"\ntype = \"mesh\"\nfile = \"bom.stl\"\n");
  EXPECT_EQ(carom("check bom.toml"), 0) << out_;
  // A scene file with a byte-order mark reads too.
  std::ofstream(dir_ / "bom_scene.toml") << "\xEF\xBB\xBF" << read(dir_ / "bom.toml");
  EXPECT_EQ(carom("check bom_scene.toml"), 0) << out_;
}

TEST_F(SpecialFiles, AHugeBadTokenIsQuotedAsAShortExcerpt) {
  std::ofstream(dir_ / "token.stl") << "solid t\nfacet normal 0 0 1\nouter loop\nvertex " << std::string(5'000'000, 'x')
                                    << " 0 1\n";
  box("token.toml", "[[walls]]\nname = \"m\"\ntype = \"mesh\"\nfile = \"token.stl\"\n");
  expect_refused("check token.toml", {"token.toml:", "walls[0].file", "characters)"});
  EXPECT_LT(out_.size(), 600u) << out_.substr(0, 600);
}

TEST_F(SpecialFiles, AMeshWhollyOutsideTheDomainIsAnError) {
  std::ofstream(dir_ / "plate.stl")
      << "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1\nvertex 4 0 1\nvertex 0 4 1\nendloop\nendfacet\n"
         "endsolid t\n";
  box("far.toml", "[[walls]]\nname = \"m\"\ntype = \"mesh\"\nfile = \"plate.stl\"\ntranslate = [0, 0, 50]\n");
  expect_refused("check far.toml", {"far.toml:", "walls[0].file", "wholly outside the domain", "translate"});
  box("mm.toml", "[[walls]]\nname = \"m\"\ntype = \"mesh\"\nfile = \"plate.stl\"\nscale = 1000\n");
  expect_refused("check mm.toml", {"wholly outside the domain", "scale"});
}

}  // namespace
