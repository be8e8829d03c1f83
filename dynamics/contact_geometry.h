// The walker's contact surfaces as the authors' Simbody program builds them,
// reduced to the plane of motion (docs/model.md, "Contact").
//
// Trunk and feet are brick triangle meshes (Simbody's
// PolygonalMesh::createBrickMesh(halfSize, 6), each quad split in two). In
// Simbody's elastic foundation every triangle is one spring at its centroid,
// whatever its face; so in the plane a box is a set of spring sites (x, y) in
// its own frame, each with the area of the triangles whose centroids project
// there. The z coordinate of a triangle only decides which other surface it
// can be inside: feet and knees sit at z = ±leg_z, the trunk spans
// [-half_body_z, half_body_z].
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "dynamics/coords.h"

namespace walkers {

// One triangle of a brick mesh: centroid in the box frame and area.
struct MeshTriangle {
  Vec3 centroid = Vec3::Zero();  // [m]
  double area = 0;               // [m^2]
};

// The triangles of Simbody's brick mesh of half sizes `half` at the given
// resolution: vertices evenly spaced on every face, the longest edge cut into
// resolution + 1 pieces and the others into pieces of about the same length;
// each quad split along the diagonal through its first vertex.
std::vector<MeshTriangle> BrickMeshTriangles(const Vec3& half, int resolution);

// A spring site against the ground: every triangle whose centroid projects to
// p (box frame), summed.
struct GroundSite {
  Vec2 p = Vec2::Zero();  // [m]
  double area = 0;        // [m^2]
};

// A box's ground sites (sorted by p.x), and the same sites grouped by how low
// they sit in the box, for the right-hand side's sums: a site can be below the
// ground only if it lies low enough in its box for the box's pose, and most of
// a resting foot's sites never are.
class GroundMesh {
 public:
  GroundMesh() = default;
  explicit GroundMesh(std::vector<GroundSite> sites_sorted_by_x);

  const std::vector<GroundSite>& sites() const { return sites_; }

  // The sites that can be below the ground for a box turned by (cos, sin)
  // with its reference point at height y, in the order of sites(): all sites
  // at or below the one height the bound allows. In exact arithmetic a site
  // (x, y_s) is below the ground iff y + sin x + cos y_s < 0, so for cos > 0
  // only if y_s < (-y + |sin| max|x|) / cos; the sites left out are above the
  // ground by far more than rounding, and summing the others in their order
  // gives the full sum's bits.
  const std::vector<GroundSite>& CanTouch(double cos, double sin, double y) const;

 private:
  std::vector<GroundSite> sites_;
  std::vector<double> heights_;                   // the sites' distinct p.y, ascending
  std::vector<std::vector<GroundSite>> at_most_;  // at_most_[k]: the sites with p.y <= heights_[k], in order
  double reach_x_ = 0;                            // max |p.x| [m]
};

// A spring site that may be inside another box: the point, its area, and how
// far its triangles' centroids are from the other box's nearer z face
// (z_margin > 0: inside the other box's z extent). Where z_margin is the
// smallest of the distances to the other box's faces, the nearest face is a z
// face and the spring pushes along z, out of the plane.
struct BoxSite {
  Vec2 p = Vec2::Zero();  // [m] in this box's frame
  double area = 0;        // [m^2]
  double z_margin = 0;    // [m]
};

// A spring site that may be inside a knee sphere: the point, its area and the
// square of its z distance from the sphere's centre.
struct SphereSite {
  Vec2 p = Vec2::Zero();  // [m] in the box's frame
  double area = 0;        // [m^2]
  double dz2 = 0;         // [m^2]
};

// Every site the walker's contacts use, built once per body. Each list is
// sorted by p.x, so that a contact law can go straight to the sites within
// reach of the other body (SitesWithinX).
struct ContactSites {
  GroundMesh trunk_ground;
  GroundMesh foot_ground;                                // the same for both feet
  std::array<std::vector<BoxSite>, kNumLegs> trunk_in_foot;   // trunk sites within the z extent of foot[leg]
  std::array<std::vector<BoxSite>, kNumLegs> foot_in_trunk;   // foot[leg] sites within the trunk's z extent
  std::array<std::vector<SphereSite>, kNumLegs> trunk_in_knee;  // trunk sites within reach of knee[leg]
  std::vector<SphereSite> foot_in_knee;  // a foot's sites within reach of its own knee (the same for both legs)
};

// The sites of a list sorted by p.x whose p.x lies in [lo, hi].
template <typename Site>
std::pair<typename std::vector<Site>::const_iterator, typename std::vector<Site>::const_iterator> SitesWithinX(
    const std::vector<Site>& sites, double lo, double hi) {
  const auto first = std::lower_bound(sites.begin(), sites.end(), lo,
                                      [](const Site& site, double x) { return site.p.x() < x; });
  const auto last =
      std::upper_bound(first, sites.end(), hi, [](double x, const Site& site) { return x < site.p.x(); });
  return {first, last};
}

// z of each leg's plane in the authors' model: the left leg at +leg_z, the right at -leg_z.
inline double LegZ(int leg, double leg_z) { return leg == kLeft ? leg_z : -leg_z; }

ContactSites BuildContactSites(const Vec3& half_trunk, const Vec3& half_foot, double leg_z, double knee_radius,
                               int resolution);

}  // namespace walkers
