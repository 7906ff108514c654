#pragma once
/// Reading triangle meshes from STL files (the format CAD and DEM tools export equipment in):
/// ASCII ("solid ... facet normal ... outer loop vertex x y z ... endloop endfacet ... endsolid")
/// and binary (80-byte header, little-endian uint32 triangle count, then per triangle 12
/// float32 (normal, three vertices) and a uint16 attribute). Which one a file is is decided by
/// its size: a file whose size is exactly 84 + 50 n, n its header's count, is binary (some
/// binary headers start with "solid" too); anything else starting with "solid" is ASCII.
/// The stored normals are ignored: a triangle's orientation is its vertices' order
/// (right-handed), as every STL writer keeps it consistent with the normal.
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace carom {

/// A triangle of a mesh: three vertices, m, in order (the right-hand rule gives its normal).
using Triangle = std::array<Vec3, 3>;

/// A fault in an STL file; what() names the file (and the line, for ASCII) and what is wrong.
class StlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How the file's coordinates become metres: x_m = scale * x_file + translate.
struct StlUnits {
  double scale = 1.0;             ///< metres per file unit (0.001 for millimetres)
  Vec3 translate = Vec3::Zero();  ///< added after scaling, m
};

/// The triangles of the STL file at `path` (ASCII or binary), in the file's order, in metres.
/// Throws StlError for an unreadable, empty, truncated or malformed file, a binary triangle
/// count that does not match the file's size, a non-finite coordinate, or a degenerate triangle
/// (zero area: two vertices equal or all three on a line, to 1e-12 of its longest edge squared).
std::vector<Triangle> read_stl(const std::string& path, const StlUnits& units = {});

/// The same from the file's bytes; `name` stands for the file in messages.
std::vector<Triangle> parse_stl(const std::string& bytes, const std::string& name,
                                const StlUnits& units = {});

}  // namespace carom
