// What an integrator integrates, apart from how: a mechanical system of
// kNumCoords coordinates with the state y = (q, v), q' = v and
// v' = a(q, v) under whatever the system holds at the time (the walker's
// held joint torques and welds). A caller that changes what the system holds
// marks the jump on the integrator (TimeStepper::MarkJump).
//
// Beyond the accelerations, a method may use:
// - their Jacobian (CVODE's Newton iteration);
// - functions whose zeros mark where the right-hand side switches (CVODE's
//   root finding, when asked to locate the switches);
// - Simbody's view of the system (RK-Merson, integration/rk_merson.h): an
//   auxiliary variable z with z' = w(q, v) that only the error control sees,
//   the local error measured in the system's own coordinates, and exact
//   constraints that a step's end is projected onto, its error estimate with it.
// The defaults describe a system of free coordinates without constraints, as
// Simbody would measure one whose coordinates are all its q's and u's.
#pragma once

#include <Eigen/Core>

#include "dynamics/coords.h"

namespace walkers {

// y = (q, v) and the auxiliary variable z.
struct SystemState : State {
  double z = 0;
};

// A step's estimated local error in the system's own coordinates: Simbody's
// q's (position-level, in the units of the u's they move with), u's and z's.
// Only the first q_size, u_size and z_size entries count; their norms are
// RMS norms over those sizes, so entries that are always zero still count.
struct LocalError {
  static constexpr int kMaxSize = 32;
  using Vector = Eigen::Matrix<double, kMaxSize, 1>;
  Vector q = Vector::Zero();  // already weighted: 1 is a unit change
  Vector u = Vector::Zero();  // unweighted; ErrorNorm weighs them
  double z = 0;               // unweighted
  int q_size = 0, u_size = 0, z_size = 0;
};

// How a projection onto the constraints ended (Simbody's ProjectResults).
enum class Projection {
  kUnchanged,  // the constraints held within the tolerance already
  kProjected,  // moved onto them
  kFailed,     // beyond the limit, or the iteration did not converge
};

class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  // a = q'' at (q, v); false when it is not finite.
  virtual bool Accelerations(const Vec9& q, const Vec9& v, Vec9* a) = 0;

  // da/dq and da/dv at (q, v), for methods that use a Jacobian; false when
  // not finite or when the system has none.
  virtual bool AccelerationJacobian(const Vec9& q, const Vec9& v, Mat9* da_dq, Mat9* da_dv);

  // A coordinate held fixed: its rate stays 0.
  virtual bool Locked(int /*coordinate*/) const { return false; }

  // Functions of the state that cross zero where the right-hand side switches
  // law (a contact starting or ending): continuous, of one sign between
  // switches. An integrator that locates events (IntegratorSettings::
  // locate_contact_switches) finds their zeros and restarts there. By
  // default there are none.
  virtual int NumSwitchFunctions() const { return 0; }
  // g[0..NumSwitchFunctions()) at (q, v)
  virtual void SwitchFunctions(const Vec9& /*q*/, const Vec9& /*v*/, double* /*g*/) {}

  // The accelerations and z' together; by default z' = 0.
  virtual bool Derivatives(const Vec9& q, const Vec9& v, Vec9* a, double* z_rate);

  // The local error of y1 estimated from the embedded solution y_check as
  // factor * |y1 - y_check|, component by component in the system's own
  // coordinates. By default those are q, v and z themselves.
  virtual LocalError EstimateError(const SystemState& y1, const SystemState& y_check, double factor) const;

  // Simbody's error norm (IntegratorRep::calcErrorNorm): the largest of the
  // RMS norms of the q, u and z errors; each u and z error relative to
  // max(1, |value|) at the step's start y0.
  virtual double ErrorNorm(const LocalError& error, const SystemState& y0) const;

  // Simbody's projectQ and projectU onto the exact constraints at the
  // tolerance (RMS of the constraint errors), failing beyond `limit`; the
  // error estimate is projected with the state. By default there are no
  // constraints.
  virtual Projection ProjectPositions(SystemState* /*y*/, LocalError* /*error*/, double /*tolerance*/,
                                      double /*limit*/) {
    return Projection::kUnchanged;
  }
  virtual Projection ProjectVelocities(SystemState* /*y*/, LocalError* /*error*/, double /*tolerance*/,
                                       double /*limit*/) {
    return Projection::kUnchanged;
  }
};

}  // namespace walkers
