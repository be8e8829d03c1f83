#include "dynamics/jacobian.h"

#include <cmath>

namespace walkers {
namespace {

// d(J^T F) for a force F(q, v) applied at point p
void AddForceDerivatives(const PointKinematics& p, const Vec2& F, const Jac2x9& dF_dq, const Jac2x9& dF_dv,
                         Mat9* dG_dq, Mat9* dG_dv) {
  // the link vectors turn with their angles: d perp(r_k) / d angle_k = -r_k
  for (int k = 0; k < p.num_links; ++k) {
    const PointKinematics::Link& link = p.links[k];
    dG_dq->noalias() += (-link.r.dot(F)) * link.body->j.transpose() * link.body->j;
  }
  dG_dq->noalias() += p.J.transpose() * dF_dq;
  dG_dv->noalias() += p.J.transpose() * dF_dv;
}

// gravity and inertia of a point mass at fixed a: F = m (g - J a - a_bias)
void AddPointMassDerivatives(double m, double gravity, const PointKinematics& p, const Vec9& a, Mat9* dG_dq,
                             Mat9* dG_dv) {
  const Vec2 F = m * (Vec2(0.0, -gravity) - p.J * a - p.a_bias);
  Jac2x9 dF_dq = Jac2x9::Zero(), dF_dv = Jac2x9::Zero();
  for (int k = 0; k < p.num_links; ++k) {
    const PointKinematics::Link& link = p.links[k];
    const double w = link.body->rate;
    // d(J a)/dq = sum -r_k (j_k a) j_k;  d(a_bias)/dq = sum -perp(r_k) w_k^2 j_k
    dF_dq.noalias() += m * (link.r * link.body->j.dot(a) + Perp(link.r) * (w * w)) * link.body->j;
    // d(a_bias)/dv = sum -2 r_k w_k j_k
    dF_dv.noalias() += (2.0 * m * w) * link.r * link.body->j;
  }
  AddForceDerivatives(p, F, dF_dq, dF_dv, dG_dq, dG_dv);
}

// a contact force F(depth, depth_rate, slip) on a point; the chain rule
// through the three contact variables, given their own derivatives
void AddContactDerivatives(const ContactParameters& c, const PointKinematics& p, double depth, double depth_rate,
                           double slip, const Row9& ddepth_dq, const Row9& drate_dq, const Row9& drate_dv,
                           const Row9& dslip_dq, const Row9& dslip_dv, Mat9* dG_dq, Mat9* dG_dv,
                           Jac2x9* dF_dq_out = nullptr, Jac2x9* dF_dv_out = nullptr) {
  const Vec2 F = GroundForce(c, depth, depth_rate, slip);
  const Eigen::Matrix<double, 2, 3> D = GroundForceDerivatives(c, depth, depth_rate, slip);
  const Jac2x9 dF_dq = D.col(0) * ddepth_dq + D.col(1) * drate_dq + D.col(2) * dslip_dq;
  const Jac2x9 dF_dv = D.col(1) * drate_dv + D.col(2) * dslip_dv;
  AddForceDerivatives(p, F, dF_dq, dF_dv, dG_dq, dG_dv);
  if (dF_dq_out) *dF_dq_out = dF_dq;
  if (dF_dv_out) *dF_dv_out = dF_dv;
}

void AddGroundContactDerivatives(const Model& model, const Kinematics& kin, Mat9* dG_dq, Mat9* dG_dv) {
  const ContactParameters& c = model.contact;
  const auto carriers = ContactCarriers(model, kin);
  for (int i = 0; i < kNumContactPoints; ++i) {
    const ContactCarrier& carrier = carriers[i];
    if (carrier.base->p.y() + carrier.r.y() >= 0.0) continue;  // above the ground
    if (!IsKneeCircle(i)) {
      // a box corner: a material point of its box
      const PointKinematics p = OffsetPoint(*carrier.base, *carrier.body, carrier.r);
      const Jac2x9 dv_dq = PointVelocityJacobian(p);
      AddContactDerivatives(c, p, -p.p.y(), -p.v.y(), p.v.x(), -p.J.row(1), -dv_dq.row(1), -p.J.row(1),
                            dv_dq.row(0), p.J.row(0), dG_dq, dG_dv);
      continue;
    }
    // a knee circle: the force acts at the knee, and friction also turns the
    // femur by R F_t (the offset stays vertical: it does not turn)
    const PointKinematics& knee = *carrier.base;
    const AngleKinematics& femur = *carrier.body;
    const double radius = -carrier.r.y();
    const Jac2x9 dv_dq = PointVelocityJacobian(knee);
    const Row9 dslip_dv = knee.J.row(0) + radius * femur.j;
    Jac2x9 dF_dq, dF_dv;
    AddContactDerivatives(c, knee, radius - knee.p.y(), -knee.v.y(), knee.v.x() + radius * femur.rate,
                          -knee.J.row(1), -dv_dq.row(1), -knee.J.row(1), dv_dq.row(0), dslip_dv, dG_dq, dG_dv,
                          &dF_dq, &dF_dv);
    dG_dq->noalias() += radius * femur.j.transpose() * dF_dq.row(0);
    dG_dv->noalias() += radius * femur.j.transpose() * dF_dv.row(0);
  }
}

void AddWeldDerivatives(const Model& model, const Kinematics& kin, const Welds& welds, Mat9* dG_dq, Mat9* dG_dv) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    const LegKinematics& l = kin.legs[leg];
    const Vec2 F = -model.weld.stiffness * (l.ankle.p - welds[leg].anchor) - model.weld_damping * l.ankle.v;
    const Jac2x9 dF_dq = -model.weld.stiffness * l.ankle.J - model.weld_damping * PointVelocityJacobian(l.ankle);
    const Jac2x9 dF_dv = -model.weld_damping * l.ankle.J;
    AddForceDerivatives(l.ankle, F, dF_dq, dF_dv, dG_dq, dG_dv);
    // the torque on the foot angle: its row j is constant
    dG_dq->noalias() -= model.weld.angular_stiffness * l.foot.j.transpose() * l.foot.j;
    dG_dv->noalias() -= model.weld_angular_damping * l.foot.j.transpose() * l.foot.j;
  }
}

