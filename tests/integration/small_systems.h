// Small analytic systems for the integrators' tests, apart from the walker:
// each moves its first coordinate alone.
#pragma once

#include <cmath>
#include <limits>

#include "integration/system.h"

namespace walkers {

// q'' = -q
struct HarmonicOscillator : SecondOrderSystem {
  bool Accelerations(const Vec9& q, const Vec9& /*v*/, Vec9* a) override {
    a->setZero();
    (*a)(0) = -q(0);
    return true;
  }
};

// q'' = -sin q (g = L = 1)
struct Pendulum : SecondOrderSystem {
  bool Accelerations(const Vec9& q, const Vec9& /*v*/, Vec9* a) override {
    a->setZero();
    (*a)(0) = -std::sin(q(0));
    return true;
  }
};

// q'' = -1e6 q - 100 q': stiff and damped
struct StiffSpring : SecondOrderSystem {
  bool Accelerations(const Vec9& q, const Vec9& v, Vec9* a) override {
    a->setZero();
    (*a)(0) = -1e6 * q(0) - 100.0 * v(0);
    return true;
  }
};

// q'' = u, a force the caller holds and changes
struct HeldForce : SecondOrderSystem {
  double force = 0;
  bool Accelerations(const Vec9& /*q*/, const Vec9& /*v*/, Vec9* a) override {
    a->setZero();
    (*a)(0) = force;
    return true;
  }
};

// A unit mass under unit gravity over a ground spring: q'' = -1 above the
// ground, -1 - k q below it (q < 0); the law switches at q = 0, which its one
// switch function, the height q, marks. Dropped from rest at q = 1/2 it lands
// at t = 1 with q' = -1, and leaves the spring with q' = +1 (no damping)
// at LiftOffTime().
struct BallOnSpringGround : SecondOrderSystem {
  double stiffness = 1e4;  // k
  bool Accelerations(const Vec9& q, const Vec9& /*v*/, Vec9* a) override {
    a->setZero();
    (*a)(0) = q(0) < 0.0 ? -1.0 - stiffness * q(0) : -1.0;
    return true;
  }
  int NumSwitchFunctions() const override { return 1; }
  void SwitchFunctions(const Vec9& q, const Vec9& /*v*/, double* g) override { g[0] = q(0); }
  // In the spring, s = t - 1, w = k^(1/2): q = g/w^2 (cos ws - 1) - sin(ws)/w
  // with g = 1, which is zero again where tan(ws/2) = -w/g.
  double LiftOffTime() const {
    const double w = std::sqrt(stiffness);
    return 1.0 + (M_PI + 2.0 * std::atan(1.0 / w)) / w;
  }
};

// q'' = 1 at rest at the origin, and not finite anywhere else: every step fails
struct FiniteOnlyAtRest : SecondOrderSystem {
  bool Accelerations(const Vec9& q, const Vec9& v, Vec9* a) override {
    a->setZero();
    if (q.isZero() && v.isZero()) {
      (*a)(0) = 1.0;
      return true;
    }
    (*a)(0) = std::numeric_limits<double>::quiet_NaN();
    return false;
  }
};

}  // namespace walkers
