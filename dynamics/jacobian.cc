#include "dynamics/jacobian.h"

#include <array>
#include <cmath>

namespace walkers {
namespace {

// Every point and angle of the tree depends on at most six coordinates, the
// trunk's (x, y, pitch) and its leg's (hip, knee, ankle): ColumnsOf(its leg).
// Each force's derivative terms are assembled in that 6x6 block and scattered
// into the 9x9 matrices: the dense products would mostly multiply zeros.
using Row6 = Eigen::Matrix<double, 1, 6>;
using Jac2x6 = Eigen::Matrix<double, 2, 6>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

struct Block {
  TreeColumns cols;
  explicit Block(int leg) : cols(ColumnsOf(leg)) {}
  Row6 Gather(const Row9& r) const {
    Row6 out;
    for (int i = 0; i < 6; ++i) out(i) = r(cols[i]);
    return out;
  }
  Jac2x6 Gather(const Jac2x9& J) const {
    Jac2x6 out;
    for (int i = 0; i < 6; ++i) out.col(i) = J.col(cols[i]);
    return out;
  }
  void ScatterAdd(const Mat6& local, Mat9* M) const {
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) (*M)(cols[i], cols[j]) += local(i, j);
    }
  }
};

// d(J^T F) for a force F(q, v) applied at point p, given dF/dq and dF/dv in
// the point's block
void AddForceDerivatives(const PointKinematics& p, const Block& block, const Vec2& F, const Jac2x6& dF_dq,
                         const Jac2x6& dF_dv, Mat6* dG_dq, Mat6* dG_dv) {
  // the link vectors turn with their angles: d perp(r_k) / d angle_k = -r_k
  for (int k = 0; k < p.num_links; ++k) {
    const PointKinematics::Link& link = p.links[k];
    const Row6 j = block.Gather(link.body->j);
    dG_dq->noalias() += (-link.r.dot(F)) * j.transpose() * j;
  }
  const Jac2x6 J = block.Gather(p.J);
  dG_dq->noalias() += J.transpose() * dF_dq;
  dG_dv->noalias() += J.transpose() * dF_dv;
}

// d(J v)/dq in the point's block
Jac2x6 LocalVelocityJacobian(const PointKinematics& p, const Block& block) {
  return block.Gather(PointVelocityJacobian(p));
}

// gravity and inertia of a point mass at fixed a: F = m (g - J a - a_bias)
void AddPointMassDerivatives(double m, double gravity, const PointKinematics& p, const Vec9& a, Mat9* dR_dq,
                             Mat9* dR_dv) {
  const Block block(p.leg);
  const Vec2 F = m * (Vec2(0.0, -gravity) - p.J * a - p.a_bias);
  Jac2x6 dF_dq = Jac2x6::Zero(), dF_dv = Jac2x6::Zero();
  for (int k = 0; k < p.num_links; ++k) {
    const PointKinematics::Link& link = p.links[k];
    const double w = link.body->rate;
    const Row6 j = block.Gather(link.body->j);
    // d(J a)/dq = sum -r_k (j_k a) j_k;  d(a_bias)/dq = sum -perp(r_k) w_k^2 j_k
    dF_dq.noalias() += m * (link.r * link.body->j.dot(a) + Perp(link.r) * (w * w)) * j;
    // d(a_bias)/dv = sum -2 r_k w_k j_k
    dF_dv.noalias() += (2.0 * m * w) * link.r * j;
  }
  Mat6 dG_dq = Mat6::Zero(), dG_dv = Mat6::Zero();
  AddForceDerivatives(p, block, F, dF_dq, dF_dv, &dG_dq, &dG_dv);
  block.ScatterAdd(dG_dq, dR_dq);
  block.ScatterAdd(dG_dv, dR_dv);
}

// a contact force F(depth, depth_rate, slip) on a point: the chain rule
// through the three contact variables, given their own derivatives
Jac2x6 ContactForceDerivative(const Eigen::Matrix<double, 2, 3>& D, const Row6& ddepth, const Row6& drate,
                              const Row6& dslip) {
  return D.col(0) * ddepth + D.col(1) * drate + D.col(2) * dslip;
}

