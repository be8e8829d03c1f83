#include "dynamics/contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/contact_laws.h"

namespace walkers {

using contact_laws::BodyMotion;
using contact_laws::PairResult;
using contact_laws::Wrench;
using contact_laws::ContactBodyKinematics;
using contact_laws::KinematicsOf;

const std::array<ContactPairSpec, kNumContactPairs>& ContactPairs() {
  using B = ContactBody;
  using L = ContactLaw;
  // clang-format off
  static const std::array<ContactPairSpec, kNumContactPairs> pairs = {{
      {"ground-trunk",  B::kGround, B::kTrunk, L::kMeshOnGround,   kLeft,  true,  false},
      {"ground-foot_l", B::kGround, B::kFootL, L::kMeshOnGround,   kLeft,  false, false},
      {"ground-foot_r", B::kGround, B::kFootR, L::kMeshOnGround,   kRight, false, false},
      {"ground-knee_l", B::kGround, B::kKneeL, L::kSphereOnGround, kLeft,  false, false},
      {"ground-knee_r", B::kGround, B::kKneeR, L::kSphereOnGround, kRight, false, false},
      {"trunk-foot_l",  B::kTrunk,  B::kFootL, L::kMeshOnMesh,     kLeft,  true,  true},
      {"trunk-foot_r",  B::kTrunk,  B::kFootR, L::kMeshOnMesh,     kRight, true,  true},
      {"trunk-knee_l",  B::kTrunk,  B::kKneeL, L::kMeshOnSphere,   kLeft,  false, true},
      {"trunk-knee_r",  B::kTrunk,  B::kKneeR, L::kMeshOnSphere,   kRight, false, true},
      {"foot_l-knee_l", B::kFootL,  B::kKneeL, L::kMeshOnSphere,   kLeft,  false, true},
      {"foot_r-knee_r", B::kFootR,  B::kKneeR, L::kMeshOnSphere,   kRight, false, true},
  }};
  // clang-format on
  return pairs;
}

namespace {

constexpr int kNumContactBodies = 6;

BodyMotion<double> MotionOf(const Kinematics& kin, ContactBody body) {
  BodyMotion<double> m;
  const ContactBodyKinematics k = KinematicsOf(kin, body);
  if (!k.point) return m;  // the ground stands still
  m.p = k.point->p;
  m.v = k.point->v;
  m.angle = k.angle->angle;
  m.rate = k.angle->rate;
  m.cos = k.angle->c;
  m.sin = k.angle->s;
  return m;
}

bool PairEnabled(const ModelOptions& options, const ContactPairSpec& spec) {
  return options.contact && (options.self_contact || !spec.self_contact);
}

// every enabled pair's result at the state of kin; with welds, not the pairs
// they hold (HeldByWeld), which are then not computed at all
template <typename Visit>
void ForEachPair(const Model& model, const Kinematics& kin, Visit&& visit, const Welds* welds = nullptr,
                 bool count_dissipation = false) {
  std::array<BodyMotion<double>, kNumContactBodies> motions;
  for (int i = 0; i < kNumContactBodies; ++i) motions[i] = MotionOf(kin, static_cast<ContactBody>(i));
  for (int pair = 0; pair < kNumContactPairs; ++pair) {
    const ContactPairSpec& spec = ContactPairs()[pair];
    if (!PairEnabled(model.options, spec)) continue;
    if (welds && HeldByWeld(spec, *welds)) continue;
    const BodyMotion<double>& a = motions[static_cast<int>(spec.a)];
    const BodyMotion<double>& b = motions[static_cast<int>(spec.b)];
    if (!contact_laws::MayTouch(model, spec, a, b)) continue;
    visit(pair, spec, contact_laws::PairContact<double>(model, pair, a, b, count_dissipation));
  }
}

}  // namespace

double FrictionPerSlip(const FrictionLaw& law, double slip_squared) {
  return contact_laws::FrictionPerSlip<double>(law, slip_squared);
}

ContactReports ReportContacts(const Model& model, const Kinematics& kin) {
  ContactReports reports{};
  ForEachPair(model, kin, [&](int pair, const ContactPairSpec&, const PairResult<double>& r) {
    reports[pair] = r.report;
  });
  return reports;
}

bool HeldByWeld(const ContactPairSpec& pair, const Welds& welds) {
  return pair.a == ContactBody::kGround &&
         ((pair.b == ContactBody::kFootL && welds[kLeft].active) || (pair.b == ContactBody::kFootR && welds[kRight].active));
}

void AddContactForces(const Model& model, const Kinematics& kin, const Welds& welds, Vec9* Q,
                      double* dissipation) {
  // each body's wrench about its reference point, then J^T F + j^T torque
  std::array<Wrench<double>, kNumContactBodies> wrenches{};
  double power = 0.0;
  const auto add = [&](int, const ContactPairSpec& spec, const PairResult<double>& r) {
    power += r.report.dissipation;
    Wrench<double>& a = wrenches[static_cast<int>(spec.a)];
    Wrench<double>& b = wrenches[static_cast<int>(spec.b)];
    a.force += r.on_a.force;
    a.torque += r.on_a.torque;
    b.force += r.on_b.force;
    b.torque += r.on_b.torque;
  };
  ForEachPair(model, kin, add, &welds, dissipation != nullptr);
  if (dissipation) *dissipation = power;
  for (int i = 0; i < kNumContactBodies; ++i) {
    const ContactBodyKinematics k = KinematicsOf(kin, static_cast<ContactBody>(i));
    if (!k.point) continue;
    AddTransposeProduct(*k.point, wrenches[i].force, Q);
    AddTransposeProduct(*k.angle, wrenches[i].torque, Q);
  }
}

double LowestPointDepth(const Model& model, const Kinematics& kin) {
  double deepest = -std::numeric_limits<double>::infinity();
  const auto deepest_site = [&](const GroundMesh& mesh, const PointKinematics& p, const AngleKinematics& a) {
    for (const GroundSite& s : mesh.sites()) deepest = std::max(deepest, -(p.p.y() + Rotate(a, s.p).y()));
  };
  deepest_site(model.sites.trunk_ground, kin.trunk, kin.pitch);
  for (const LegKinematics& l : kin.legs) {
    deepest_site(model.sites.foot_ground, l.ankle, l.foot);
    deepest = std::max(deepest, model.contact.knee_radius - l.knee.p.y());
  }
  return deepest;
}

double MaxGroundPenetration(const Model& model, const Kinematics& kin) {
  return std::max(0.0, LowestPointDepth(model, kin));
}

bool TrunkSupported(const Model& model, const Kinematics& kin) {
  bool supported = false;
  ForEachPair(model, kin, [&](int, const ContactPairSpec& spec, const PairResult<double>& r) {
    supported = supported || (spec.trunk_support && r.report.touching);
  });
  return supported;
}

namespace {

using contact_laws::BoxMargins;
using contact_laws::BoxView;
using contact_laws::GroundView;
using contact_laws::SphereView;

// the deepest of a ground mesh's sites below the ground
double DeepestBelowGround(const GroundMesh& mesh, const BodyMotion<double>& body) {
  const GroundView view(body);
  double deepest = -std::numeric_limits<double>::infinity();
  for (const GroundSite& site : mesh.sites()) deepest = std::max(deepest, view.Depth(site.p));
  return deepest;
}

// the deepest of mesh m's sites inside box o: the smaller of its margins to
// o's x and y faces (MeshInBox's test; the sites lie within o's z extent)
double DeepestInBox(const std::vector<BoxSite>& sites, const BodyMotion<double>& m, const BodyMotion<double>& o,
                    const Vec2& half_o) {
  const BoxView view(m, o);
  double deepest = -std::numeric_limits<double>::infinity();
  for (const BoxSite& site : sites) deepest = std::max(deepest, BoxMargins(half_o, view.Site(site.p)).minCoeff());
  return deepest;
}

// the deepest of mesh m's sites inside the sphere about k's reference point
double DeepestInSphere(const std::vector<SphereSite>& sites, double radius, const BodyMotion<double>& m,
                       const BodyMotion<double>& k) {
  const SphereView view(m, k);
  double deepest = -std::numeric_limits<double>::infinity();
  for (const SphereSite& site : sites) deepest = std::max(deepest, radius - std::sqrt(view.SquaredDistance(site)));
  return deepest;
}

}  // namespace

ContactSwitches ContactSwitchDepths(const Model& model, const Kinematics& kin, const Welds& welds) {
  ContactSwitches depth;
  depth.fill(-1.0);
  std::array<BodyMotion<double>, kNumContactBodies> motions;
  for (int i = 0; i < kNumContactBodies; ++i) motions[i] = MotionOf(kin, static_cast<ContactBody>(i));
  const BodyParameters& body = model.body;
  const ContactSites& sites = model.sites;
  const Vec2 half_trunk(body.half_body_x, body.half_body_y), half_foot(body.half_foot_x, body.half_foot_y);
  const double radius = model.contact.knee_radius;
  for (int pair = 0; pair < kNumContactPairs; ++pair) {
    const ContactPairSpec& spec = ContactPairs()[pair];
    if (!PairEnabled(model.options, spec) || HeldByWeld(spec, welds)) continue;
    const BodyMotion<double>& a = motions[static_cast<int>(spec.a)];
    const BodyMotion<double>& b = motions[static_cast<int>(spec.b)];
    // no site can be inside: the -1 keeps the sign
    if (!contact_laws::MayTouch(model, spec, a, b)) continue;
    switch (spec.law) {
      case ContactLaw::kMeshOnGround:
        depth[pair] = DeepestBelowGround(contact_laws::GroundSitesOf(sites, spec), b);
        break;
      case ContactLaw::kSphereOnGround:
        depth[pair] = radius - b.p.y();
        break;
      case ContactLaw::kMeshOnMesh:
        // a = trunk, b = foot: the trunk's sites in the foot, the foot's in the trunk
        depth[pair] = std::max(DeepestInBox(sites.trunk_in_foot[spec.leg], a, b, half_foot),
                               DeepestInBox(sites.foot_in_trunk[spec.leg], b, a, half_trunk));
        break;
      case ContactLaw::kMeshOnSphere:
        depth[pair] = DeepestInSphere(contact_laws::KneeSitesOf(sites, spec), radius, a, b);
        break;
    }
  }
  return depth;
}

JointStopSwitches JointStopMargins(const Model& model, const Vec9& q) {
  JointStopSwitches margin;
  margin.fill(-1.0);
  if (!model.options.joint_stops) return margin;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int joint = 0; joint < kNumJoints; ++joint) {
      const int i = JointIndex(leg, joint);
      margin[i - JointIndex(kLeft, kHip)] = std::abs(q(i)) - model.stops[joint].limit;
    }
  }
  return margin;
}

