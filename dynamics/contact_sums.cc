// The elastic foundation's sums for the right-hand side (contact_laws.h
// declares them): the laws of contact_laws.h for doubles, each summed in the
// frame of one body of the pair. There a site's position is one rotation of
// its fixed coordinates, the relative velocity at a point u is B + dw perp(u)
// with B and dw fixed for the pair, and the force and torque on the mesh are
// summed about that frame's origin; each body's wrench follows from the two
// sums at the end.
#include <cmath>

#include "dynamics/contact_laws.h"

namespace walkers::contact_laws {
namespace {

// v in the frame of a body of angle (c, s)
Vec2 ToFrame(double c, double s, const Vec2& v) { return Vec2(c * v.x() + s * v.y(), -s * v.x() + c * v.y()); }
Vec2 FromFrame(double c, double s, const Vec2& v) { return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); }

}  // namespace

template <>
void MeshOnGround<double>(const FoundationLaw& law, const GroundMesh& mesh, const BodyMotion<double>& body,
                          Wrench<double>* w, ContactReport* r) {
  const GroundView view(body);
  // in the world frame, about the body's reference point
  Vec2 F = Vec2::Zero();
  double T = 0.0;
  for (const GroundSite& site : mesh.CanTouch(view.c, view.s, view.y)) {
    const double depth = view.Depth(site.p);
    if (depth <= 0.0) continue;
    const double rx = view.c * site.p.x() - view.s * site.p.y(), ry = view.Rise(site.p);
    const Vec2 v_site(body.v.x() - body.rate * ry, body.v.y() + body.rate * rx);
    double f_n;
    if (!FoundationNormal<double>(law, site.area, depth, -v_site.y(), &f_n, r)) continue;
    // the force acts a share `squish` of the depth above the site, where the
    // mesh's point slides at v_site.x - w squish d
    const double lift = law.squish * depth;
    const double slip = v_site.x() - body.rate * lift;
    const double f_t = -f_n * FrictionPerSlip<double>(law.friction, slip * slip) * slip;
    if (r->counts_dissipation) r->dissipation -= f_t * slip;
    F += Vec2(f_t, f_n);
    T += rx * f_n - (ry + lift) * f_t;
  }
  w->force += F;
  w->torque += T;
  r->force += F;
}

template <>
void MeshInBox<double>(const FoundationLaw& law, double scale, const std::vector<BoxSite>& sites,
                       const BodyMotion<double>& m, const BodyMotion<double>& o, const Vec2& half_o,
                       Wrench<double>* w_m, Wrench<double>* w_o, ContactReport* r, double report_sign) {
  // in the other box's frame: the mesh's reference point u0 and its turn
  const BoxView view(m, o);
  const Vec2& u0 = view.u0;
  const auto [first, last] = view.Candidates(sites, half_o);
  // the other box's velocity relative to the mesh's at a point u of its frame:
  // R_o^T (v_o - v_m) + w_o perp(u) - w_m perp(u - u0) = B + dw perp(u)
  const Vec2 B = ToFrame(o.cos, o.sin, o.v - m.v) + m.rate * Perp(u0);
  const double dw = o.rate - m.rate;
  // the force on the mesh and its torque about the frame's origin
  Vec2 F = Vec2::Zero();
  double T = 0.0;
  for (auto it = first; it != last; ++it) {
    const BoxSite& site = *it;
    const Vec2 u = view.Site(site.p);
    const Vec2 margins = BoxMargins(half_o, u);
    const double e_x = margins.x(), e_y = margins.y();
    if (e_x <= 0.0 || e_y <= 0.0) continue;
    // the nearest face and its outward normal (none in the plane for a z face)
    double depth;
    Vec2 normal = Vec2::Zero();
    if (site.z_margin <= e_x && site.z_margin <= e_y) {
      depth = site.z_margin;
    } else if (e_x <= e_y) {
      depth = e_x;
      normal.x() = u.x() < 0.0 ? -1.0 : 1.0;
    } else {
      depth = e_y;
      normal.y() = u.y() < 0.0 ? -1.0 : 1.0;
    }
    const Vec2 point = u + (law.squish * depth) * normal;
    const Vec2 v_rel = B + dw * Perp(point);
    const double d_rate = v_rel.dot(normal);
    double f_n;
    if (!FoundationNormal<double>(law, scale * site.area, depth, d_rate, &f_n, r)) continue;
    const Vec2 v_t = v_rel - d_rate * normal;
    // the push out of the other box and the other box's drag
    const double slip_squared = v_t.squaredNorm();
    const double drag = f_n * FrictionPerSlip<double>(law.friction, slip_squared);
    if (r->counts_dissipation) r->dissipation += drag * slip_squared;
    const Vec2 f = f_n * normal + drag * v_t;
    F += f;
    T += Cross<double>(point, f);
  }
  const Vec2 F_world = FromFrame(o.cos, o.sin, F);
  w_m->force += F_world;
  w_m->torque += T - Cross<double>(u0, F);
  w_o->force -= F_world;
  w_o->torque -= T;
  r->force += report_sign * F_world;
}

template <>
void MeshInSphere<double>(const FoundationLaw& law, const std::vector<SphereSite>& sites, double radius,
                          const BodyMotion<double>& m, const BodyMotion<double>& k, Wrench<double>* w_m,
                          Wrench<double>* w_k, ContactReport* r) {
  const double r2 = radius * radius;
  // in the mesh's frame: the sphere's centre
  const SphereView view(m, k);
  const Vec2& centre = view.centre;
  const auto [first, last] = view.Candidates(sites, radius);
  // the knee's velocity relative to the mesh's at a point u of the mesh's
  // frame: R_m^T (v_k - v_m) + w_k perp(u - centre) - w_m perp(u) = B + dw perp(u)
  const Vec2 B = ToFrame(m.cos, m.sin, k.v - m.v) - k.rate * Perp(centre);
  const double dw = k.rate - m.rate;
  // the force on the mesh and its torque about the mesh's reference point
  Vec2 F = Vec2::Zero();
  double T = 0.0;
  for (auto it = first; it != last; ++it) {
    const SphereSite& site = *it;
    const double d3_squared = view.SquaredDistance(site);
    if (d3_squared >= r2) continue;
    // in 3D the normal runs from the sphere's centre through the site; its
    // part in the plane is d / d3
    const double d3 = std::sqrt(d3_squared);
    const double depth = radius - d3;
    const Vec2 normal = (site.p - centre) / d3;
    const Vec2 point = site.p + (law.squish * depth) * normal;
    const Vec2 v_rel = B + dw * Perp(point);
    const double d_rate = v_rel.dot(normal);
    double f_n;
    if (!FoundationNormal<double>(law, site.area, depth, d_rate, &f_n, r)) continue;
    // the tangential slip in 3D: |v_t|^2 = |v_rel|^2 - d_rate^2; its part in the plane
    const Vec2 v_t = v_rel - d_rate * normal;
    const double slip_squared = v_rel.squaredNorm() - d_rate * d_rate;
    const double drag = f_n * FrictionPerSlip<double>(law.friction, slip_squared);
    if (r->counts_dissipation) r->dissipation += drag * slip_squared;
    const Vec2 f = f_n * normal + drag * v_t;
    F += f;
    T += Cross<double>(point, f);
  }
  const Vec2 F_world = FromFrame(m.cos, m.sin, F);
  w_m->force += F_world;
  w_m->torque += T;
  w_k->force -= F_world;
  w_k->torque -= T - Cross<double>(centre, F);
  r->force -= F_world;  // reported on the knee
}

}  // namespace walkers::contact_laws
