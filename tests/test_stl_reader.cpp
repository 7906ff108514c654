// The STL reader (core/stl_reader.hpp): the same tetrahedron written as ASCII and as binary
// reads back to the same triangles (coordinates chosen exact in float32, so equality is exact),
// units (scale, translate) applied, and every malformed file refused with a message naming the
// file (and line, for ASCII) and the fault.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "core/stl_reader.hpp"

namespace carom {
namespace {

/// The four faces of the tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), outward.
std::vector<Triangle> tetrahedron() {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  return {{o, y, x}, {o, x, z}, {o, z, y}, {x, y, z}};
}

std::string ascii(const std::vector<Triangle>& triangles) {
  std::string text = "solid tetra\n";
  for (const Triangle& t : triangles) {
    text += "  facet normal 0 0 0\n    outer loop\n";
    for (const Vec3& p : t)
      text += "      vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
              std::to_string(p.z()) + "\n";
    text += "    endloop\n  endfacet\n";
  }
  return text + "endsolid tetra\n";
}

void put_u32(std::string& out, std::uint32_t x) {
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((x >> (8 * k)) & 0xff));
}
void put_f32(std::string& out, float f) {
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  put_u32(out, bits);
}

/// Binary STL; the header starts with "solid" on purpose (writers do that; the size decides).
std::string binary(const std::vector<Triangle>& triangles, std::uint32_t count) {
  std::string out = "solid but binary";
  out.resize(80, ' ');
  put_u32(out, count);
  for (const Triangle& t : triangles) {
    for (int c = 0; c < 3; ++c) put_f32(out, 0.0f);
    for (const Vec3& p : t)
      for (int c = 0; c < 3; ++c) put_f32(out, static_cast<float>(p[c]));
    out.push_back('\0');
    out.push_back('\0');
  }
  return out;
}

/// The message of the StlError that parsing `bytes` throws ("" if none).
std::string stl_error(const std::string& bytes) {
  try {
    parse_stl(bytes, "part.stl");
  } catch (const StlError& e) {
    return e.what();
  }
  return "";
}

TEST(StlReader, AsciiAndBinaryReadTheSameTriangles) {
  const std::vector<Triangle> expected = tetrahedron();
  const std::vector<Triangle> from_ascii = parse_stl(ascii(expected), "a.stl");
  const std::vector<Triangle> from_binary = parse_stl(binary(expected, 4), "b.stl");
  ASSERT_EQ(from_ascii.size(), 4u);
  ASSERT_EQ(from_binary.size(), 4u);
  for (std::size_t t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(from_ascii[t][k], expected[t][k]);
      EXPECT_EQ(from_binary[t][k], expected[t][k]);
    }
}

TEST(StlReader, ScaleThenTranslate) {
  const StlUnits mm{0.001, Vec3(1.0, 2.0, 3.0)};
  const std::vector<Triangle> t = parse_stl(binary(tetrahedron(), 4), "b.stl", mm);
  // (1, 0, 0) mm -> 0.001 m, then moved: exactly 0.001 * 1 + 1.
  EXPECT_EQ(t[0][2], Vec3(0.001 * 1.0 + 1.0, 2.0, 3.0));
  EXPECT_EQ(t[3][2], Vec3(1.0, 2.0, 0.001 + 3.0));
}

TEST(StlReader, ReadsAFileAndNamesAMissingOne) {
  const std::string path = testing::TempDir() + "stl_reader_tetra.stl";
  {
    std::ofstream out(path, std::ios::binary);
    out << binary(tetrahedron(), 4);
  }
  EXPECT_EQ(read_stl(path).size(), 4u);
  try {
    read_stl(path + ".missing");
    FAIL() << "no error for a missing file";
  } catch (const StlError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ".missing"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

TEST(StlReader, TruncatedOrMiscountedBinaryIsRefused) {
  std::string bytes = binary(tetrahedron(), 4);
  bytes[0] = 'X';  // not "solid": surely binary
  const std::string truncated = stl_error(bytes.substr(0, bytes.size() - 7));
  EXPECT_NE(truncated.find("part.stl"), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("truncated"), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("4 triangles"), std::string::npos) << truncated;
  std::string miscounted = binary(tetrahedron(), 3);  // 4 written, count says 3
  miscounted[0] = 'X';
  const std::string message = stl_error(miscounted);
  EXPECT_NE(message.find("does not match its triangle count"), std::string::npos) << message;
  EXPECT_NE(message.find("3 triangles"), std::string::npos) << message;
  EXPECT_NE(stl_error("XY").find("neither ASCII STL"), std::string::npos);
}

TEST(StlReader, DegenerateAndNaNTrianglesAreRefused) {
  std::vector<Triangle> flat = tetrahedron();
  flat[2][2] = 0.5 * (flat[2][0] + flat[2][1]);  // vertex on the opposite edge: zero area
  for (const std::string& bytes : {ascii(flat), binary(flat, 4)}) {
    const std::string message = stl_error(bytes);
    EXPECT_NE(message.find("triangle 3"), std::string::npos) << message;
    EXPECT_NE(message.find("zero area"), std::string::npos) << message;
  }
  EXPECT_NE(stl_error(ascii(flat)).find("part.stl:22:"), std::string::npos)  // its endfacet
      << stl_error(ascii(flat));
  std::vector<Triangle> nan = tetrahedron();
  nan[1][1].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(stl_error(binary(nan, 4)).find("not a finite number"), std::string::npos);
  std::string text = ascii(tetrahedron());
  text.replace(text.find("vertex 1.000000"), 15, "vertex nan");
  const std::string message = stl_error(text);
  EXPECT_NE(message.find("part.stl:6:"), std::string::npos) << message;
  EXPECT_NE(message.find("not a finite number"), std::string::npos) << message;
}

TEST(StlReader, MalformedAsciiNamesTheLine) {
  const std::string good = ascii(tetrahedron());
  std::string typo = good;
  typo.replace(typo.find("outer loop"), 10, "outer lop");
  EXPECT_NE(stl_error(typo).find("part.stl:3: 'outer' must be followed by 'loop'"),
            std::string::npos)
      << stl_error(typo);
  std::string unknown = good;
  unknown.replace(unknown.find("endloop"), 7, "endlop");
  EXPECT_NE(stl_error(unknown).find("part.stl:7: unknown keyword 'endlop'"), std::string::npos)
      << stl_error(unknown);
  const std::string cut = good.substr(0, good.find("endfacet"));  // ends inside a facet
  EXPECT_NE(stl_error(cut).find("ends inside a facet"), std::string::npos) << stl_error(cut);
  std::string four = good;
  four.insert(four.find("    endloop"), "      vertex 0 0 2\n");
  EXPECT_NE(stl_error(four).find("more than 3 vertices"), std::string::npos) << stl_error(four);
  EXPECT_NE(stl_error("solid empty\nendsolid empty\n").find("no triangles"), std::string::npos);
  std::string word = good;
  word.replace(word.find("vertex 0.000000"), 15, "vertex 0.0abc");
  EXPECT_NE(stl_error(word).find("'0.0abc' is not a number"), std::string::npos) << stl_error(word);
}

}  // namespace
}  // namespace carom
