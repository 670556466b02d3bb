#include "synthesis/growth_queries.h"

#include "geometry/errors.h"
#include "synthesis/segment2d.h"

#include <algorithm>
#include <limits>

namespace dg {

namespace {

constexpr double element_found = 1, guide_found = 2, link_found = 3;

// The closest thing found by a query: kind code, distance (or ray parameter), point, id.
struct Found {
  double kind = 0;
  double distance = std::numeric_limits<double>::infinity();
  Vec2 point = Vec2::Zero();
  double id = -1;
  std::size_t edge = 0;
};

// The id a filtered query (`?DLI`, ...) asks for, or nothing.
using IdFilter = std::optional<double>;

bool passes(const IdFilter& filter, double id) { return !filter || *filter == id; }

bool selectable(const GuideEnvironment& environment, const LinkEdge& link, const IdFilter& filter) {
  return passes(filter, static_cast<double>(link.link)) && (!environment.available || environment.available(link.link));
}

// Outgoing links that start on `edge`, in scene order.
std::vector<std::size_t> links_on_edge(const GuideEnvironment& environment, std::size_t edge) {
  std::vector<std::size_t> links;
  for (const LinkEdge& link : environment.links)
    if (link.edge == edge) links.push_back(link.link);
  return links;
}

Found nearest_link(const Vec2& p, const GuideEnvironment& environment, const IdFilter& filter) {
  Found best;
  for (const LinkEdge& link : environment.links) {
    if (!selectable(environment, link, filter)) continue;
    const Vec2 point = link.a + closest_parameter(p, link.a, link.b) * (link.b - link.a);
    const double distance = (point - p).norm();
    if (distance < best.distance) best = {link_found, distance, point, static_cast<double>(link.link), link.edge};
  }
  return best;
}

Found nearest_guide_edge(const Vec2& p, const GuideEnvironment& environment, const IdFilter& filter = {}) {
  Found best;
  const std::vector<Vec2>& polygon = *environment.polygon;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (!passes(filter, static_cast<double>(i))) continue;
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    const Vec2 point = a + closest_parameter(p, a, b) * (b - a);
    const double distance = (point - p).norm();
    if (distance < best.distance) best = {guide_found, distance, point, static_cast<double>(i), i};
  }
  return best;
}

// First guide edge met by [p, q] with parameter above min_t; distance holds the parameter.
Found first_guide_edge(const Vec2& p, const Vec2& q, double min_t, const GuideEnvironment& environment,
                       const IdFilter& filter = {}) {
  Found best;
  const std::vector<Vec2>& polygon = *environment.polygon;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (!passes(filter, static_cast<double>(i))) continue;
    const auto crossing = cross_segments(p, q, polygon[i], polygon[(i + 1) % polygon.size()]);
    if (crossing && crossing->s > min_t && crossing->s < best.distance)
      best = {guide_found, crossing->s, p + crossing->s * (q - p), static_cast<double>(i), i};
  }
  return best;
}

Found first_link_edge(const Vec2& p, const Vec2& q, double min_t, const GuideEnvironment& environment,
                      const IdFilter& filter) {
  Found best;
  for (const LinkEdge& link : environment.links) {
    if (!selectable(environment, link, filter)) continue;
    const auto crossing = cross_segments(p, q, link.a, link.b);
    if (crossing && crossing->s > min_t && crossing->s < best.distance)
      best = {link_found, crossing->s, p + crossing->s * (q - p), static_cast<double>(link.link), link.edge};
  }
  return best;
}

Found first_element(const Vec2& p, const Vec2& q, double min_t, const GuideEnvironment& environment,
                    const IdFilter& filter = {}) {
  Found best;
  if (const auto hit = environment.elements->first_hit(p, q, min_t, filter))
    best = {element_found, hit->t, hit->point, (*environment.elements)[hit->index].id, 0};
  return best;
}

