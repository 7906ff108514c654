#pragma once
/// NaN: the value of a quantity not measured or not defined (NaN in HDF5, null in JSON).
#include <limits>

namespace carom {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace carom
