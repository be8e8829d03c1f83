#include "dynamics/jacobian.h"

#include <array>
#include <cmath>

#include <unsupported/Eigen/AutoDiff>

#include "dynamics/contact_laws.h"

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

// The derivative of the wrench F, torque that a contact pair puts on a body
// about its reference point p (angle a), given their derivatives: J^T F +
// j^T torque changes with q through the links of p and through F and torque.
void AddWrenchDerivatives(const PointKinematics& p, const AngleKinematics& a, const Vec2& F, const Jac2x9& dF_dq,
                          const Jac2x9& dF_dv, const Row9& dT_dq, const Row9& dT_dv, Mat9* dR_dq, Mat9* dR_dv) {
  for (int k = 0; k < p.num_links; ++k) {
    const PointKinematics::Link& link = p.links[k];
    dR_dq->noalias() += (-link.r.dot(F)) * link.body->j.transpose() * link.body->j;
  }
  dR_dq->noalias() += p.J.transpose() * dF_dq + a.j.transpose() * dT_dq;
  dR_dv->noalias() += p.J.transpose() * dF_dv + a.j.transpose() * dT_dv;
}

// Every contact pair by forward-mode automatic differentiation of its law
// (dynamics/contact_laws.h) with respect to the motions of its two bodies,
// (p, angle, v, rate) of a then of b, chained with the kinematics.
using Partials = Eigen::Matrix<double, 12, 1>;
using AD = Eigen::AutoDiffScalar<Partials>;
using contact_laws::BodyMotion;
using contact_laws::ContactBodyKinematics;
using contact_laws::KinematicsOf;

// the body's motion with its six partials seeded from `first`
BodyMotion<AD> SeededMotion(const ContactBodyKinematics& k, int first) {
  BodyMotion<AD> m;
  if (!k.point) {
    m.p = contact_laws::V2<AD>(AD(0.0, Partials::Zero()), AD(0.0, Partials::Zero()));
    m.v = m.p;
    m.angle = AD(0.0, Partials::Zero());
    m.rate = m.angle;
    m.cos = AD(1.0, Partials::Zero());
    m.sin = m.angle;
    return m;
  }
  const auto seed = [&](double value, int i) { return AD(value, Partials::Unit(first + i)); };
  m.p = contact_laws::V2<AD>(seed(k.point->p.x(), 0), seed(k.point->p.y(), 1));
  m.angle = seed(k.angle->angle, 2);
  m.v = contact_laws::V2<AD>(seed(k.point->v.x(), 3), seed(k.point->v.y(), 4));
  m.rate = seed(k.angle->rate, 5);
  // d cos = -sin d angle, d sin = cos d angle
  m.cos = AD(k.angle->c, -k.angle->s * Partials::Unit(first + 2));
  m.sin = AD(k.angle->s, k.angle->c * Partials::Unit(first + 2));
  return m;
}

// d(motion)/dq and d(motion)/dv of a body: (p, angle, v, rate) = (p, angle, J v, j v)
void MotionDerivatives(const ContactBodyKinematics& k, int first, Eigen::Matrix<double, 12, kNumCoords>* dm_dq,
                       Eigen::Matrix<double, 12, kNumCoords>* dm_dv) {
  if (!k.point) return;
  dm_dq->middleRows<2>(first) = k.point->J;
  dm_dq->row(first + 2) = k.angle->j;
  dm_dq->middleRows<2>(first + 3) = PointVelocityJacobian(*k.point);
  dm_dv->middleRows<2>(first + 3) = k.point->J;
  dm_dv->row(first + 5) = k.angle->j;
}

void AddContactDerivatives(const Model& model, const Kinematics& kin, const Welds& welds, Mat9* dR_dq,
                           Mat9* dR_dv) {
  // the pairs apart, found in plain doubles, need no differentiation
  const ContactReports reports = ReportContacts(model, kin);
  for (int pair = 0; pair < kNumContactPairs; ++pair) {
    const ContactPairSpec& spec = ContactPairs()[pair];
    if (!model.options.contact || (spec.self_contact && !model.options.self_contact)) continue;
    if (HeldByWeld(spec, welds) || !reports[pair].touching) continue;
    const ContactBodyKinematics ka = KinematicsOf(kin, spec.a), kb = KinematicsOf(kin, spec.b);
    const contact_laws::PairResult<AD> r =
        contact_laws::PairContact<AD>(model, pair, SeededMotion(ka, 0), SeededMotion(kb, 6));
    if (!r.report.touching) continue;
    Eigen::Matrix<double, 12, kNumCoords> dm_dq = Eigen::Matrix<double, 12, kNumCoords>::Zero();
    Eigen::Matrix<double, 12, kNumCoords> dm_dv = Eigen::Matrix<double, 12, kNumCoords>::Zero();
    MotionDerivatives(ka, 0, &dm_dq, &dm_dv);
    MotionDerivatives(kb, 6, &dm_dq, &dm_dv);
    const auto add = [&](const ContactBodyKinematics& k, const contact_laws::Wrench<AD>& w) {
      if (!k.point) return;
      Eigen::Matrix<double, 3, 12> d;
      d.row(0) = w.force.x().derivatives().transpose();
      d.row(1) = w.force.y().derivatives().transpose();
      d.row(2) = w.torque.derivatives().transpose();
      const Eigen::Matrix<double, 3, kNumCoords> d_dq = d.lazyProduct(dm_dq), d_dv = d.lazyProduct(dm_dv);
      AddWrenchDerivatives(*k.point, *k.angle, Vec2(w.force.x().value(), w.force.y().value()), d_dq.topRows<2>(),
                           d_dv.topRows<2>(), d_dq.row(2), d_dv.row(2), dR_dq, dR_dv);
    };
    add(ka, r.on_a);
    add(kb, r.on_b);
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

// da/dq and da/dv with the welds' constraints on the accelerations held, for their R rows
template <int R>
void ConstrainByWelds(const Model& model, const Welds& welds, const Vec9& a, const Workspace& ws, Mat9* da_dq,
                      Mat9* da_dv) {
  WeldJacobian C_q, C_v;
  WeldConstraintDerivatives(model, ws.kin, welds, a, &C_q, &C_v);
  ws.ApplyWelds<R, kNumCoords>(-C_q.topRows<R>(), da_dq);
  ws.ApplyWelds<R, kNumCoords>(-C_v.topRows<R>(), da_dv);
}

}  // namespace

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

  AddContactDerivatives(model, kin, inputs.welds, &dR_dq, &dR_dv);
  AddWeldForceDerivatives(kin, inputs.welds, ws->lambda, &dR_dq);
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

  // the welds hold: M da = dR + G^T dlambda with G da = -C, so
  // da = M^-1 dR - M^-1 G^T (G M^-1 G^T)^-1 (C + G M^-1 dR)
  if (ws->weld_rows == kWeldRowsPerFoot) {
    ConstrainByWelds<kWeldRowsPerFoot>(model, inputs.welds, a, *ws, da_dq, da_dv);
  } else if (ws->weld_rows == kMaxWeldRows) {
    ConstrainByWelds<kMaxWeldRows>(model, inputs.welds, a, *ws, da_dq, da_dv);
  }
  return da_dq->allFinite() && da_dv->allFinite();
}

}  // namespace walkers
