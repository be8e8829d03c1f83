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
