#include "geometry/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>

namespace dg {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Adds every triangle in order (face i = triangle i); false when the halfedge structure
// rejects one (non-manifold edge or vertex, inconsistent orientation).
bool build_halfedge_mesh(const std::vector<Point>& points, const std::vector<std::vector<std::size_t>>& polygons,
                         Mesh& mesh) {
  mesh.clear();
  mesh.reserve(static_cast<Mesh::size_type>(points.size()), 0, static_cast<Mesh::size_type>(polygons.size()));
  for (const Point& p : points) mesh.add_vertex(p);
  for (const auto& polygon : polygons) {
    const Mesh::Face_index f = mesh.add_face(Mesh::Vertex_index(static_cast<Mesh::size_type>(polygon[0])),
                                             Mesh::Vertex_index(static_cast<Mesh::size_type>(polygon[1])),
                                             Mesh::Vertex_index(static_cast<Mesh::size_type>(polygon[2])));
    if (f == Mesh::null_face()) return false;
  }
  return true;
}

}  // namespace

SelfIntersections find_self_intersections(const TriangleMesh& mesh, const SelfIntersectionOptions& options) {
  std::vector<Point> points;
  points.reserve(mesh.positions.size());
  for (const Vec3& p : mesh.positions) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});

  SelfIntersections result;
  Mesh halfedge_mesh;
  if (!build_halfedge_mesh(points, polygons, halfedge_mesh)) {
    // Duplicates vertices (and flips polygons) until the soup is a halfedge mesh; polygon
    // order is kept, so face i is still triangle i.
    result.non_manifold_input = true;
    PMP::orient_polygon_soup(points, polygons);
    build_halfedge_mesh(points, polygons, halfedge_mesh);
  }
  result.any = PMP::does_self_intersect<CGAL::Parallel_if_available_tag>(halfedge_mesh);
  if (!result.any || options.max_pairs == 0) return result;

  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> faces;
  PMP::self_intersections<CGAL::Parallel_if_available_tag>(
      halfedge_mesh, std::back_inserter(faces),
      CGAL::parameters::maximum_number(static_cast<unsigned>(options.max_pairs)));
  for (const auto& [a, b] : faces) {
    const auto i = static_cast<std::uint32_t>(a.idx()), j = static_cast<std::uint32_t>(b.idx());
    result.pairs.emplace_back(std::min(i, j), std::max(i, j));
  }
  std::sort(result.pairs.begin(), result.pairs.end());
  result.pairs.erase(std::unique(result.pairs.begin(), result.pairs.end()), result.pairs.end());
  if (result.pairs.size() >= options.max_pairs) {
    result.pairs.resize(options.max_pairs);
    result.capped = true;
  }
  return result;
}

}  // namespace dg
