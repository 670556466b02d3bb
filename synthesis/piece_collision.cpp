#include "synthesis/piece_collision.h"

#include <embree3/rtcore.h>

#include <atomic>
#include <cmath>
#include <stdexcept>

namespace dg {
namespace {

// A triangle soup as Embree user geometry (bounds only: the collision query needs no more).
// Its scene is built on first use: most placed pieces are never queried against.
struct Soup {
  TriangleMesh mesh;
  BoundingBox box;
  RTCScene scene = nullptr;

  explicit Soup(const TriangleMesh& piece) : mesh(piece), box(piece.bounds()) {}
  Soup(const Soup&) = delete;
  Soup& operator=(const Soup&) = delete;
  ~Soup() {
    if (scene) rtcReleaseScene(scene);
  }
};

void triangle_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* mesh = static_cast<const TriangleMesh*>(args->geometryUserPtr);
  BoundingBox box;
  for (const Vec3& p : mesh->corners(args->primID)) box.add(p);
  // Padded a little so float rounding never loses a touching pair.
  auto lower = [](double v) { return static_cast<float>(v) - 1e-4f * (1.0f + std::abs(static_cast<float>(v))); };
  auto upper = [](double v) { return static_cast<float>(v) + 1e-4f * (1.0f + std::abs(static_cast<float>(v))); };
  RTCBounds* out = args->bounds_o;
  out->lower_x = lower(box.min.x()), out->lower_y = lower(box.min.y()), out->lower_z = lower(box.min.z());
  out->upper_x = upper(box.max.x()), out->upper_y = upper(box.max.y()), out->upper_z = upper(box.max.z());
}

// A scene of `mesh` for collision queries. Low build quality (Morton builder): a piece is built
// for a few queries only, and the query reports every overlapping pair whatever the tree, so
// the faster build wins (100k-triangle pipe tree: half the time per variant).
RTCScene make_scene(RTCDevice device, const TriangleMesh& mesh) {
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_LOW);
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(mesh.triangles.size()));
  rtcSetGeometryUserData(geometry, const_cast<TriangleMesh*>(&mesh));
  rtcSetGeometryBoundsFunction(geometry, triangle_bounds, nullptr);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

// Slack of the crossing test in barycentric and segment parameters: pieces that only touch (an
// edge ending on a face, edges meeting) cross within rounding, and verify counts touching as
// intersecting.
constexpr double kTouchSlack = 1e-9;

// Point where segment a-b crosses or touches triangle (p, q, r), if it does (Moller-Trumbore,
// parameters within kTouchSlack of the closed ranges).
bool segment_hits_triangle(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, const Vec3& r, Vec3& hit) {
  const Vec3 d = b - a, e1 = q - p, e2 = r - p;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);
  const double scale = d.norm() * e1.norm() * e2.norm();
  if (std::abs(det) <= 1e-12 * scale) return false;  // parallel or coplanar
  const double inv = 1.0 / det;
  const Vec3 s = a - p;
  const double u = inv * s.dot(h);
  if (u < -kTouchSlack || u > 1.0 + kTouchSlack) return false;
  const Vec3 qv = s.cross(e1);
  const double v = inv * d.dot(qv);
  if (v < -kTouchSlack || u + v > 1.0 + kTouchSlack) return false;
  const double t = inv * e2.dot(qv);
  if (t < -kTouchSlack || t > 1.0 + kTouchSlack) return false;
  hit = a + t * d;
  return true;
}

struct Query {
  const TriangleMesh* piece;
  const TriangleMesh* placed;
  const SeamContact* at_seam;
  std::atomic<bool> found{false};

  bool near_seam(const Vec3& x) const { return (*at_seam)(x); }

  // Any edge of one triangle crossing the other away from the seams.
  bool crossing(std::size_t a, std::size_t b) const {
    const auto ta = piece->corners(a), tb = placed->corners(b);
    Vec3 hit;
    for (int k = 0; k < 3; ++k) {
      if (segment_hits_triangle(ta[k], ta[(k + 1) % 3], tb[0], tb[1], tb[2], hit) && !near_seam(hit)) return true;
      if (segment_hits_triangle(tb[k], tb[(k + 1) % 3], ta[0], ta[1], ta[2], hit) && !near_seam(hit)) return true;
    }
    return false;
  }
};

void on_collision(void* user, RTCCollision* collisions, unsigned count) {
  auto* query = static_cast<Query*>(user);
  for (unsigned i = 0; i < count && !query->found.load(std::memory_order_relaxed); ++i)
    if (query->crossing(collisions[i].primID0, collisions[i].primID1)) query->found.store(true, std::memory_order_relaxed);
}

bool boxes_overlap(const BoundingBox& a, const BoundingBox& b, double margin) {
  for (int k = 0; k < 3; ++k)
    if (a.min[k] > b.max[k] + margin || b.min[k] > a.max[k] + margin) return false;
  return true;
}

}  // namespace

struct PieceCollisions::Impl {
  RTCDevice device = nullptr;
  double margin = 0.0;
  std::vector<std::unique_ptr<Soup>> placed;

  // The scene of `mesh` in `scene`, built on the first call.
  RTCScene scene_of(const TriangleMesh& mesh, RTCScene& scene) const {
    if (!scene) scene = make_scene(device, mesh);
    return scene;
  }

  // Whether `piece` (bounds `box`, scene built into `scene` when first needed) crosses a placed
  // piece away from the seams.
  bool collides(const TriangleMesh& piece, const BoundingBox& box, RTCScene& scene, const SeamContact& at_seam) const {
    for (const auto& soup : placed) {
      if (soup->mesh.triangles.empty() || !boxes_overlap(box, soup->box, margin)) continue;
      Query query{&piece, &soup->mesh, &at_seam};
      rtcCollide(scene_of(piece, scene), scene_of(soup->mesh, soup->scene), on_collision, &query);
      if (query.found.load()) return true;
    }
    return false;
  }
};

PieceCollisions::PieceCollisions(double margin) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("Embree: cannot create a device");
  impl_->margin = margin;
}

PieceCollisions::~PieceCollisions() {
  impl_->placed.clear();  // the scenes go before their device
  rtcReleaseDevice(impl_->device);
}

bool PieceCollisions::collides(const TriangleMesh& piece, const SeamContact& at_seam) const {
  if (piece.triangles.empty()) return false;
  RTCScene scene = nullptr;
  const bool found = impl_->collides(piece, piece.bounds(), scene, at_seam);
  if (scene) rtcReleaseScene(scene);
  return found;
}

bool PieceCollisions::add_unless_collides(const TriangleMesh& piece, const SeamContact& at_seam) {
  auto soup = std::make_unique<Soup>(piece);
  if (!piece.triangles.empty() && impl_->collides(soup->mesh, soup->box, soup->scene, at_seam)) return false;
  impl_->placed.push_back(std::move(soup));
  return true;
}

void PieceCollisions::add(const TriangleMesh& piece) { impl_->placed.push_back(std::make_unique<Soup>(piece)); }

std::size_t PieceCollisions::pieces() const { return impl_->placed.size(); }

}  // namespace dg
