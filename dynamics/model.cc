#include "dynamics/model.h"

#include <cmath>

namespace walkers {

Model BuildModel(const BodyParameters& body, const ModelOptions& options,
                 const ContactParameters& contact, const WeldParameters& weld) {
  Model m;
  m.body = body;
  m.options = options;
  m.contact = contact;
  m.weld = weld;

  const double hx = body.half_body_x, hy = body.half_body_y, hz = body.half_body_z;
  const double fx = body.half_foot_x, fy = body.half_foot_y, fz = body.half_foot_z;

  // boxes of density 1180
  m.trunk_mass = 8.0 * hx * hy * hz * kBodyDensity;
  m.foot_mass = 8.0 * fx * fy * fz * kBodyDensity;

  // trunk: the box's own pitch inertia, plus at each hip the quirk inertia
  // m_b ((hx^2 + hy^2)/3 + hy^2) of the authors' model, rigid with the trunk
  const double box_inertia = m.trunk_mass * (hx * hx + hy * hy) / 3.0;
  const double hip_quirk = m.trunk_mass * ((hx * hx + hy * hy) / 3.0 + hy * hy);
  m.trunk_inertia = box_inertia + 2.0 * hip_quirk;
  m.hips_mass = 2.0 * body.hip_mass;

  // femur: the knee's sphere (radius 0.05) inertia; tibia: the foot's inertia (quirk)
  m.knee_mass = body.knee_mass;
  m.femur_inertia = body.knee_mass * 0.4 * 0.05 * 0.05;
  m.foot_inertia = m.foot_mass * (fx * fx + fy * fy) / 3.0;
  m.tibia_inertia = m.foot_inertia;

  // the ankle point carries the ankle mass and the foot box (ankle at its centre)
  m.ankle_mass = body.ankle_mass + m.foot_mass;
  m.total_mass = m.trunk_mass + m.hips_mass + 2.0 * (m.knee_mass + m.ankle_mass);

  // the original's soft joint stops (MODEL.md §2)
  m.stops[kHip] = {M_PI / 4.0, 2.0, 5.0};
  m.stops[kKnee] = {M_PI / 3.0, 0.2, 50.0};
  m.stops[kAnkle] = {M_PI / 4.0, 2.0, 50.0};

  // weld damping: the given damping ratio for the foot (with its ankle mass)
  // alone on the weld's springs, so the weld's own mode dies out in a few ms
  m.weld_damping = 2.0 * weld.damping_ratio * std::sqrt(weld.stiffness * m.ankle_mass);
  m.weld_angular_damping =
      2.0 * weld.damping_ratio * std::sqrt(weld.angular_stiffness * (m.foot_inertia + m.tibia_inertia));
  return m;
}

}  // namespace walkers
