#include "kernel/contact/contact_detection.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim {

namespace {

/// A shape placed in the world at this position stage.
struct PlacedShape {
  const ContactShape& shape;
  Transform X_world_shape;
  Vector3 axis(int k) const { return X_world_shape.rotation().col(k); }
  const Vector3& centre() const { return X_world_shape.translation(); }
};

/// Collects the points of one pair; the normal is from b towards a. When the narrow
/// phase ran with the pair's shapes swapped (`swapped`), the normal is turned round so
/// that the pair's own a is still the one pushed along +n.
class PointWriter {
 public:
  PointWriter(std::span<ContactPoint> out, int& count, int pair, int link_a, int link_b, bool swapped,
              const Vector3& reference_x, const Vector3& reference_y, double margin)
      : out_(out), count_(count), first_(count), pair_(pair), link_a_(link_a), link_b_(link_b), swapped_(swapped),
        reference_x_(reference_x), reference_y_(reference_y), margin_(margin) {}

  /// A point with surface a at point + n gap/2 and surface b at point - n gap/2.
  void add(const Vector3& point_world, const Vector3& normal_world, double gap) {
    if (!(gap < margin_)) return;
    // Two narrow-phase passes (box-box) can find the same point from both sides.
    for (int k = first_; k < std::min(count_, static_cast<int>(out_.size())); ++k)
      if ((out_[k].point_world - point_world).norm() <= 1e-9 + 1e-6 * margin_) return;
    if (count_ >= static_cast<int>(out_.size())) {
      ++overflow_;
      return;
    }
    ContactPoint& c = out_[count_++];
    c.pair = pair_;
    c.link_a = link_a_;
    c.link_b = link_b_;
    c.point_world = point_world;
    c.normal_world = swapped_ ? Vector3(-normal_world) : normal_world;
    c.gap = gap;
    // Tangents from a direction fixed on the supporting shape (so that they do not spin
    // with the contact point): its x axis projected on the tangent plane, or its y axis
    // when x is nearly normal.
    const Vector3& n = c.normal_world;
    const Vector3& reference = std::abs(reference_x_.dot(n)) < 0.9 ? reference_x_ : reference_y_;
    c.tangent1_world = (reference - reference.dot(n) * n).normalized();
    c.tangent2_world = n.cross(c.tangent1_world);
  }
  int overflow() const { return overflow_; }