// A guide edge that holds links reports as a link (its id the first link's index).
Found promote_link(Found found, const GuideEnvironment& environment) {
  if (found.kind != guide_found) return found;
  const std::vector<std::size_t> links = links_on_edge(environment, found.edge);
  if (!links.empty()) {
    found.kind = link_found;
    found.id = static_cast<double>(links.front());
  }
  return found;
}

// True when p lies outside the guide by more than rounding (points on the boundary are inside).
bool outside_guide(const Vec2& p, const GuideEnvironment& environment) {
  if (point_in_polygon(p, *environment.polygon)) return false;
  const Found edge = nearest_guide_edge(p, environment);
  return edge.distance > 1e-9 * (1 + p.cwiseAbs().maxCoeff());
}

Found closer(const Found& a, const Found& b) { return b.distance < a.distance ? b : a; }

// The ray length that leaves the guide from anywhere inside it.
double ray_length(const GuideEnvironment& environment) {
  Vec2 low = environment.polygon->front(), high = low;
  for (const Vec2& v : *environment.polygon) {
    low = low.cwiseMin(v);
    high = high.cwiseMax(v);
  }
  return 2 * (high - low).norm() + 1;
}

void prepend(Module& module, std::initializer_list<double> outputs) {
  module.parameters.insert(module.parameters.begin(), outputs.begin(), outputs.end());
}

// Answers a distance query; returns what it found.
Found answer_distance(Module& module, const TurtlePose& pose, const GuideEnvironment& environment, char target,
                      const IdFilter& filter) {
  const Vec2& p = pose.position;
  Found found;
  if (target == 'L') {
    found = nearest_link(p, environment, filter);
  } else if (target == 'G') {
    found = nearest_guide_edge(p, environment, filter);
  } else {
    found = promote_link(nearest_guide_edge(p, environment, filter), environment);
    if (const auto hit = environment.elements->nearest(p, filter); hit && hit->t < found.distance)
      found = {element_found, hit->t, hit->point, (*environment.elements)[hit->index].id, 0};
  }
  if (found.kind == 0) {
    prepend(module, {0, 0, 0, -1});
    return found;
  }
  const double beta = found.distance > 0 ? turn_toward(pose.heading_deg, found.point - p) : 0;
  prepend(module, {found.kind, found.distance, beta, found.id});
  return found;
}

// Answers a forward-distance query; returns what it found.
Found answer_ahead(Module& module, const TurtlePose& pose, const GuideEnvironment& environment, char target,
                   const IdFilter& filter) {
  const double length = ray_length(environment);
  const Vec2 p = pose.position, q = p + heading_vector(pose.heading_deg) * length;
  const double min_t = 1e-9;
  Found found;
  if (target == 'L') {
    found = first_link_edge(p, q, min_t, environment, filter);
  } else if (target == 'G') {
    found = first_guide_edge(p, q, min_t, environment, filter);
  } else {
    found = closer(promote_link(first_guide_edge(p, q, min_t, environment, filter), environment),
                   first_element(p, q, min_t, environment, filter));
  }
  if (found.kind == 0)
    prepend(module, {0, 0, -1});
  else
    prepend(module, {found.kind, found.distance * length, found.id});
  return found;
}

