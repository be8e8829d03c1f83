#include "dynamics/contact_geometry.h"

#include <algorithm>
#include <cmath>

namespace walkers {
namespace {

// Vertices along each edge of a brick mesh: the longest edge is cut into
// resolution + 1 pieces, every edge into the whole number of pieces of about
// that length (rounded at .51, at least one).
std::array<int, 3> BrickMeshDivisions(const Vec3& half, int resolution) {
  const Vec3 dims = 2.0 * half;
  const double target = dims.maxCoeff() / (resolution + 1);
  std::array<int, 3> n{};
  for (int i = 0; i < 3; ++i) n[i] = std::max(static_cast<int>(dims[i] / target + 0.49), 1);
  return n;
}

// A face of the brick: its normal axis and side, its two in-face axes (u, w),
// and which diagonal splits its quads: the one from (u0, w0) to (u1, w1)
// (`rising`) or from (u0, w1) to (u1, w0). This is where Simbody's face
// vertex order puts each quad's first and third vertices.
struct BrickFace {
  int axis;
  double side;
  int u, w;
  bool rising;
};
constexpr BrickFace kBrickFaces[6] = {
    {0, -1.0, 1, 2, false},  // -x (y, z)
    {0, +1.0, 1, 2, true},   // +x
    {1, -1.0, 0, 2, true},   // -y (x, z)
    {1, +1.0, 0, 2, false},  // +y
    {2, -1.0, 0, 1, false},  // -z (x, y)
    {2, +1.0, 0, 1, true},   // +z
};

// Sites at the same point (and the same margin) merge into one: a box's
// springs repeat along z.
template <typename Site, typename Same>
void AddSite(std::vector<Site>* sites, const Site& site, Same same) {
  for (Site& s : *sites) {
    if (same(s, site)) {
      s.area += site.area;
      return;
    }
  }
  sites->push_back(site);
}

bool SamePoint(const Vec2& a, const Vec2& b) { return (a - b).cwiseAbs().maxCoeff() < 1e-12; }

// A box's triangles that can be inside a box of z extent [lo, hi], as sites
// in the plane with their z margins.
std::vector<BoxSite> SitesInZRange(const std::vector<MeshTriangle>& triangles, double z_offset, double lo, double hi) {
  std::vector<BoxSite> sites;
  for (const MeshTriangle& t : triangles) {
    const double z = t.centroid.z() + z_offset;
    const double margin = std::min(z - lo, hi - z);
    if (margin <= 0.0) continue;
    AddSite(&sites, BoxSite{t.centroid.head<2>(), t.area, margin}, [](const BoxSite& a, const BoxSite& b) {
      return SamePoint(a.p, b.p) && std::abs(a.z_margin - b.z_margin) < 1e-12;
    });
  }
  return sites;
}

// A box's triangles within reach of a sphere of radius r centred at z_sphere.
std::vector<SphereSite> SitesNearSphere(const std::vector<MeshTriangle>& triangles, double z_offset,
                                        double z_sphere, double r) {
  std::vector<SphereSite> sites;
  for (const MeshTriangle& t : triangles) {
    const double dz = t.centroid.z() + z_offset - z_sphere;
    if (std::abs(dz) >= r) continue;
    AddSite(&sites, SphereSite{t.centroid.head<2>(), t.area, dz * dz}, [](const SphereSite& a, const SphereSite& b) {
      return SamePoint(a.p, b.p) && std::abs(a.dz2 - b.dz2) < 1e-12;
    });
  }
  return sites;
}

std::vector<GroundSite> GroundSites(const std::vector<MeshTriangle>& triangles) {
  std::vector<GroundSite> sites;
  for (const MeshTriangle& t : triangles) {
    AddSite(&sites, GroundSite{t.centroid.head<2>(), t.area},
            [](const GroundSite& a, const GroundSite& b) { return SamePoint(a.p, b.p); });
  }
  return sites;
}

}  // namespace

std::vector<MeshTriangle> BrickMeshTriangles(const Vec3& half, int resolution) {
  const std::array<int, 3> n = BrickMeshDivisions(half, resolution);
  std::vector<MeshTriangle> triangles;
  for (const BrickFace& face : kBrickFaces) {
    const double du = 2.0 * half[face.u] / n[face.u], dw = 2.0 * half[face.w] / n[face.w];
    // the two triangles of a quad, as centroid offsets in quad units
    const std::array<Eigen::Vector2d, 2> centroids =
        face.rising ? std::array<Eigen::Vector2d, 2>{Eigen::Vector2d(2.0 / 3, 1.0 / 3), Eigen::Vector2d(1.0 / 3, 2.0 / 3)}
                    : std::array<Eigen::Vector2d, 2>{Eigen::Vector2d(2.0 / 3, 2.0 / 3), Eigen::Vector2d(1.0 / 3, 1.0 / 3)};
    for (int i = 0; i < n[face.u]; ++i) {
      for (int k = 0; k < n[face.w]; ++k) {
        for (const Eigen::Vector2d& c : centroids) {
          MeshTriangle t;
          t.centroid[face.axis] = face.side * half[face.axis];
          t.centroid[face.u] = -half[face.u] + (i + c.x()) * du;
          t.centroid[face.w] = -half[face.w] + (k + c.y()) * dw;
          t.area = 0.5 * du * dw;
          triangles.push_back(t);
        }
      }
    }
  }
  return triangles;
}

GroundMesh::GroundMesh(std::vector<GroundSite> sites_sorted_by_x) : sites_(std::move(sites_sorted_by_x)) {
  for (const GroundSite& site : sites_) {
    heights_.push_back(site.p.y());
    reach_x_ = std::max(reach_x_, std::abs(site.p.x()));
  }
  std::sort(heights_.begin(), heights_.end());
  heights_.erase(std::unique(heights_.begin(), heights_.end()), heights_.end());
  for (const double height : heights_) {
    std::vector<GroundSite>& low = at_most_.emplace_back();
    for (const GroundSite& site : sites_) {
      if (site.p.y() <= height) low.push_back(site);
    }
  }
}

const std::vector<GroundSite>& GroundMesh::CanTouch(double cos, double sin, double y) const {
  static const std::vector<GroundSite> kNone;
  // turned by a right angle or more (or not finite): no bound
  if (!(cos > 0.0)) return sites_;
  // 1e-9 m covers the rounding of the bound and of each site's own test
  const double highest = (-y + std::abs(sin) * reach_x_) / cos + 1e-9;
  const auto above = std::upper_bound(heights_.begin(), heights_.end(), highest);
  if (above == heights_.begin()) return kNone;
  return at_most_[above - heights_.begin() - 1];
}

ContactSites BuildContactSites(const Vec3& half_trunk, const Vec3& half_foot, double leg_z, double knee_radius,
                               int resolution) {
  const std::vector<MeshTriangle> trunk = BrickMeshTriangles(half_trunk, resolution);
  const std::vector<MeshTriangle> foot = BrickMeshTriangles(half_foot, resolution);
  ContactSites s;
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const double z = LegZ(leg, leg_z);
    s.trunk_in_foot[leg] = SitesInZRange(trunk, 0.0, z - half_foot.z(), z + half_foot.z());
    s.foot_in_trunk[leg] = SitesInZRange(foot, z, -half_trunk.z(), half_trunk.z());
    s.trunk_in_knee[leg] = SitesNearSphere(trunk, 0.0, z, knee_radius);
  }
  // the knee sits in its foot's plane: the foot's own z is the sphere's
  s.foot_in_knee = SitesNearSphere(foot, 0.0, 0.0, knee_radius);
  const auto by_x = [](auto* sites) {
    std::stable_sort(sites->begin(), sites->end(), [](const auto& a, const auto& b) { return a.p.x() < b.p.x(); });
  };
  std::vector<GroundSite> trunk_ground = GroundSites(trunk), foot_ground = GroundSites(foot);
  by_x(&trunk_ground);
  by_x(&foot_ground);
  s.trunk_ground = GroundMesh(std::move(trunk_ground));
  s.foot_ground = GroundMesh(std::move(foot_ground));
  by_x(&s.foot_in_knee);
  for (int leg = 0; leg < kNumLegs; ++leg) {
    by_x(&s.trunk_in_foot[leg]);
    by_x(&s.foot_in_trunk[leg]);
    by_x(&s.trunk_in_knee[leg]);
  }
  return s;
}

}  // namespace walkers
