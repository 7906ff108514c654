// Reading STL files: the binary/ASCII decision, the two parsers and the checks on each triangle.
#include "core/stl_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace carom {

namespace {

constexpr std::size_t kHeaderBytes = 84;    // 80-byte header + uint32 count
constexpr std::size_t kTriangleBytes = 50;  // 12 float32 + uint16

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw StlError(where + ": " + what);
}

std::uint32_t little_u32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

float little_f32(const unsigned char* p) {
  const std::uint32_t bits = little_u32(p);
  float x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

/// "" when the triangle (file units) is fine, else what is wrong with it.
std::string triangle_problem(const Triangle& t) {
  for (const Vec3& p : t)
    if (!p.allFinite()) return "has a vertex that is not a finite number (NaN or infinity)";
  const double longest = std::max(
      {(t[1] - t[0]).squaredNorm(), (t[2] - t[1]).squaredNorm(), (t[0] - t[2]).squaredNorm()});
  const double twice_area = (t[1] - t[0]).cross(t[2] - t[0]).norm();
  if (!(twice_area > 1e-12 * longest))
    return "is degenerate: it has zero area (two vertices equal, or all three on a line)";
  return "";
}

Triangle in_metres(const Triangle& t, const StlUnits& units) {
  Triangle out;
  for (int k = 0; k < 3; ++k) out[k] = units.scale * t[k] + units.translate;
  return out;
}

std::vector<Triangle> parse_binary(const std::string& bytes, const std::string& name,
                                   const StlUnits& units) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint32_t count = little_u32(data + 80);
  std::vector<Triangle> triangles;
  triangles.reserve(count);
  for (std::uint32_t n = 0; n < count; ++n) {
    const unsigned char* facet = data + kHeaderBytes + kTriangleBytes * n;
    Triangle t;
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) t[k][c] = little_f32(facet + 12 + 12 * k + 4 * c);
    if (const std::string why = triangle_problem(t); !why.empty())
      fail(name, "binary STL, triangle " + std::to_string(n + 1) + " of " + std::to_string(count) +
                     " " + why);
    triangles.push_back(in_metres(t, units));
  }
  return triangles;
}

/// The ASCII parser: one keyword per line, checked against where it may appear.
class AsciiParser {
 public:
  AsciiParser(const std::string& name, const StlUnits& units) : name_(name), units_(units) {}

