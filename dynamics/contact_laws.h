// The contact laws, written once for any scalar: double for the right-hand
// side, Eigen's forward-mode AutoDiffScalar for their derivatives in the
// Jacobian (dynamics/jacobian.cc). Internal to dynamics/.
//
// Each pair sees its two bodies as rigid motions of a reference point and an
// angle, and returns the wrench it puts on each about that point. Simbody's
// elastic foundation, in the plane: every spring site inside the other
// surface pushes with k A d (1 + c d') along the normal from the nearest
// point of the other surface, at the point a share `squish` of the overlap
// back from the site, with friction f_n mu(|v_t|) against the tangential
// slip there; a spring that would pull ("yanking") does nothing.
#pragma once

#include <cmath>
#include <type_traits>

#include "dynamics/contact.h"
#include "dynamics/contact_geometry.h"
#include "dynamics/kinematics.h"
#include "dynamics/model.h"

namespace walkers::contact_laws {

template <typename S>
using V2 = Eigen::Matrix<S, 2, 1>;

// The rigid motion of a contacting body: its reference point (trunk centre,
// ankle, knee) and absolute angle, and their rates; with the angle's cosine
// and sine.
template <typename S>
struct BodyMotion {
  V2<S> p = V2<S>::Zero();
  V2<S> v = V2<S>::Zero();
  S angle = S(0);
  S rate = S(0);
  S cos = S(1);
  S sin = S(0);
};

// Force and torque about the body's reference point.
template <typename S>
struct Wrench {
  V2<S> force = V2<S>::Zero();
  S torque = S(0);
};

template <typename S>
struct PairResult {
  Wrench<S> on_a, on_b;
  ContactReport report;  // values only
};

// A contacting body's reference point and angle in the kinematics (null for the ground).
struct ContactBodyKinematics {
  const PointKinematics* point = nullptr;
  const AngleKinematics* angle = nullptr;
};
inline ContactBodyKinematics KinematicsOf(const Kinematics& kin, ContactBody body) {
  switch (body) {
    case ContactBody::kTrunk:
      return {&kin.trunk, &kin.pitch};
    case ContactBody::kFootL:
      return {&kin.legs[kLeft].ankle, &kin.legs[kLeft].foot};
    case ContactBody::kFootR:
      return {&kin.legs[kRight].ankle, &kin.legs[kRight].foot};
    case ContactBody::kKneeL:
      return {&kin.legs[kLeft].knee, &kin.legs[kLeft].femur};
    case ContactBody::kKneeR:
      return {&kin.legs[kRight].knee, &kin.legs[kRight].femur};
    case ContactBody::kGround:
      break;
  }
  return {};
}

template <typename S>
S Cross(const V2<S>& a, const V2<S>& b) {
  return a.x() * b.y() - a.y() * b.x();
}
template <typename S>
V2<S> Perp(const V2<S>& r) {
  return V2<S>(-r.y(), r.x());
}
template <typename S>
V2<S> Rotate(const S& c, const S& s, const Vec2& r) {
  return V2<S>(c * r.x() - s * r.y(), s * r.x() + c * r.y());
}
template <typename S>
V2<S> VelocityAt(const BodyMotion<S>& b, const V2<S>& point) {
  return b.v + b.rate * Perp<S>(point - b.p);
}
template <typename S>
void Push(const BodyMotion<S>& b, const V2<S>& point, const V2<S>& f, Wrench<S>* w) {
  w->force += f;
  w->torque += Cross<S>(point - b.p, f);
}
template <typename S>
double Value(const S& x) {
  if constexpr (std::is_same_v<S, double>) {
    return x;
  } else {
    return x.value();
  }
}

// The dissipated power (ContactReport::dissipation) is counted when the
// report asks for it, by the right-hand side's instances alone: the
// Jacobian's never read it.
template <typename S>
bool CountsPower(const ContactReport* r) {
  if constexpr (std::is_same_v<S, double>) {
    return r->counts_dissipation;
  } else {
    return false;
  }
}

// ---- each law's site geometry, in plain doubles ----
// Where a law's sites lie relative to the other surface: the laws below test
// with these which sites touch before any S arithmetic, the right-hand side's
// sums (contact_sums.cc) work in these frames throughout, and the contact
// switches (ContactSwitchDepths, contact.cc) find the deepest site by them.

// A ground mesh's sites on a body at height y, turned by (c, s).
struct GroundView {
  double y, c, s;
  template <typename S>
  explicit GroundView(const BodyMotion<S>& body) : y(Value(body.p.y())), c(Value(body.cos)), s(Value(body.sin)) {}
  // a site's height above the body's reference point: (R p).y
  double Rise(const Vec2& p) const { return s * p.x() + c * p.y(); }
  // its depth below the ground, positive inside
  double Depth(const Vec2& p) const { return -(y + Rise(p)); }
};

// Mesh m's sites in the frame of box o: a site p of m lies at u0 + R_rel p.
struct BoxView {
  double c_rel, s_rel;  // cos and sin of angle_m - angle_o
  Vec2 u0;              // m's reference point in o's frame
  double centre_x;      // o's reference point along m's x axis
  template <typename S>
  BoxView(const BodyMotion<S>& m, const BodyMotion<S>& o) {
    const double cm = Value(m.cos), sm = Value(m.sin), co = Value(o.cos), so = Value(o.sin);
    const double dx = Value(m.p.x()) - Value(o.p.x()), dy = Value(m.p.y()) - Value(o.p.y());
    c_rel = cm * co + sm * so;
    s_rel = sm * co - cm * so;
    u0 = Vec2(co * dx + so * dy, -so * dx + co * dy);
    centre_x = -(cm * dx + sm * dy);
  }
  Vec2 Site(const Vec2& p) const {
    return Vec2(u0.x() + c_rel * p.x() - s_rel * p.y(), u0.y() + s_rel * p.x() + c_rel * p.y());
  }
  // Only sites within the x extent of o's bounding box in m's frame can be inside o.
  auto Candidates(const std::vector<BoxSite>& sites, const Vec2& half_o) const {
    const double reach = std::abs(c_rel) * half_o.x() + std::abs(s_rel) * half_o.y();
    return SitesWithinX(sites, centre_x - reach, centre_x + reach);
  }
};

// A point's margins to a box's x and y faces, u in the box's frame: both positive inside.
inline Vec2 BoxMargins(const Vec2& half, const Vec2& u) {
  return Vec2(half.x() - std::abs(u.x()), half.y() - std::abs(u.y()));
}

// Mesh m's sites about the centre of knee sphere k (its reference point), in m's frame.
struct SphereView {
  Vec2 centre;  // the sphere's centre in m's frame
  template <typename S>
  SphereView(const BodyMotion<S>& m, const BodyMotion<S>& k) {
    const double c = Value(m.cos), s = Value(m.sin);
    const double kx = Value(k.p.x()) - Value(m.p.x()), ky = Value(k.p.y()) - Value(m.p.y());
    centre = Vec2(c * kx + s * ky, -s * kx + c * ky);
  }
  // a site's squared distance from the centre in 3D
  double SquaredDistance(const SphereSite& site) const { return (site.p - centre).squaredNorm() + site.dz2; }
  auto Candidates(const std::vector<SphereSite>& sites, double radius) const {
    return SitesWithinX(sites, centre.x() - radius, centre.x() + radius);
  }
};

// Each pair's site lists: a mesh on the ground, a mesh in a knee sphere
// (a = the mesh); the mesh pairs' two lists are ContactSites' trunk_in_foot
// and foot_in_trunk.
inline const GroundMesh& GroundSitesOf(const ContactSites& sites, const ContactPairSpec& spec) {
  return spec.b == ContactBody::kTrunk ? sites.trunk_ground : sites.foot_ground;
}
inline const std::vector<SphereSite>& KneeSitesOf(const ContactSites& sites, const ContactPairSpec& spec) {
  return spec.a == ContactBody::kTrunk ? sites.trunk_in_knee[spec.leg] : sites.foot_in_knee;
}

// Simbody's quintic step 10x^3 - 15x^4 + 6x^5 on [0, 1]
template <typename S>
S Step5(const S& x) {
  return x * x * x * (10.0 + x * (6.0 * x - 15.0));
}

// g(s) = mu(s) / s from the squared slip speed: the friction force is
// -f_n g v_slip. Below the transition velocity mu_dry / s is a polynomial in
// x = s / v_t, written without the square root where it would be 0 / 0.
template <typename S>
S FrictionPerSlip(const FrictionLaw& law, const S& slip_squared) {
  using std::sqrt;
  const double vt = law.transition;
  const S x2 = slip_squared / (vt * vt);
  if (Value(x2) < 1e-24) return S(law.viscous) + (law.static_friction / vt) * 10.0 * x2;
  if (Value(x2) < 1.0) {
    // us (10 x^3 - 15 x^4 + 6 x^5) / (x vt)
    const S x = sqrt(x2);
    return S(law.viscous) + (law.static_friction / vt) * x2 * (10.0 + x * (6.0 * x - 15.0));
  }
  const S s = sqrt(slip_squared);
  const S x = s / vt;
  S mu_dry;
  if (Value(x) < 3.0) {
    // Stribeck: from static down to dynamic between 1 and 3 transition velocities
    mu_dry = law.static_friction - (law.static_friction - law.dynamic_friction) * Step5<S>((x - 1.0) / 2.0);
  } else {
    mu_dry = S(law.dynamic_friction);
  }
  return S(law.viscous) + mu_dry / s;
}

// One elastic-foundation spring: its normal force from the overlap d, its
// rate and the area; false if it would pull. Its elastic energy counts while
// it overlaps, pulling or not, so that a spring that lets go only loses energy.
template <typename S>
bool FoundationNormal(const FoundationLaw& law, double area, const S& d, const S& d_rate, S* f_n,
                      ContactReport* r) {
  const S f_elastic = law.stiffness * area * d;
  r->energy += 0.5 * Value(f_elastic) * Value(d);
  *f_n = f_elastic * (1.0 + law.dissipation * d_rate);
  if (!(Value(*f_n) > 0.0)) {
    // yanking: the elastic force goes, and its power with it
    if (CountsPower<S>(r)) r->dissipation -= Value(f_elastic) * Value(d_rate);
    return false;
  }
  // Hunt-Crossley's damping: f_elastic c d' at the rate d'
  if (CountsPower<S>(r)) r->dissipation += Value(f_elastic) * law.dissipation * Value(d_rate) * Value(d_rate);
  r->touching = true;
  ++r->elements;
  return true;
}

// ---- a brick mesh on the ground ----
template <typename S>
void MeshOnGround(const FoundationLaw& law, const GroundMesh& mesh, const BodyMotion<S>& body, Wrench<S>* w,
                  ContactReport* r) {
  const GroundView view(body);
  const S& c = body.cos;
  const S& s = body.sin;
  for (const GroundSite& site : mesh.CanTouch(view.c, view.s, view.y)) {
    // a site above the ground pushes nothing; tested in plain doubles, before any S arithmetic
    if (view.Depth(site.p) <= 0.0) continue;
    const V2<S> r_site = Rotate<S>(c, s, site.p);
    const S depth = -(body.p.y() + r_site.y());
    if (Value(depth) <= 0.0) continue;
    const V2<S> v_site = body.v + body.rate * Perp<S>(r_site);
    S f_n;
    if (!FoundationNormal<S>(law, site.area, depth, S(-v_site.y()), &f_n, r)) continue;
    // the ground's normal is vertical; the force acts a share `squish` of the
    // depth above the site, where the mesh's point slides at v_site.x - w squish d
    const S lift = law.squish * depth;
    const V2<S> point(body.p.x() + r_site.x(), body.p.y() + r_site.y() + lift);
    const S slip = v_site.x() - body.rate * lift;
    const S f_t = -f_n * FrictionPerSlip<S>(law.friction, S(slip * slip)) * slip;
    if (CountsPower<S>(r)) r->dissipation -= Value(f_t) * Value(slip);
    Push<S>(body, point, V2<S>(f_t, f_n), w);
    r->force += Vec2(Value(f_t), Value(f_n));
  }
}

// ---- a knee sphere on the ground (Hertz) ----
template <typename S>
void SphereOnGround(const HertzLaw& law, double radius, const BodyMotion<S>& knee, Wrench<S>* w,
                    ContactReport* r) {
  using std::sqrt;
  const S x = radius - knee.p.y();
  if (Value(x) <= 0.0) return;
  const S f_elastic = law.stiffness * x * sqrt(x);
  r->energy += 0.4 * Value(f_elastic) * Value(x);
  const S f_n = f_elastic * (1.0 + 1.5 * law.dissipation * (-knee.v.y()));
  if (!(Value(f_n) > 0.0)) {
    if (CountsPower<S>(r)) r->dissipation += Value(f_elastic) * Value(knee.v.y());  // yanking: x' = -v_y
    return;
  }
  if (CountsPower<S>(r)) r->dissipation += Value(f_elastic) * 1.5 * law.dissipation * Value(knee.v.y()) * Value(knee.v.y());
  // the force acts above the sphere's lowest point by the sphere's share of the depth
  const V2<S> point(knee.p.x(), knee.p.y() - radius + law.squish * x);
  const S slip = VelocityAt<S>(knee, point).x();
  const S f_t = -f_n * FrictionPerSlip<S>(law.friction, S(slip * slip)) * slip;
  if (CountsPower<S>(r)) r->dissipation -= Value(f_t) * Value(slip);
  Push<S>(knee, point, V2<S>(f_t, f_n), w);
  r->force += Vec2(Value(f_t), Value(f_n));
  r->touching = true;
  ++r->elements;
}

// ---- the springs of one mesh (body m) inside another box (body o) ----
// A site inside the other box pushes along the outward normal of the other
// box's nearest face; where that is a z face the push is out of the plane
// and only the friction acts in it. `scale` is the share of the patch this
// mesh's springs carry.
template <typename S>
void MeshInBox(const FoundationLaw& law, double scale, const std::vector<BoxSite>& sites,
               const BodyMotion<S>& m, const BodyMotion<S>& o, const Vec2& half_o, Wrench<S>* w_m, Wrench<S>* w_o,
               ContactReport* r, double report_sign) {
  const S& cm = m.cos;
  const S& sm = m.sin;
  const S& co = o.cos;
  const S& so = o.sin;
  // in plain doubles first, whether a site is inside the other box at all
  const BoxView view(m, o);
  const auto [first, last] = view.Candidates(sites, half_o);
  for (auto it = first; it != last; ++it) {
    const BoxSite& site = *it;
    const Vec2 margins = BoxMargins(half_o, view.Site(site.p));
    if (margins.x() <= 0.0 || margins.y() <= 0.0) continue;
    const V2<S> p = m.p + Rotate<S>(cm, sm, site.p);
    // the site in the other box's frame
    const V2<S> d = p - o.p;
    const V2<S> u(co * d.x() + so * d.y(), -so * d.x() + co * d.y());
    const S e_x = half_o.x() - (Value(u.x()) < 0.0 ? S(-u.x()) : u.x());
    const S e_y = half_o.y() - (Value(u.y()) < 0.0 ? S(-u.y()) : u.y());
    if (Value(e_x) <= 0.0 || Value(e_y) <= 0.0) continue;
    // the nearest face and its outward normal
    S depth;
    V2<S> normal = V2<S>::Zero();
    if (site.z_margin <= Value(e_x) && site.z_margin <= Value(e_y)) {
      depth = S(site.z_margin);
    } else if (Value(e_x) <= Value(e_y)) {
      depth = e_x;
      const double sign = Value(u.x()) < 0.0 ? -1.0 : 1.0;
      normal = V2<S>(sign * co, sign * so);
    } else {
      depth = e_y;
      const double sign = Value(u.y()) < 0.0 ? -1.0 : 1.0;
      normal = V2<S>(-sign * so, sign * co);
    }
    const V2<S> point = p + (law.squish * depth) * normal;
    const V2<S> v_rel = VelocityAt<S>(o, point) - VelocityAt<S>(m, point);
    const S d_rate = v_rel.dot(normal);
    S f_n;
    if (!FoundationNormal<S>(law, scale * site.area, depth, d_rate, &f_n, r)) continue;
    const V2<S> v_t = v_rel - d_rate * normal;
    // on the mesh: the push out of the other box and the other box's drag
    const S drag = f_n * FrictionPerSlip<S>(law.friction, S(v_t.squaredNorm()));
    if (CountsPower<S>(r)) r->dissipation += Value(drag) * Value(v_t.squaredNorm());
    const V2<S> f = f_n * normal + drag * v_t;
    Push<S>(m, point, f, w_m);
    Push<S>(o, point, V2<S>(-f), w_o);
    r->force += report_sign * Vec2(Value(f.x()), Value(f.y()));
  }
}

// ---- a mesh's springs (body m) inside a knee sphere (body k, centre at its reference point) ----
template <typename S>
void MeshInSphere(const FoundationLaw& law, const std::vector<SphereSite>& sites, double radius,
                  const BodyMotion<S>& m, const BodyMotion<S>& k, Wrench<S>* w_m, Wrench<S>* w_k,
                  ContactReport* r) {
  using std::sqrt;
  const S& c = m.cos;
  const S& s = m.sin;
  const double r2 = radius * radius;
  // in plain doubles first, whether a site is inside the sphere at all
  const SphereView view(m, k);
  const auto [first, last] = view.Candidates(sites, radius);
  for (auto it = first; it != last; ++it) {
    const SphereSite& site = *it;
    if (view.SquaredDistance(site) >= r2) continue;
    const V2<S> p = m.p + Rotate<S>(c, s, site.p);
    const V2<S> d = p - k.p;
    const S d3_squared = d.squaredNorm() + site.dz2;
    if (Value(d3_squared) >= r2) continue;
    // in 3D the normal runs from the sphere's centre through the site; its
    // part in the plane is d / d3
    const S d3 = sqrt(d3_squared);
    const S depth = radius - d3;
    const V2<S> normal = d / d3;
    const V2<S> point = p + (law.squish * depth) * normal;
    const V2<S> v_rel = VelocityAt<S>(k, point) - VelocityAt<S>(m, point);
    const S d_rate = v_rel.dot(normal);
    S f_n;
    if (!FoundationNormal<S>(law, site.area, depth, d_rate, &f_n, r)) continue;
    // the tangential slip in 3D: |v_t|^2 = |v_rel|^2 - d_rate^2; its part in the plane
    const V2<S> v_t = v_rel - d_rate * normal;
    const S slip_squared = v_rel.squaredNorm() - d_rate * d_rate;
    const S drag = f_n * FrictionPerSlip<S>(law.friction, slip_squared);
    if (CountsPower<S>(r)) r->dissipation += Value(drag) * Value(slip_squared);
    const V2<S> f = f_n * normal + drag * v_t;
    Push<S>(m, point, f, w_m);
    Push<S>(k, point, V2<S>(-f), w_k);
    r->force -= Vec2(Value(f.x()), Value(f.y()));  // reported on the knee
  }
}

// The right-hand side's instances of the three foundation laws are written
// out in dynamics/contact_sums.cc: the same physics summed in the frame of
// one of the pair's bodies, where a site's position and velocity cost a few
// operations, and each body's wrench is formed once from the sums. The
// templates above stay the reference; the automatic differentiation of the
// Jacobian runs them, and tests/dynamics/contact_sums_test.cc
// (ContactSumsTest.AgreeWithTheReferenceLawsAtRandomOverlaps) checks that both agree.
template <>
void MeshOnGround<double>(const FoundationLaw& law, const GroundMesh& mesh, const BodyMotion<double>& body,
                          Wrench<double>* w, ContactReport* r);
template <>
void MeshInBox<double>(const FoundationLaw& law, double scale, const std::vector<BoxSite>& sites,
                       const BodyMotion<double>& m, const BodyMotion<double>& o, const Vec2& half_o,
                       Wrench<double>* w_m, Wrench<double>* w_o, ContactReport* r, double report_sign);
template <>
void MeshInSphere<double>(const FoundationLaw& law, const std::vector<SphereSite>& sites, double radius,
                          const BodyMotion<double>& m, const BodyMotion<double>& k, Wrench<double>* w_m,
                          Wrench<double>* w_k, ContactReport* r);

// Whether a pair's surfaces can touch at all, in plain doubles: a mesh whose
// box's lowest corner, or a knee sphere whose lowest point, is below the
// ground; two bodies whose circumcircles overlap (the knee's is its sphere).
// PairContact computes nothing for a pair that cannot; a caller visiting every
// pair asks first and skips the call.
template <typename S>
bool MayTouch(const Model& model, const ContactPairSpec& spec, const BodyMotion<S>& a, const BodyMotion<S>& b) {
  const BodyParameters& body = model.body;
  const Vec2 half_trunk(body.half_body_x, body.half_body_y), half_foot(body.half_foot_x, body.half_foot_y);
  const double radius = model.contact.knee_radius;
  const auto half_of = [&](ContactBody mesh) { return mesh == ContactBody::kTrunk ? half_trunk : half_foot; };
  // the distance of the two reference points, for the pairs of two bodies
  const auto gap = [&] { return Vec2(Value(a.p.x()) - Value(b.p.x()), Value(a.p.y()) - Value(b.p.y())).norm(); };
  switch (spec.law) {
    case ContactLaw::kMeshOnGround: {
      const Vec2 half = half_of(spec.b);
      return Value(b.p.y()) - (std::abs(Value(b.sin)) * half.x() + std::abs(Value(b.cos)) * half.y()) < 0.0;
    }
    case ContactLaw::kSphereOnGround:
      return Value(b.p.y()) < radius;
    case ContactLaw::kMeshOnMesh:
      return gap() < half_trunk.norm() + half_foot.norm();
    case ContactLaw::kMeshOnSphere:
      return gap() < half_of(spec.a).norm() + radius;
  }
  return true;
}

// One pair's wrenches on its bodies a and b (a's motion unused for the ground).
template <typename S>
PairResult<S> PairContact(const Model& model, int pair, const BodyMotion<S>& a, const BodyMotion<S>& b,
                          bool count_dissipation = false) {
  PairResult<S> out;
  out.report.counts_dissipation = count_dissipation;
  const ContactPairSpec& spec = ContactPairs()[pair];
  const BodyParameters& body = model.body;
  const ContactSites& sites = model.sites;
  const Vec2 half_trunk(body.half_body_x, body.half_body_y), half_foot(body.half_foot_x, body.half_foot_y);
  const double radius = model.contact.knee_radius;
  if (!MayTouch<S>(model, spec, a, b)) return out;
  switch (spec.law) {
    case ContactLaw::kMeshOnGround:
      MeshOnGround<S>(model.laws.mesh_ground, GroundSitesOf(sites, spec), b, &out.on_b, &out.report);
      break;
    case ContactLaw::kSphereOnGround:
      SphereOnGround<S>(model.laws.knee_ground, radius, b, &out.on_b, &out.report);
      break;
    case ContactLaw::kMeshOnMesh: {
      // a = trunk, b = foot; each mesh's springs carry half the patch (docs/model.md)
      MeshInBox<S>(model.laws.mesh_mesh, 0.5, sites.trunk_in_foot[spec.leg], a, b, half_foot, &out.on_a, &out.on_b,
                   &out.report, -1.0);
      MeshInBox<S>(model.laws.mesh_mesh, 0.5, sites.foot_in_trunk[spec.leg], b, a, half_trunk, &out.on_b,
                   &out.on_a, &out.report, 1.0);
      break;
    }
    case ContactLaw::kMeshOnSphere: {
      // a = the mesh (trunk or foot), b = the knee
      MeshInSphere<S>(model.laws.mesh_knee, KneeSitesOf(sites, spec), radius, a, b, &out.on_a, &out.on_b,
                      &out.report);
      break;
    }
  }
  return out;
}

}  // namespace walkers::contact_laws
