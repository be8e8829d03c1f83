#include "integration/system.h"

#include <algorithm>
#include <cmath>

namespace walkers {
namespace {

// Simbody's weighted RMS norm over the first `size` entries
double Rms(const LocalError::Vector& x, int size) {
  return size > 0 ? std::sqrt(x.head(size).squaredNorm() / size) : 0.0;
}

}  // namespace

bool SecondOrderSystem::AccelerationJacobian(const Vec9& /*q*/, const Vec9& /*v*/, Mat9* /*da_dq*/,
                                             Mat9* /*da_dv*/) {
  return false;
}

bool SecondOrderSystem::Derivatives(const Vec9& q, const Vec9& v, Vec9* a, double* z_rate) {
  *z_rate = 0.0;
  return Accelerations(q, v, a);
}

LocalError SecondOrderSystem::EstimateError(const SystemState& y1, const SystemState& y_check, double factor) const {
  LocalError e;
  e.q_size = e.u_size = kNumCoords;
  e.z_size = 1;
  e.q.head<kNumCoords>() = factor * (y1.q - y_check.q).cwiseAbs();
  e.u.head<kNumCoords>() = factor * (y1.v - y_check.v).cwiseAbs();
  e.z = factor * std::abs(y1.z - y_check.z);
  return e;
}

double SecondOrderSystem::ErrorNorm(const LocalError& error, const SystemState& y0) const {
  // u's and z's relative to their size where it exceeds 1 (Simbody's
  // calcRelativeScaling with unit weights)
  LocalError::Vector u = error.u;
  for (int i = 0; i < std::min<int>(error.u_size, kNumCoords); ++i) u(i) /= std::max(1.0, std::abs(y0.v(i)));
  const double z = error.z_size > 0 ? error.z / std::max(1.0, std::abs(y0.z)) : 0.0;
  return std::max({Rms(error.q, error.q_size), Rms(u, error.u_size), z});
}

}  // namespace walkers