 private:
  std::span<ContactPoint> out_;
  int& count_;
  int first_;
  int pair_, link_a_, link_b_;
  bool swapped_;
  Vector3 reference_x_, reference_y_;
  double margin_;
  int overflow_ = 0;
};

Vector3 box_corner(const PlacedShape& box, int k) {
  const Vector3& h = box.shape.half_extents;
  const Vector3 local((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z());
  return box.X_world_shape.act_point(local);
}

// ---- narrow phase: shape a against shape b, normal from b to a ----

void sphere_plane(const PlacedShape& sphere, const PlacedShape& plane, PointWriter& writer) {
  const Vector3 n = plane.axis(2);
  const double gap = n.dot(sphere.centre() - plane.centre()) - sphere.shape.radius;
  writer.add(sphere.centre() - (sphere.shape.radius + 0.5 * gap) * n, n, gap);
}

void box_plane(const PlacedShape& box, const PlacedShape& plane, PointWriter& writer) {
  const Vector3 n = plane.axis(2);
  for (int k = 0; k < 8; ++k) {
    const Vector3 corner = box_corner(box, k);
    const double gap = n.dot(corner - plane.centre());
    writer.add(corner - 0.5 * gap * n, n, gap);
  }
}

void cylinder_plane(const PlacedShape& cylinder, const PlacedShape& plane, PointWriter& writer) {
  const Vector3 n = plane.axis(2);
  const Vector3 u = cylinder.axis(2);
  const double r = cylinder.shape.radius;
  const Vector3 towards_plane = -(n - n.dot(u) * u);  // in the end disc's plane
  for (const double side : {-1.0, 1.0}) {
    const Vector3 end = cylinder.centre() + side * cylinder.shape.half_length * u;
    if (towards_plane.norm() > 1e-6) {
      // The end disc's lowest rim point (the whole cylinder's lowest points lie on the
      // two rims: a cylinder lying on a deck touches along a line, held by both ends).
      const Vector3 rim = end + r * towards_plane.normalized();
      const double gap = n.dot(rim - plane.centre());
      writer.add(rim - 0.5 * gap * n, n, gap);
    } else {
      // Standing on an end: the disc is parallel to the plane; four rim points support it.
      for (int k = 0; k < 4; ++k) {
        const Vector3 rim = end + r * (k < 2 ? 1.0 : -1.0) * cylinder.axis(k % 2);
        const double gap = n.dot(rim - plane.centre());
        writer.add(rim - 0.5 * gap * n, n, gap);
      }
    }
  }
}

void sphere_sphere(const PlacedShape& a, const PlacedShape& b, PointWriter& writer) {
  const Vector3 d = a.centre() - b.centre();
  const double distance = d.norm();
  const Vector3 n = distance > 1e-12 ? Vector3(d / distance) : Vector3(Vector3::UnitZ());
  const double gap = distance - a.shape.radius - b.shape.radius;
  writer.add(b.centre() + (b.shape.radius + 0.5 * gap) * n, n, gap);
}

void sphere_box(const PlacedShape& sphere, const PlacedShape& box, PointWriter& writer) {
  const Vector3& h = box.shape.half_extents;
  const Vector3 p = box.X_world_shape.act_inverse_point(sphere.centre());
  const Vector3 closest = p.cwiseMax(-h).cwiseMin(h);
  Vector3 normal_local, surface_local;
  double gap = 0.0;
  if ((p - closest).norm() > 1e-12) {  // centre outside the box: the closest point
    normal_local = (p - closest).normalized();
    surface_local = closest;
    gap = (p - closest).norm() - sphere.shape.radius;
  } else {  // centre inside: out through the nearest face
    int axis = 0;
    (h - p.cwiseAbs()).minCoeff(&axis);
    normal_local = Vector3::Zero();
    normal_local[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
    surface_local = p;
    surface_local[axis] = normal_local[axis] * h[axis];
    gap = -(h[axis] - std::abs(p[axis])) - sphere.shape.radius;
  }
  const Vector3 n = box.X_world_shape.rotation() * normal_local;
  writer.add(box.X_world_shape.act_point(surface_local) + 0.5 * gap * n, n, gap);
}

/// Support of a box along direction n: max over its corners of n . x.
double box_support(const PlacedShape& box, const Vector3& n) {
  double s = n.dot(box.centre());
  for (int k = 0; k < 3; ++k) s += box.shape.half_extents[k] * std::abs(n.dot(box.axis(k)));
  return s;
}

/// True if `point` lies over the face of `box` whose outward normal is (anti)parallel to
/// n within `tolerance` [m] on the face's two in-plane axes; false if no face of the box
/// is nearly perpendicular to n (its support along n is an edge or a corner).
bool over_face(const PlacedShape& box, const Vector3& n, const Vector3& point, double tolerance) {
  int normal_axis = 0;
  double best = 0.0;
  for (int k = 0; k < 3; ++k)
    if (std::abs(n.dot(box.axis(k))) > best) best = std::abs(n.dot(box.axis(normal_axis = k)));
  if (best < 0.99) return false;
  const Vector3 p = box.X_world_shape.act_inverse_point(point);
  for (int k = 0; k < 3; ++k)
    if (k != normal_axis && std::abs(p[k]) > box.shape.half_extents[k] + tolerance) return false;
  return true;
}

/// Box a on box b by separating axes over the six face normals (the edge-edge axes are
/// not tried: an edge resting across an edge makes no point here), then vertex-face
/// points: corners of a over b's face near b's support plane, and corners of b over a's
/// face near a's support plane.
void box_box(const PlacedShape& a, const PlacedShape& b, double margin, PointWriter& writer) {
  const Vector3 between = a.centre() - b.centre();
  Vector3 n = Vector3::UnitZ();
  double best_separation = -std::numeric_limits<double>::infinity();
  for (const PlacedShape* shape : {&b, &a})
    for (int k = 0; k < 3; ++k) {
      Vector3 axis = shape->axis(k);
      if (axis.dot(between) < 0.0) axis = -axis;
      const double separation = -box_support(a, -axis) - box_support(b, axis);
      if (separation > best_separation + 1e-12) {
        best_separation = separation;
        n = axis;
      }
    }
  const double support_b = box_support(b, n);    // b's surface along +n
  const double support_a = -box_support(a, -n);  // a's surface along -n
  const double tolerance = margin;
  for (int k = 0; k < 8; ++k) {
    const Vector3 corner = box_corner(a, k);
    const double gap = n.dot(corner) - support_b;
    if (gap < margin && over_face(b, n, corner, tolerance)) writer.add(corner - 0.5 * gap * n, n, gap);
  }
  for (int k = 0; k < 8; ++k) {
    const Vector3 corner = box_corner(b, k);
    const double gap = support_a - n.dot(corner);
    if (gap < margin && over_face(a, n, corner, tolerance)) writer.add(corner + 0.5 * gap * n, n, gap);
  }
}

/// Puts the kinds of a pair in the order the narrow phase takes them (the more
/// "solid" first: sphere, box, cylinder before plane; sphere before box).
int kind_rank(ContactShapeKind kind) {
  switch (kind) {
    case ContactShapeKind::sphere: return 0;
    case ContactShapeKind::cylinder: return 1;
    case ContactShapeKind::box: return 2;
    case ContactShapeKind::plane: return 3;
  }
  return 3;
}

}  // namespace

int max_contact_points(const ContactModel& contacts) {
  int points = 0;
  for (const ContactPair& pair : contacts.pairs) {
    const ContactShapeKind a = contacts.geometries[pair.geometry_a].shape.kind;
    const ContactShapeKind b = contacts.geometries[pair.geometry_b].shape.kind;
    if (a == ContactShapeKind::sphere || b == ContactShapeKind::sphere) points += 1;
    else if (a == ContactShapeKind::plane || b == ContactShapeKind::plane) points += 8;
    else points += 16;
  }
  return points;
}

int detect_contacts(const Model& model, const Data& data, const ContactModel& contacts, std::span<ContactPoint> out) {
  (void)model;
  int count = 0;
  int overflow = 0;
  for (int p = 0; p < static_cast<int>(contacts.pairs.size()); ++p) {
    const ContactPair& pair = contacts.pairs[p];
    const ContactGeometry& geometry_a = contacts.geometries[pair.geometry_a];
    const ContactGeometry& geometry_b = contacts.geometries[pair.geometry_b];
    const bool swapped = kind_rank(geometry_a.shape.kind) > kind_rank(geometry_b.shape.kind);
    const ContactGeometry& first = swapped ? geometry_b : geometry_a;
    const ContactGeometry& second = swapped ? geometry_a : geometry_b;
    const PlacedShape a{first.shape, data.X_world_link[first.link] * first.X_link_shape};
    const PlacedShape b{second.shape, data.X_world_link[second.link] * second.X_link_shape};
    PointWriter writer(out, count, p, geometry_a.link, geometry_b.link, swapped, b.axis(0), b.axis(1),
                       contacts.margin);
    using K = ContactShapeKind;
    const K ka = first.shape.kind, kb = second.shape.kind;
    if (kb == K::plane) {
      if (ka == K::sphere) sphere_plane(a, b, writer);
      else if (ka == K::box) box_plane(a, b, writer);
      else if (ka == K::cylinder) cylinder_plane(a, b, writer);
    } else if (ka == K::sphere && kb == K::sphere) {
      sphere_sphere(a, b, writer);
    } else if (ka == K::sphere && kb == K::box) {
      sphere_box(a, b, writer);
    } else if (ka == K::box && kb == K::box) {
      box_box(a, b, contacts.margin, writer);
    }
    overflow += writer.overflow();
  }
  return overflow > 0 ? static_cast<int>(out.size()) + 1 : count;
}

}  // namespace heavesim
