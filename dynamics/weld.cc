#include "dynamics/weld.h"

#include "dynamics/kinematics.h"
#include "dynamics/model.h"

namespace walkers {

bool SameWeld(const Weld& a, const Weld& b) {
  return a.active == b.active && (!a.active || (a.anchor == b.anchor && a.angle == b.angle));
}

Vec2 WeldedFootPoint(const Model& model) { return Vec2(0.0, -model.body.half_foot_y + model.weld.depth); }

Weld FlatWeldAt(const Model& model, double x) {
  Weld w;
  w.active = true;
  // the welded point at ground level with the foot flat
  w.anchor = Vec2(x, -WeldedFootPoint(model).y());
  w.angle = 0.0;
  return w;
}

Weld PlantFoot(const Model& model, const State& state, int leg) {
  Kinematics kin;
  ComputeKinematics(model, state.q, state.v, &kin);
  return FlatWeldAt(model, kin.legs[leg].ankle.p.x());
}

int ActiveWeldRows(const Welds& welds) {
  int rows = 0;
  for (const Weld& w : welds) rows += w.active ? kWeldRowsPerFoot : 0;
  return rows;
}

void WeldConstraints(const Model& model, const Kinematics& kin, const Welds& welds, WeldJacobian* G, WeldVector* b) {
  const double a = model.weld.stabilization;
  int row = 0;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const Weld& w = welds[leg];
    if (!w.active) continue;
    const LegKinematics& l = kin.legs[leg];
    // the foot centre: J q'' + a_bias = -2a v - a^2 (p - anchor)
    G->middleRows<2>(row) = l.ankle.J;
    b->segment<2>(row) = -l.ankle.a_bias - 2.0 * a * l.ankle.v - a * a * (l.ankle.p - w.anchor);
    // the foot angle: j q'' = -2a w - a^2 (angle - held)
    G->row(row + 2) = l.foot.j;
    (*b)(row + 2) = -2.0 * a * l.foot.rate - a * a * (l.foot.angle - w.angle);
    row += kWeldRowsPerFoot;
  }
  for (int i = 0; i < kNumCoords; ++i) {
    if (model.options.locked[i]) G->col(i).head(row).setZero();
  }
}

void WeldConstraintDerivatives(const Model& model, const Kinematics& kin, const Welds& welds, const Vec9& qdd,
                               WeldJacobian* C_q, WeldJacobian* C_v) {
  const double s = model.weld.stabilization;
  int row = 0;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    const LegKinematics& l = kin.legs[leg];
    // the foot centre: d(J a + a_bias)/dq = -sum (r_k (j_k a) + perp(r_k) w_k^2) j_k,
    // d(a_bias)/dv = -sum 2 w_k r_k j_k, d(J v)/dq = PointVelocityJacobian
    Jac2x9 d_acc_dq = Jac2x9::Zero(), d_bias_dv = Jac2x9::Zero();
    for (int k = 0; k < l.ankle.num_links; ++k) {
      const PointKinematics::Link& link = l.ankle.links[k];
      const double w = link.body->rate;
      d_acc_dq.noalias() -= (link.r * link.body->j.dot(qdd) + Perp(link.r) * (w * w)) * link.body->j;
      d_bias_dv.noalias() -= (2.0 * w) * link.r * link.body->j;
    }
    C_q->middleRows<2>(row) = d_acc_dq + 2.0 * s * PointVelocityJacobian(l.ankle) + s * s * l.ankle.J;
    C_v->middleRows<2>(row) = d_bias_dv + 2.0 * s * l.ankle.J;
    // the foot angle: its row is constant
    C_q->row(row + 2) = s * s * l.foot.j;
    C_v->row(row + 2) = 2.0 * s * l.foot.j;
    row += kWeldRowsPerFoot;
  }
  for (int i = 0; i < kNumCoords; ++i) {
    if (!model.options.locked[i]) continue;
    C_q->col(i).head(row).setZero();
    C_v->col(i).head(row).setZero();
  }
}

void AddWeldForceDerivatives(const Kinematics& kin, const Welds& welds, const WeldVector& lambda, Mat9* dR_dq) {
  int row = 0;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    if (!welds[leg].active) continue;
    // the foot centre's part turns with the links of the ankle point (the angle's row is constant)
    const PointKinematics& ankle = kin.legs[leg].ankle;
    const Vec2 F = lambda.segment<2>(row);
    for (int k = 0; k < ankle.num_links; ++k) {
      const PointKinematics::Link& link = ankle.links[k];
      dR_dq->noalias() += (-link.r.dot(F)) * link.body->j.transpose() * link.body->j;
    }
    row += kWeldRowsPerFoot;
  }
}

}  // namespace walkers
