// The walker as a system to integrate (integration/system.h): its forward
// dynamics under the held joint torques and welds (dynamics/), their
// analytic Jacobian for CVODE, and for RK-Merson the authors' model as
// Simbody sees it: the energy its contact dissipates as the auxiliary
// variable z, errors measured in its coordinates, and the welds projected as
// its SimbodyMatterSubsystem projects them (docs/model.md, "RK-Merson").
#pragma once

#include "dynamics/equations_of_motion.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"
#include "integration/free_body_cache.h"
#include "integration/system.h"

namespace walkers {

class WalkerSystem final : public SecondOrderSystem {
 public:
  explicit WalkerSystem(const Model& model);

  const Model& model() const { return model_; }
  const Inputs& inputs() const { return inputs_; }
  // What the walker holds from now on; the caller marks the jump on its integrator.
  void SetInputs(const Inputs& inputs) { inputs_ = inputs; }
  Inputs& inputs() { return inputs_; }

  // ForwardDynamics (dynamics/equations_of_motion.h)
  bool Accelerations(const Vec9& q, const Vec9& v, Vec9* a) override;
  // AccelerationJacobian (dynamics/jacobian.h)
  bool AccelerationJacobian(const Vec9& q, const Vec9& v, Mat9* da_dq, Mat9* da_dv) override;
  bool Locked(int coordinate) const override { return model_.options.locked[coordinate]; }
  // Every contact pair's deepest site (ContactSwitchDepths: a welded foot's
  // ground pair is off) and every joint stop's margin (JointStopMargins).
  int NumSwitchFunctions() const override;
  void SwitchFunctions(const Vec9& q, const Vec9& v, double* g) override;

  // z' = the power the contact's damping and friction dissipate (Simbody's
  // CompliantContactSubsystem with setTrackDissipatedEnergy, as walker.cpp
  // sets it; dynamics/contact.h, ContactReport::dissipation).
  bool Derivatives(const Vec9& q, const Vec9& v, Vec9* a, double* z_rate) override;

  // In the authors' coordinates (dynamics/planting.h): the trunk and feet as
  // free bodies, each orientation a unit quaternion, and the six pins: 27
  // q's, 24 u's and the one z. A turn's error is taken from the quaternion's
  // components as Simbody takes it, and stored as the angle it stands for.
  LocalError EstimateError(const SystemState& y1, const SystemState& y_check, double factor) const override;
  // Simbody's RMS norms over 27 q's (a turn counting half its angle: the
  // quaternion's change), 24 u's (relative to max(1, |u|) at y0) and the z.
  double ErrorNorm(const LocalError& error, const SystemState& y0) const override;
  // The hip welds (exact in our tree, but counted) and the active foot welds.
  Projection ProjectPositions(SystemState* y, LocalError* error, double tolerance, double limit) override;
  Projection ProjectVelocities(SystemState* y, LocalError* error, double tolerance, double limit) override;

 private:
  Model model_;
  Kinematics switch_kinematics_;  // SwitchFunctions' scratch
  Inputs inputs_;
  Workspace workspace_;
  mutable FreeBodyCache free_bodies_;  // the authors' coordinates of the states an attempt revisits
};

}  // namespace walkers
