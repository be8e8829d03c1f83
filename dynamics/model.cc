#include "dynamics/model.h"

#include <cmath>

namespace walkers {
namespace {

// 2 a b / (a + b), 0 if either is 0 (Simbody's combination of friction coefficients)
double HarmonicMean(double a, double b) { return a * b == 0.0 ? 0.0 : 2.0 * a * b / (a + b); }

FrictionLaw CombineFriction(const ContactMaterial& a, const ContactMaterial& b, double transition) {
  return {HarmonicMean(a.static_friction, b.static_friction), HarmonicMean(a.dynamic_friction, b.dynamic_friction),
          HarmonicMean(a.viscous_friction, b.viscous_friction), transition};
}

// springs per unit area k/h of the mesh and the other surface in series (a
// surface that is not a mesh takes the mesh's thickness)
FoundationLaw CombineFoundation(const ContactMaterial& mesh, const ContactMaterial& other, double thickness,
                                double transition) {
  const double k_mesh = mesh.stiffness / thickness, k_other = other.stiffness / thickness;
  const double share = k_other / (k_mesh + k_other);  // of the deformation, taken by the mesh
  FoundationLaw law;
  law.stiffness = k_mesh * share;
  law.dissipation = mesh.dissipation * share + other.dissipation * (1.0 - share);
  law.squish = share;
  law.friction = CombineFriction(mesh, other, transition);
  return law;
}

// Hertz: f = 4/3 sqrt(R) k^1.5 x^1.5 with k the two k^(2/3) in series
HertzLaw CombineHertz(const ContactMaterial& sphere, const ContactMaterial& ground, double radius,
                      double transition) {
  const double k_sphere = std::cbrt(sphere.stiffness * sphere.stiffness);
  const double k_ground = std::cbrt(ground.stiffness * ground.stiffness);
  const double share = k_ground / (k_ground + k_sphere);  // of the deformation, taken by the sphere
  const double k = k_sphere * share;
  HertzLaw law;
  law.stiffness = 4.0 / 3.0 * std::sqrt(radius) * k * std::sqrt(k);
  law.dissipation = sphere.dissipation * share + ground.dissipation * (1.0 - share);
  law.squish = share;
  law.friction = CombineFriction(sphere, ground, transition);
  return law;
}

}  // namespace

ContactLaws CombineMaterials(const ContactParameters& c) {
  ContactLaws laws;
  laws.mesh_ground = CombineFoundation(c.surface, c.surface, c.mesh_thickness, c.transition_velocity);
  laws.mesh_mesh = CombineFoundation(c.surface, c.surface, c.mesh_thickness, c.transition_velocity);
  laws.mesh_knee = CombineFoundation(c.surface, c.knee, c.mesh_thickness, c.transition_velocity);
  laws.knee_ground = CombineHertz(c.knee, c.surface, c.knee_radius, c.transition_velocity);
  return laws;
}

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

  // the original's soft joint stops (docs/model.md, "Joint stops")
  m.stops[kHip] = {M_PI / 4.0, 2.0, 5.0};
  m.stops[kKnee] = {M_PI / 3.0, 0.2, 50.0};
  m.stops[kAnkle] = {M_PI / 4.0, 2.0, 50.0};

  // contact laws and the surfaces' spring sites
  m.laws = CombineMaterials(contact);
  m.sites = BuildContactSites(Vec3(hx, hy, hz), Vec3(fx, fy, fz), contact.leg_z, contact.knee_radius,
                              contact.mesh_resolution);

  return m;
}

}  // namespace walkers