  std::vector<Triangle> parse(const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      ++line_number_;
      std::istringstream words(line);
      std::string keyword;
      if (!(words >> keyword)) continue;
      std::transform(keyword.begin(), keyword.end(), keyword.begin(),
                     [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      handle(keyword, words);
    }
    if (state_ != State::Outside)
      fail(name_ + ":" + std::to_string(line_number_),
           "ASCII STL ends inside a " + std::string(state_ == State::Solid ? "solid" : "facet") +
               " (truncated: every facet needs endloop and endfacet, the solid endsolid)");
    if (triangles_.empty()) fail(name_, "ASCII STL holds no triangles");
    return triangles_;
  }

 private:
  enum class State { Outside, Solid, Facet, Loop, LoopDone };

  [[noreturn]] void error(const std::string& what) const {
    fail(name_ + ":" + std::to_string(line_number_), what);
  }
  void expect(State wanted, const std::string& keyword, const char* where) const {
    if (state_ != wanted) error("'" + keyword + "' is out of place (expected " + where + ")");
  }
  Vec3 numbers(std::istringstream& words, const std::string& keyword) const {
    Vec3 x;
    for (int c = 0; c < 3; ++c) {
      std::string word;
      if (!(words >> word)) error("'" + keyword + "' needs three numbers");
      char* end = nullptr;
      x[c] = std::strtod(word.c_str(), &end);
      if (end != word.c_str() + word.size()) error("'" + word + "' is not a number");
      if (!std::isfinite(x[c])) error("'" + word + "' is not a finite number (NaN or infinity)");
    }
    return x;
  }

  void handle(const std::string& keyword, std::istringstream& words) {
    if (keyword == "solid") {
      expect(State::Outside, keyword, "only at the start, or after endsolid");
      state_ = State::Solid;
    } else if (keyword == "endsolid") {
      expect(State::Solid, keyword, "after the last endfacet");
      state_ = State::Outside;
    } else if (keyword == "facet") {
      expect(State::Solid, keyword, "after solid or endfacet");
      std::string normal;
      if (!(words >> normal) || normal != "normal") error("'facet' must be followed by 'normal'");
      numbers(words, "facet normal");  // read for its syntax; the vertices' order counts
      state_ = State::Facet;
      vertices_ = 0;
    } else if (keyword == "outer") {
      expect(State::Facet, keyword, "after facet normal");
      std::string loop;
      if (!(words >> loop) || loop != "loop") error("'outer' must be followed by 'loop'");
      state_ = State::Loop;
    } else if (keyword == "vertex") {
      expect(State::Loop, keyword, "inside outer loop ... endloop");
      if (vertices_ == 3) error("a facet has more than 3 vertices (STL holds triangles only)");
      triangle_[static_cast<std::size_t>(vertices_++)] = numbers(words, keyword);
    } else if (keyword == "endloop") {
      expect(State::Loop, keyword, "after the third vertex");
      if (vertices_ != 3)
        error("a facet has " + std::to_string(vertices_) + " vertices; a triangle needs 3");
      state_ = State::LoopDone;
    } else if (keyword == "endfacet") {
      expect(State::LoopDone, keyword, "after endloop");
      if (const std::string why = triangle_problem(triangle_); !why.empty())
        error("triangle " + std::to_string(triangles_.size() + 1) + " " + why);
      triangles_.push_back(in_metres(triangle_, units_));
      state_ = State::Solid;
    } else {
      error("unknown keyword '" + keyword +
            "' (ASCII STL has solid, facet normal, outer loop, vertex, endloop, endfacet, "
            "endsolid)");
    }
  }

  const std::string& name_;
  const StlUnits& units_;
  State state_ = State::Outside;
  int line_number_ = 0;
  int vertices_ = 0;
  Triangle triangle_;
  std::vector<Triangle> triangles_;
};

}  // namespace

std::vector<Triangle> parse_stl(const std::string& bytes, const std::string& name,
                                const StlUnits& units) {
  if (!(std::isfinite(units.scale) && units.scale > 0.0) || !units.translate.allFinite())
    throw std::invalid_argument(name +
                                ": the scale must be finite and > 0, the translation finite");
  const bool looks_ascii = bytes.compare(0, 5, "solid") == 0;
  if (bytes.size() >= kHeaderBytes) {
    const std::uint32_t count =
        little_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    const std::size_t expected = kHeaderBytes + kTriangleBytes * static_cast<std::size_t>(count);
    if (bytes.size() == expected) {
      if (count == 0) fail(name, "binary STL holds no triangles (its count is 0)");
      return parse_binary(bytes, name, units);
    }
    if (!looks_ascii)
      fail(name, "binary STL whose size does not match its triangle count: the header says " +
                     std::to_string(count) + " triangles, which take 84 + 50 * " +
                     std::to_string(count) + " = " + std::to_string(expected) +
                     " bytes, and the file has " + std::to_string(bytes.size()) +
                     (bytes.size() < expected ? " (truncated)" : ""));
  } else if (!looks_ascii) {
    fail(name,
         "is neither ASCII STL (it does not start with 'solid') nor binary STL (shorter "
         "than the 84-byte header: " +
             std::to_string(bytes.size()) + " bytes)");
  }
  return AsciiParser(name, units).parse(bytes);
}

std::vector<Triangle> read_stl(const std::string& path, const StlUnits& units) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened (missing or unreadable STL file)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) fail(path, "could not be read");
  return parse_stl(bytes, path, units);
}

}  // namespace carom