double JointStopTorque(const JointStop& stop, double angle, double rate) {
  // overrun x past the limit, pushing back with a Hunt–Crossley style damper
  if (angle > stop.limit) {
    const double x = angle - stop.limit;
    return -stop.stiffness * x * std::max(0.0, 1.0 + stop.damping * rate);
  }
  if (angle < -stop.limit) {
    const double x = -stop.limit - angle;
    return stop.stiffness * x * std::max(0.0, 1.0 - stop.damping * rate);
  }
  return 0.0;
}

void AddJointStopTorques(const Model& model, const Vec9& q, const Vec9& v, Vec9* Q) {
  for (int leg = 0; leg < kNumLegs; ++leg) {
    for (int joint = 0; joint < kNumJoints; ++joint) {
      const int i = JointIndex(leg, joint);
      (*Q)(i) += JointStopTorque(model.stops[joint], q(i), v(i));
    }
  }
}

double ElasticEnergy(const Model& model, const Kinematics& kin) {
  double e = 0.0;
  for (const ContactReport& r : ReportContacts(model, kin)) e += r.energy;
  if (model.options.joint_stops) {
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const LegKinematics& l = kin.legs[leg];
      // joint angles from the absolute ones: hip = pitch - femur, ...
      const double angles[kNumJoints] = {kin.pitch.angle - l.femur.angle, l.femur.angle - l.tibia.angle,
                                         l.tibia.angle - l.foot.angle};
      for (int joint = 0; joint < kNumJoints; ++joint) {
        const double x = std::max(0.0, std::abs(angles[joint]) - model.stops[joint].limit);
        e += 0.5 * model.stops[joint].stiffness * x * x;
      }
    }
  }
  return e;
}

}  // namespace walkers