// d(torque)/d(angle) and d(torque)/d(rate) of JointStopTorque
Eigen::Vector2d JointStopDerivatives(const JointStop& stop, double angle, double rate) {
  if (angle > stop.limit) {
    const double s = 1.0 + stop.damping * rate;
    if (s <= 0.0) return Eigen::Vector2d::Zero();
    return Eigen::Vector2d(-stop.stiffness * s, -stop.stiffness * (angle - stop.limit) * stop.damping);
  }
  if (angle < -stop.limit) {
    const double s = 1.0 - stop.damping * rate;
    if (s <= 0.0) return Eigen::Vector2d::Zero();
    return Eigen::Vector2d(-stop.stiffness * s, -stop.stiffness * (-stop.limit - angle) * stop.damping);
  }
  return Eigen::Vector2d::Zero();
}

}  // namespace

Jac2x9 PointVelocityJacobian(const PointKinematics& p) {
  Jac2x9 dv_dq = Jac2x9::Zero();
  for (int k = 0; k < p.num_links; ++k) {
    dv_dq.noalias() -= (p.links[k].body->rate * p.links[k].r) * p.links[k].body->j;
  }
  return dv_dq;
}

Eigen::Matrix<double, 2, 3> GroundForceDerivatives(const ContactParameters& c, double depth, double depth_rate,
                                                   double slip) {
  Eigen::Matrix<double, 2, 3> D = Eigen::Matrix<double, 2, 3>::Zero();
  if (depth <= 0.0) return D;
  const double damping = 1.0 + c.dissipation * depth_rate;
  const double sqrt_depth = std::sqrt(depth);
  // normal: k d^1.5 max(0, 1 + c d')
  double dn_ddepth = 0.0, dn_drate = 0.0;
  if (damping > 0.0) {
    dn_ddepth = 1.5 * c.stiffness * sqrt_depth * damping;
    dn_drate = c.stiffness * depth * sqrt_depth * c.dissipation;
  }
  const double normal = c.stiffness * depth * sqrt_depth * std::max(0.0, damping);
  // tangential: -F_n phi(s), phi = mu tanh(s / s0) + mu_v s
  const double th = std::tanh(slip / c.slip_velocity);
  const double phi = c.friction * th + c.viscous_friction * slip;
  const double dphi = c.friction * (1.0 - th * th) / c.slip_velocity + c.viscous_friction;
  D << -phi * dn_ddepth, -phi * dn_drate, -normal * dphi,
       dn_ddepth,        dn_drate,        0.0;
  return D;
}

bool AccelerationJacobian(const Model& model, const Inputs& inputs, const Vec9& q, const Vec9& v, Workspace* ws,
                          Mat9* da_dq, Mat9* da_dv) {
  Vec9 a;
  if (!ForwardDynamics(model, inputs, q, v, ws, &a)) return false;
  const Kinematics& kin = ws->kin;
  Mat9 dR_dq = Mat9::Zero(), dR_dv = Mat9::Zero();

  // gravity, velocity products and inertia of the point masses (the
  // rotational inertias' terms are constant)
  const double g = model.options.gravity;
  AddPointMassDerivatives(model.trunk_mass, g, kin.trunk, a, &dR_dq, &dR_dv);
  AddPointMassDerivatives(model.hips_mass, g, kin.hip, a, &dR_dq, &dR_dv);
  for (const LegKinematics& l : kin.legs) {
    AddPointMassDerivatives(model.knee_mass, g, l.knee, a, &dR_dq, &dR_dv);
    AddPointMassDerivatives(model.ankle_mass, g, l.ankle, a, &dR_dq, &dR_dv);
  }

  if (model.options.contact) AddGroundContactDerivatives(model, kin, &dR_dq, &dR_dv);
  AddWeldDerivatives(model, kin, inputs.welds, &dR_dq, &dR_dv);
  if (model.options.joint_stops) {
    for (int leg = 0; leg < kNumLegs; ++leg) {
      for (int joint = 0; joint < kNumJoints; ++joint) {
        const int i = JointIndex(leg, joint);
        const Eigen::Vector2d d = JointStopDerivatives(model.stops[joint], q(i), v(i));
        dR_dq(i, i) += d(0);
        dR_dv(i, i) += d(1);
      }
    }
  }

  // a locked coordinate does not accelerate: its rows vanish (ws->llt holds
  // the correspondingly masked mass matrix)
  for (int i = 0; i < kNumCoords; ++i) {
    if (!model.options.locked[i]) continue;
    dR_dq.row(i).setZero();
    dR_dv.row(i).setZero();
  }
  *da_dq = ws->llt.solve(dR_dq);
  *da_dv = ws->llt.solve(dR_dv);
  return da_dq->allFinite() && da_dv->allFinite();
}

}  // namespace walkers