void AddGroundContactDerivatives(const Model& model, const Kinematics& kin, Mat9* dR_dq, Mat9* dR_dv) {
  const ContactParameters& c = model.contact;
  const auto carriers = ContactCarriers(model, kin);
  for (int i = 0; i < kNumContactPoints; ++i) {
    const ContactCarrier& carrier = carriers[i];
    if (carrier.base->p.y() + carrier.r.y() >= 0.0) continue;  // above the ground
    Mat6 dG_dq = Mat6::Zero(), dG_dv = Mat6::Zero();
    if (!IsKneeCircle(i)) {
      // a box corner: a material point of its box
      const PointKinematics p = OffsetPoint(*carrier.base, *carrier.body, carrier.r);
      const Block block(p.leg);
      const Jac2x6 J = block.Gather(p.J), dv_dq = LocalVelocityJacobian(p, block);
      const double depth = -p.p.y(), rate = -p.v.y(), slip = p.v.x();
      const Eigen::Matrix<double, 2, 3> D = GroundForceDerivatives(c, depth, rate, slip);
      const Jac2x6 dF_dq = ContactForceDerivative(D, -J.row(1), -dv_dq.row(1), dv_dq.row(0));
      const Jac2x6 dF_dv = ContactForceDerivative(D, Row6::Zero(), -J.row(1), J.row(0));
      AddForceDerivatives(p, block, GroundForce(c, depth, rate, slip), dF_dq, dF_dv, &dG_dq, &dG_dv);
      block.ScatterAdd(dG_dq, dR_dq);
      block.ScatterAdd(dG_dv, dR_dv);
      continue;
    }
    // a knee circle: the force acts at the knee, and friction also turns the
    // femur by R F_t (the offset stays vertical: it does not turn)
    const PointKinematics& knee = *carrier.base;
    const Block block(knee.leg);
    const Row6 femur = block.Gather(carrier.body->j);
    const double radius = -carrier.r.y();
    const Jac2x6 J = block.Gather(knee.J), dv_dq = LocalVelocityJacobian(knee, block);
    const double depth = radius - knee.p.y(), rate = -knee.v.y(), slip = knee.v.x() + radius * carrier.body->rate;
    const Eigen::Matrix<double, 2, 3> D = GroundForceDerivatives(c, depth, rate, slip);
    const Jac2x6 dF_dq = ContactForceDerivative(D, -J.row(1), -dv_dq.row(1), dv_dq.row(0));
    const Jac2x6 dF_dv = ContactForceDerivative(D, Row6::Zero(), -J.row(1), J.row(0) + radius * femur);
    AddForceDerivatives(knee, block, GroundForce(c, depth, rate, slip), dF_dq, dF_dv, &dG_dq, &dG_dv);
    dG_dq.noalias() += radius * femur.transpose() * dF_dq.row(0);
    dG_dv.noalias() += radius * femur.transpose() * dF_dv.row(0);
    block.ScatterAdd(dG_dq, dR_dq);
    block.ScatterAdd(dG_dv, dR_dv);
  }
}

void AddWeldDerivatives(const Model& model, const Kinematics& kin, const Welds& welds, Mat9* dR_dq, Mat9* dR_dv) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    const LegKinematics& l = kin.legs[leg];
    const Block block(leg);
    const Jac2x6 J = block.Gather(l.ankle.J);
    const Vec2 F = -model.weld.stiffness * (l.ankle.p - welds[leg].anchor) - model.weld_damping * l.ankle.v;
    const Jac2x6 dF_dq = -model.weld.stiffness * J - model.weld_damping * LocalVelocityJacobian(l.ankle, block);
    const Jac2x6 dF_dv = -model.weld_damping * J;
    Mat6 dG_dq = Mat6::Zero(), dG_dv = Mat6::Zero();
    AddForceDerivatives(l.ankle, block, F, dF_dq, dF_dv, &dG_dq, &dG_dv);
    // the torque on the foot angle: its row j is constant
    const Row6 foot = block.Gather(l.foot.j);
    dG_dq.noalias() -= model.weld.angular_stiffness * foot.transpose() * foot;
    dG_dv.noalias() -= model.weld_angular_damping * foot.transpose() * foot;
    block.ScatterAdd(dG_dq, dR_dq);
    block.ScatterAdd(dG_dv, dR_dv);
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

  // a locked coordinate does not accelerate: its rows vanish (ws->mass_ldlt
  // holds the correspondingly masked mass matrix)
  for (int i = 0; i < kNumCoords; ++i) {
    if (!model.options.locked[i]) continue;
    dR_dq.row(i).setZero();
    dR_dv.row(i).setZero();
  }
  *da_dq = dR_dq;
  *da_dv = dR_dv;
  ws->mass_ldlt.SolveInPlace(da_dq);
  ws->mass_ldlt.SolveInPlace(da_dv);
  return da_dq->allFinite() && da_dv->allFinite();
}

}  // namespace walkers