// Answers a collision query (`assigned`: ?XS or ?XSI, whose second input is idin).
std::optional<EdgeCrossing> answer_collision(Module& module, const TurtlePose& pose, GuideEnvironment& environment,
                                             double element_id, bool assigned, const IdFilter& filter) {
  const double length = collision_query_length(module, false, pose.scale);
  const Vec2 p = pose.position, q = p + heading_vector(pose.heading_deg) * length;
  const double min_t = 1e-6;
  const Found edge = promote_link(first_guide_edge(p, q, min_t, environment, filter), environment);
  Found found = closer(edge, first_element(p, q, min_t, environment, filter));
  if (found.kind == 0 && !filter && outside_guide(p, environment)) {  // escaped (e.g. through a vertex): the guide stops it
    found = nearest_guide_edge(p, environment);
    found.point = p;
  }
  std::optional<EdgeCrossing> crossing;
  if (found.kind == link_found) {
    const std::vector<Vec2>& polygon = *environment.polygon;
    const Vec2& a = polygon[found.edge];
    const Vec2& b = polygon[(found.edge + 1) % polygon.size()];
    crossing = EdgeCrossing{links_on_edge(environment, found.edge), closest_parameter(found.point, a, b),
                            std::vector<double>(module.parameters.begin() + 1, module.parameters.end())};
  }
  if (found.kind == 0) environment.elements->insert({p, q, assigned ? module.parameters[1] : element_id});
  prepend(module, {found.kind, found.id});
  return crossing;
}

}  // namespace

bool is_growth_query(const std::string& symbol) {
  static const std::vector<std::string> known{"?DL",  "?DG",  "?DA",  "?NL",  "?NG", "?NA", "?X",  "?seed", "?DLI",
                                              "?DGI", "?DAI", "?NLI", "?NGI", "?NAI", "?XI", "?XS", "?XSI"};
  return std::find(known.begin(), known.end(), symbol) != known.end();
}

bool is_collision_query(const std::string& symbol) {
  return symbol == "?X" || symbol == "?XI" || symbol == "?XS" || symbol == "?XSI";
}

std::optional<double> assigned_id(const Module& module) {
  if ((module.symbol == "?XS" || module.symbol == "?XSI") && module.parameters.size() > 3) return module.parameters[3];
  return std::nullopt;
}

double collision_query_length(const Module& module, bool answered, double scale) {
  const std::size_t at = answered ? 2 : 0;
  if (module.parameters.size() <= at)
    throw InputError(module.symbol + " needs the length of the segment it tests as its first argument, like ?X(2)");
  return module.parameters[at] * scale;
}

QueryOutcome answer_query(Module& module, const TurtlePose& pose, GuideEnvironment& environment, const SeedStart& seed) {
  const std::string& symbol = module.symbol;
  if (!is_growth_query(symbol))
    throw InputError("unknown query module " + symbol +
                     " (known: ?DL ?DG ?DA ?NL ?NG ?NA ?X ?XS ?seed, and ?DLI ... ?XI ?XSI with an id filter)");
  const bool assigned = symbol == "?XS" || symbol == "?XSI";
  if (assigned && module.parameters.size() < 2)
    throw InputError(symbol + " needs the id it gives the tested segment as its second argument, like ?XS(2, 7)");
  const bool filtered = symbol.back() == 'I';
  IdFilter filter;
  if (filtered) {  // idtest: the first input (?XI: the second, after delta; ?XSI: the third, after idin)
    const std::size_t at = symbol == "?XI" ? 1 : symbol == "?XSI" ? 2 : 0;
    static const char* const ordinal[] = {"first", "second", "third"};
    if (module.parameters.size() <= at)
      throw InputError(symbol + " needs the id it looks for as its " + ordinal[at] + " argument");
    filter = module.parameters[at];
  }
  QueryOutcome outcome;
  if (is_collision_query(symbol)) {
    outcome.crossing = answer_collision(module, pose, environment, seed.element_id, assigned, filter);
  } else if (symbol == "?seed") {
    if (!seed.values.empty()) module.parameters = seed.values;
    prepend(module, {seed.pose.position.x(), seed.pose.position.y(), seed.pose.heading_deg});
  } else {
    const Found found = symbol[1] == 'D' ? answer_distance(module, pose, environment, symbol[2], filter)
                                         : answer_ahead(module, pose, environment, symbol[2], filter);
    if (symbol[2] == 'L' && found.kind == link_found) outcome.selected_link = static_cast<std::size_t>(found.id);
  }
  return outcome;
}

}  // namespace dg
