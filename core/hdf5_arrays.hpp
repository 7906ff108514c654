#pragma once
/// Vectors and tensors as the flat arrays HDF5 datasets hold (N x 3, 3 x 3 row by row).
#include <Eigen/Core>
#include <vector>

#include "vec3.hpp"

namespace carom::h5 {

/// N vectors as 3 N values (x, y, z of each in turn).
inline std::vector<double> flatten(const std::vector<Vec3>& vectors) {
  std::vector<double> values;
  values.reserve(3 * vectors.size());
  for (const Vec3& v : vectors) values.insert(values.end(), {v.x(), v.y(), v.z()});
  return values;
}

/// The inverse of flatten.
inline std::vector<Vec3> unflatten(const std::vector<double>& values) {
  std::vector<Vec3> vectors(values.size() / 3);
  for (std::size_t i = 0; i < vectors.size(); ++i)
    vectors[i] = Vec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
  return vectors;
}

/// A 3x3 tensor as 9 values, row by row (xx, xy, xz, yx, ...).
inline std::vector<double> row_major(const Eigen::Matrix3d& tensor) {
  std::vector<double> values(9);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) values[3 * r + c] = tensor(r, c);
  return values;
}

/// The inverse of row_major.
inline Eigen::Matrix3d from_row_major(const std::vector<double>& values) {
  Eigen::Matrix3d tensor;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) tensor(r, c) = values[3 * r + c];
  return tensor;
}

}  // namespace carom::h5
