#include "tools/dockgrammar/grammar_report.h"
#include "tools/dockgrammar/model_summary.h"

#include "geometry/atomic_file.h"
#include "geometry/model_io.h"
#include "geometry/submesh.h"
#include "geometry/topology.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_seams.h"
#include "grammar/seam_curve.h"
#include "synthesis/shape_derivation.h"
#include "tools/dockgrammar/docking_site_picture.h"
#include "tools/dockgrammar/not_built.h"
#include "tools/dockgrammar/pictures.h"
#include "tools/dockgrammar/symmetry_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace dg::cli {
namespace {

// Clouds drawn on the bundled facade gave its whole grid from about this many points per
// occupied voxel (3.0 to 8.8 did; from 2 to 3 two samples of as many points gave all or part of
// it, 60k points at 1.4 nothing). Twice r gave 2.1 to 3.2 times the points per voxel (the facade
// at 60k and 150k points, the corpus building scan).
constexpr double kDensePointsPerVoxel = 3.0;

// ... and up to this much scan noise (rms off the surface, fraction of eps: 0.11 did, 0.13 lost a
// row, 0.15 gave no symmetry; at an r that brought the noise to 0.10 eps, 0.13 and 0.15 gave it).
constexpr double kQuietNoiseEps = 0.11, kTargetNoiseEps = 0.10;

// Scatter that grows by more than this factor from neighbourhoods of 2 eps to 4 eps is surface
// detail rather than scan noise (noisy facade scans: 1.07; the corpus building scan: 2.2).
constexpr double kNoiseGrowthLimit = 1.25;

// Points of a cloud per occupied voxel of its voxel surface.
double points_per_voxel(const PreparedModel& prepared) {
  const std::size_t voxels = prepared.surface.cell_count();
  return voxels == 0 ? 0.0 : static_cast<double>(prepared.model.cloud.positions.size()) / static_cast<double>(voxels);
}

// A cloud's scatter off the surface (rms) as a fraction of eps.
double noise_eps(const PreparedModel& prepared) { return prepared.cloud_sampling.noise / prepared.surface.eps(); }

// "N points, D per occupied voxel, scatter X eps" and hints to use larger voxels: below
// kDensePointsPerVoxel, and above kQuietNoiseEps when the scatter is scan noise (the r that brings
// it to kTargetNoiseEps: noise in eps falls as eps = r / 4 grows).
std::string cloud_density_text(const PreparedModel& prepared) {
  const double density = points_per_voxel(prepared), noise = noise_eps(prepared);
  const std::size_t points = prepared.model.cloud.positions.size();
  std::string text = fmt::format("{} point{}, {:.1f} per occupied voxel, {:.2f} eps off the surface (rms)", points,
                                 points == 1 ? "" : "s", density, noise);
  if (density < kDensePointsPerVoxel)
    text += " (sparse: clouds drawn on the bundled facade gave its whole grid from 3 points per voxel; from 2 to 3, all "
            "or part of it as the points fell; a larger -r gives larger voxels, eps = r / 4, and 2 to 3 times the points "
            "per voxel for twice r)";
  if (noise <= kQuietNoiseEps) return text;
  if (prepared.cloud_sampling.noise_wide > kNoiseGrowthLimit * prepared.cloud_sampling.noise)
    return text + fmt::format(" (rough: {:.2f} eps within {} eps, so surface detail rather than scan noise, which a "
                              "larger -r does not make smaller)",
                              prepared.cloud_sampling.noise_wide / prepared.surface.eps(), 2.0 * kCloudStatisticsRadius);
  return text + fmt::format(" (noisy: clouds drawn on the bundled facade gave its whole grid up to 0.11 eps of noise, a row "
                            "less at 0.13, nothing at 0.15; noise in eps falls as r grows: -r {:.3g} gives about {:.2f} eps)",
                            prepared.surface.r() * noise / kTargetNoiseEps, kTargetNoiseEps);
}

// NAME of the model's NAME.grammar.json, NAME.report.md and pictures.
std::string model_stem(const AnalysisReport& report) { return report.grammar_path.stem().stem().string(); }

// Docking sites that never became a pair of locations in the context-free stage, e.g. "; 171
// more give no pair of locations (...)"; empty when there are none.
std::string unpaired_sites_text(const AnalysisReport& report) {
  const ContextFreeStats& stats = report.context_free;
  const std::size_t accounted = stats.sites_used + stats.sites_without_fit + stats.sites_slippable + stats.sites_stray_seam;
  if (report.docking.sites.size() <= accounted) return "";
  return fmt::format("; {} more give no pair of locations (the docker and its image fall on one location, or the "
                     "limit of {} locations, largest dockers first, was reached)",
                     report.docking.sites.size() - accounted, ContextFreeOptions{}.max_nodes);
}

// "; 4 more have a site whose image also runs where nothing is replaced" when such sites were
// dropped; empty otherwise.
std::string stray_seam_text(const ContextFreeStats& stats) {
  if (stats.sites_stray_seam == 0) return "";
  return fmt::format("; {} more have a site whose image also runs where nothing is replaced", stats.sites_stray_seam);
}

// "N non-terminal(s) were dropped because ..." for non-terminals no derivation reaches.
std::string unreachable_text(const ContextFreeStats& stats) {
  return fmt::format("{} non-terminal(s) were dropped because no derivation reaches them from the axiom (their sites "
                     "conflict with the sites the axiom uses)",
                     stats.unreachable_nonterminals);
}

// "N production(s) were dropped because ..." for alternatives that would only move the model.
std::string moving_text(const ContextFreeStats& stats) {
  return fmt::format("{} production(s) were dropped because putting one at another site of its non-terminal moves "
                     "the whole model (the rest of the model around each of those sites is the same, moved)",
                     stats.productions_moving_the_model);
}

// "N pair(s) of site locations ... kept apart" when the loop rule left related locations in
// different non-terminals.
std::string kept_apart_text(const ContextFreeStats& stats) {
  return fmt::format("{} pair(s) of docking-site locations related by a symmetry were kept in separate non-terminals: the "
                     "docker of one, put in place of the other's, would leave the model in more parts (it joins fewer of "
                     "the site's loops, such as the stems of a tree, than the docker it replaces)",
                     stats.locations_kept_apart);
}

// " 16 sites sat up to 0.13 eps off ..." when the fit test aligned locations on their
// non-terminal's reference seam; empty otherwise.
std::string aligned_text(const ContextFreeStats& stats, double eps) {
  if (stats.locations_aligned == 0) return "";
  const bool one = stats.locations_aligned == 1;
  return fmt::format(" {} site{} sat up to {:.2g} eps off the motion relating {} to {} non-terminal's first site and {} "
                     "aligned on its seam before the fit test (sites placed by hand a little off the pitch).",
                     stats.locations_aligned, one ? "" : "s", stats.largest_alignment / eps, one ? "it" : "them",
                     one ? "its" : "their", one ? "was" : "were");
}

// "; 12 production(s) were dropped because ..." when context-free rules were dropped for
// opening holes in a closed model or for being unreachable from the axiom; empty otherwise.
std::string dropped_rules_text(const ContextFreeStats& stats) {
  std::string text;
  if (stats.productions_with_holes > 0 || stats.axiom_with_holes)
    text += fmt::format("; {} production(s){} were dropped because their pieces hold triangles that cleaning drops (they "
                        "would open holes in the closed model)",
                        stats.productions_with_holes, stats.axiom_with_holes ? " and the axiom" : "");
  if (stats.productions_moving_the_model > 0) text += "; " + moving_text(stats);
  if (stats.unreachable_nonterminals > 0) text += "; " + unreachable_text(stats);
  return text;
}

// A note on the units a direction keeps once in its head and tail, e.g. " (1 unit kept once in
// the head: it differs a little from the repeated unit or lies where no plane may cut)"; empty
// when it keeps none.
std::string kept_units_text(const GridDirection& d) {
  const std::string split = d.split_unit ? "1 unit split between the ends: its end lies before the first plane, its "
                                           "beginning after the last"
                                         : "";
  const int head = d.head_units - (d.split_unit ? 1 : 0);
  if (head + d.tail_units == 0) return split.empty() ? "" : fmt::format(" ({})", split);
  auto units = [](int n) { return fmt::format("{} unit{}", n, n == 1 ? "" : "s"); };
  std::string kept;
  if (head > 0) kept = units(head) + " kept once in the head";
  if (d.tail_units > 0) kept += kept.empty() ? units(d.tail_units) + " kept once in the tail" : fmt::format(" and {} in the tail", d.tail_units);
  const bool one = head + d.tail_units == 1;
  return fmt::format(" ({}{}: {} a little from the repeated unit or {} within r of the model's ends, where no plane may cut)",
                     split.empty() ? "" : split + "; ", kept, one ? "it differs" : "they differ", one ? "lies" : "lie");
}

// Separate parts (vertex-connected components of `mesh`) among the listed triangles.
std::size_t parts_among(const std::vector<std::uint32_t>& triangles, const TriangleMesh& mesh) {
  std::size_t count = 0;
  if (!triangles.empty()) triangle_components(submesh(mesh, std::vector<std::size_t>(triangles.begin(), triangles.end())), &count);
  return count;
}

// The separate parts a direction keeps whole, e.g. "4 separate parts kept whole (2 placed with the
// head, 2 moved with the tail)"; empty when it keeps none.
std::string whole_parts_text(const GridDirection& d, const TriangleMesh& mesh) {
  if (d.whole_in_head.empty() && d.whole_in_tail.empty()) return "";
  const std::size_t head = parts_among(d.whole_in_head, mesh), tail = parts_among(d.whole_in_tail, mesh);
  return fmt::format("{} separate part{} kept whole ({} placed with the head, {} moved with the tail)", head + tail,
                     head + tail == 1 ? "" : "s", head, tail);
}

// "; the planes pass by 4 separate parts kept whole (...)" for the summary line, or empty.
std::string whole_parts_note(const GridDirection& d, const TriangleMesh& mesh) {
  const std::string parts = whole_parts_text(d, mesh);
  return parts.empty() ? "" : "; the planes pass by " + parts;
}

// A grid direction's generator in the model file's coordinates: "t = ..." for a translation,
// the screw's angle, axis and rise.
std::string grid_motion_text(const GridDirection& d, const PreparedModel& prepared) {
  return describe_motion(shifted_motion(d.motion, prepared.origin), d.motion.angle() > 1e-9 ? "screw" : "translation",
                         prepared.surface.eps());
}

// Offset of a direction's first cut plane along its direction in the model file's coordinates.
double first_cut(const GridDirection& d, const Vec3& origin) { return d.cut + d.direction.dot(origin); }

std::string counts_text(const GridRule& grid) { return fmt::format("{}", fmt::join(exemplar_counts(grid), "x")); }

// For a 1-grid whose motion is that of a direction of an earlier grid (a further run along it,
// grammar/grid_rules.h): that grid's index and the direction's.
std::optional<std::pair<std::size_t, std::size_t>> further_run_of(const AnalysisReport& report, std::size_t grid_index) {
  const std::vector<GridWithPieces>& grids = report.grammar.grids;
  if (grids[grid_index].rule.directions.size() != 1) return std::nullopt;
  const GridDirection& run = grids[grid_index].rule.directions.front();
  for (std::size_t g = 0; g < grid_index; ++g)
    for (std::size_t i = 0; i < grids[g].rule.directions.size(); ++i)
      if (grids[g].rule.directions[i].symmetry == run.symmetry) return std::pair{g, i};
  return std::nullopt;
}

// For a grid whose units along one direction group those of an earlier grid's (grouped_units,
// grammar/grid_rules.h): that grid's index and how it groups them.
std::optional<std::pair<std::size_t, GroupedUnits>> grouped_units_of(const AnalysisReport& report, std::size_t grid_index) {
  const std::vector<GridWithPieces>& grids = report.grammar.grids;
  for (std::size_t g = 0; g < grid_index; ++g)
    if (const std::optional<GroupedUnits> grouped = grouped_units(grids[grid_index].rule, grids[g].rule)) return std::pair{g, *grouped};
  return std::nullopt;
}

// For a grid of grouped units (grouped_units_of): which grid's units it groups, how many, and
// why that grid keeps most of them once. Else empty.
std::string grouped_units_text(const AnalysisReport& report, std::size_t grid_index) {
  const auto of = grouped_units_of(report, grid_index);
  if (!of) return "";
  const GridRule& earlier = report.grammar.grids[of->first].rule;
  const GridDirection& d = earlier.directions[of->second.direction];
  return fmt::format("groups the units of {}'s direction {} by {}: {} keeps {} of its {} units in that direction once, "
                     "because the model changes every {} units (such as a pilaster after every third window column, or a "
                     "bearer under every third board), while this grid's units repeat; resizing it adds or removes whole "
                     "groups. It is an alternative to {}, not resized together with it",
                     earlier.name, of->second.direction + 1, of->second.factor, earlier.name, min_units(d), d.count,
                     of->second.factor, earlier.name);
}

// For a further run (further_run_of): which grid's, and where along the motion both runs' planes
// lie ("along the motion of ..."). Else empty.
std::string further_run_text(const AnalysisReport& report, std::size_t grid_index) {
  const std::optional<std::pair<std::size_t, std::size_t>> of = further_run_of(report, grid_index);
  if (!of) return "";
  const GridRule& first = report.grammar.grids[of->first].rule;
  const GridDirection& d = first.directions[of->second];
  const GridDirection& run = report.grammar.grids[grid_index].rule.directions.front();
  const Vec3& origin = report.prepared.origin;
  return fmt::format("along the motion of {}'s direction {}: its planes lie from {:.6g} to {:.6g} along it, {}'s from "
                     "{:.6g} to {:.6g}, and what lies between is mostly not a copy of the units",
                     first.name, of->second + 1, first_cut(run, origin), first_cut(run, origin) + run.count * run.pitch,
                     first.name, first_cut(d, origin), first_cut(d, origin) + d.count * d.pitch);
}

// Components with 6 significant digits (more for survey coordinates).
std::string vec(const Vec3& v) { return fitted_vector_text(v, 6); }

// Every stage's time in pipeline order: preparation, symmetry detection, grammar.
std::vector<StageTiming> stage_timings(const AnalysisReport& report) {
  std::vector<StageTiming> timings = report.prepared.timings;
  for (const StageTiming& t : report.symmetries.timings) timings.push_back({"symmetry " + t.stage, t.seconds});
  timings.insert(timings.end(), report.grammar_timings.begin(), report.grammar_timings.end());
  return timings;
}

nlohmann::json timings_json(const AnalysisReport& report) {
  nlohmann::json timings = nlohmann::json::object();
  for (const StageTiming& t : stage_timings(report)) timings[t.stage] = t.seconds;
  return timings;
}

nlohmann::json operation_counts(const DockingSiteResult& docking) {
  nlohmann::json counts = {{"insert", 0}, {"delete", 0}, {"replace", 0}};
  for (const DockingSite& s : docking.sites) counts[operation_name(s.operation)] = counts[operation_name(s.operation)].get<int>() + 1;
  return counts;
}

nlohmann::json docking_sites_json(const AnalysisReport& report) {
  nlohmann::json sites = nlohmann::json::array();
  const double total = report.prepared.surface.total_area();
  for (const DockingSite& s : report.docking.sites)
    sites.push_back({{"symmetry", s.symmetry + 1},
                     {"inverse", s.inverse},
                     {"operation", operation_name(s.operation)},
                     {"site_cells", s.site.size()},
                     {"docker_fraction", s.docker_area / total},
                     {"secondary_docker_fraction", s.secondary_docker_area / total},
                     {"regions", s.regions},
                     {"collides", s.collides},
                     {"stray_seam", s.stray_seam},
                     {"slippable_motions", s.slippable_motions},
                     {"slippable", s.slippable}});
  return sites;
}

nlohmann::json production_json(const ContextFreeGrammar& g, const ShapeProduction& p) {
  nlohmann::json children = nlohmann::json::array();
  for (const ChildSlot& c : p.children) children.push_back(g.nonterminals[c.nonterminal].name);
  return {{"lhs", p.lhs == kNoProduction ? "axiom" : g.nonterminals[p.lhs].name},
          {"children", children},
          {"terminal_triangles", p.terminal.triangles.size()},
          {"terminal_points", p.terminal_points.positions.size()}};
}

nlohmann::json nonterminals_json(const ContextFreeGrammar& g) {
  nlohmann::json out = nlohmann::json::array();
  for (const ShapeNonterminal& n : g.nonterminals)
    out.push_back({{"name", n.name}, {"sites", n.sites}, {"seam_misfit", n.seam_misfit}});
  return out;
}

nlohmann::json productions_json(const ContextFreeGrammar& g) {
  nlohmann::json out = nlohmann::json::array();
  if (g.empty()) return out;
  out.push_back(production_json(g, g.axiom));
  for (const ShapeProduction& p : g.productions) out.push_back(production_json(g, p));
  return out;
}

// Which rules `generate` uses by default (upright orientation about the grammar's up axis).
std::string generate_rules_text(const AnalysisReport& report) {
  ShapeDerivationOptions upright;
  upright.up = picture_options(exemplar_bounds(report.grammar), report.grammar.up_axis).camera.up.normalized();
  if (derivation_has_choice(report.grammar.context_free, upright)) {
    if (report.grammar.grids.empty()) return "generate makes random variants from them";
    std::string grids;
    for (const GridWithPieces& grid : report.grammar.grids) grids += (grids.empty() ? "" : ", ") + grid.rule.name;
    return fmt::format("generate makes random variants from them; generate --rules grid draws the counts of {} "
                       "instead, resize sets them", grids);
  }
  if (!derivation_has_choice(report.grammar.context_free, ShapeDerivationOptions{}))
    return std::string("no non-terminal has a second production of another shape (its locations are copies of one "
                       "another") +
           (report.context_free.productions_moving_the_model > 0 ? ", or the other shapes would only move the whole model"
                                                                 : "") +
           "), so they only rebuild the exemplar" +
           (report.grammar.grids.empty() ? ": generate has nothing to vary" : ": generate varies the grid");
  if (report.grammar.grids.empty())
    return "none changes the model while keeping its pieces upright: generate --orientation free uses them";
  return "none changes the model while keeping its pieces upright, so generate varies the grid; --orientation free "
         "--rules context-free uses them";
}

// Which symmetries gave docking sites: "the top K symmetries (...)", naming those left out.
std::string examined_symmetries_text(const DockingSiteStats& stats) {
  const std::size_t examined = stats.motions / 2;
  std::string text = fmt::format("the top {} symmetr{} (one per repetition family, largest r-symmetric area first", examined,
                                 examined == 1 ? "y" : "ies");
  if (stats.symmetries_skipped > 0)
    text += fmt::format("; {} more not examined: `--site-symmetries` examines more", stats.symmetries_skipped);
  return text + ")";
}

std::string context_free_markdown(const AnalysisReport& report) {
  const ContextFreeGrammar& cf = report.grammar.context_free;
  const nlohmann::json ops = operation_counts(report.docking);
  std::string md = fmt::format(
      "## Docking sites and context-free rules\n\n{} elementary docking sites over {}: {} insert, {} delete, "
      "{} replace ({} marked as colliding, {} slippable).{}\n\n",
      report.docking.sites.size(), examined_symmetries_text(report.docking.stats), ops["insert"].get<int>(),
      ops["delete"].get<int>(), ops["replace"].get<int>(),
      std::count_if(report.docking.sites.begin(), report.docking.sites.end(), [](const DockingSite& s) { return s.collides; }),
      std::count_if(report.docking.sites.begin(), report.docking.sites.end(), [](const DockingSite& s) { return s.slippable; }),
      report.docking.sites.empty() ? ""
                                   : fmt::format(" Picture: `{}.sites.png` (dockers filled, their docking sites dark around "
                                                 "them: insert green, delete red, replace blue, slippable grey; a docker "
                                                 "covering more than half the model is only outlined).",
                                                 model_stem(report)));
  if (cf.empty())
    return md + fmt::format("No context-free production was built: {} sites slide along themselves (dropped, as in the "
                            "paper), {} have a docker that, cut at one location, does not fit the seam of the other{}.\n\n",
                            report.context_free.sites_slippable, report.context_free.sites_without_fit,
                            stray_seam_text(report.context_free) + unpaired_sites_text(report) + dropped_rules_text(report.context_free));
  const bool points = cf.of_points();
  md += points ? "| non-terminal | exemplar sites | productions |\n|---|---|---|\n"
               : "| non-terminal | exemplar sites | productions | seam misfit (eps) |\n|---|---|---|---|\n";
  for (std::size_t n = 0; n < cf.nonterminals.size(); ++n) {
    const auto productions =
        std::count_if(cf.productions.begin(), cf.productions.end(), [&](const ShapeProduction& p) { return p.lhs == n; });
    md += points ? fmt::format("| {} | {} | {} |\n", cf.nonterminals[n].name, cf.nonterminals[n].sites, productions)
                 : fmt::format("| {} | {} | {} | {:.1e} |\n", cf.nonterminals[n].name, cf.nonterminals[n].sites, productions,
                               cf.nonterminals[n].seam_misfit / report.grammar.eps);
  }
  if (points)
    md += "\nPieces are the points of each docker (in its docking site's cells, those on the docker side of the seam); "
          "derived pieces collide when their points share a cube of edge eps away from their seams.\n";
  else
    md += fmt::format("\nSeam misfit: how far the seam of a site lies from that of the non-terminal's reference site, its "
                      "first or the one most others fit (up to {:g} eps fits; exact repeats show float rounding). Derived "
                      "pieces are welded within {:.1e} eps.{}\n",
                      kSeamFitFraction, seam_weld_tolerance(cf, report.grammar.eps) / report.grammar.eps,
                      aligned_text(report.context_free, report.grammar.eps));
  md += fmt::format("\nWith these rules: {}.\n", generate_rules_text(report));
  if (report.context_free.productions_moving_the_model > 0) md += "\n" + moving_text(report.context_free) + ".\n";
  if (report.context_free.unreachable_nonterminals > 0) md += "\n" + unreachable_text(report.context_free) + ".\n";
  if (report.context_free.locations_kept_apart > 0) md += "\n" + kept_apart_text(report.context_free) + ".\n";
  md += fmt::format("\nPicture: `{}.rules.png` (the exemplar rebuilt from its productions, each piece coloured by the "
                    "non-terminal it fills, the axiom's terminal light grey).\n",
                    model_stem(report));
  md += fmt::format("\nProductions (terminal {}, then the non-terminals they contain):\n\n", points ? "points" : "triangles");
  auto line = [&](const std::string& lhs, const ShapeProduction& p) {
    std::string children;
    for (const ChildSlot& c : p.children) children += " " + cf.nonterminals[c.nonterminal].name;
    return points ? fmt::format("- {} -> terminal({} points){}\n", lhs, p.terminal_points.positions.size(), children)
                  : fmt::format("- {} -> terminal({} triangles){}\n", lhs, p.terminal.triangles.size(), children);
  };
  md += line("axiom", cf.axiom);
  for (const ShapeProduction& p : cf.productions) md += line(cf.nonterminals[p.lhs].name, p);
  return md + "\n";
}

// The model's materials and whether symmetries had to respect them.
std::string materials_paragraph(const PreparedModel& prepared) {
  const std::vector<Material>& materials = prepared.model.materials;
  if (materials.empty()) return "";
  std::string names;
  for (const Material& m : materials) names += fmt::format("{}`{}`", names.empty() ? "" : ", ", m.name);
  if (!prepared.materials_matched())
    return fmt::format("Materials ({}): {}. They are kept on every piece. Symmetries are geometric; materials need not "
                       "match (`--match-materials`).\n\n",
                       materials.size(), names);
  std::string groups;
  for (const std::vector<std::string>& group : material_groups(prepared))
    groups += fmt::format(" `{}` count as one (`--same-material`).", fmt::join(group, "`, `"));
  return fmt::format("Materials ({}): {}. They are kept on every piece. Symmetries map every material onto itself and "
                     "borders between materials are feature lines (`--match-materials`).{}\n\n",
                     materials.size(), names, groups);
}

// The measured suggestion to match materials, or, when analyze went on with it, what it did;
// empty when analyze made none. `quote` encloses option names (a backtick in Markdown).
std::string material_hint_text(const AnalysisReport& report, std::string_view quote = "") {
  if (!report.material_hint) return "";
  const MaterialHint& hint = *report.material_hint;
  std::string grids;
  for (const std::vector<int>& counts : hint.grid_counts)
    grids += fmt::format("{}a {}-grid {}", grids.empty() ? "" : ", ", counts.size(), fmt::join(counts, " x "));
  std::string description = "the model's repeats are drawn in materials", flags;
  if (hint.groups.empty()) {
    flags = "--match-materials";
  } else {
    std::string names;
    for (const std::vector<std::string>& group : hint.groups) {
      flags += fmt::format("{}--same-material '{}'", flags.empty() ? "" : " ", fmt::join(group, ","));
      names += fmt::format("{}{}", names.empty() ? "" : "; ", fmt::join(group, ","));
    }
    description += fmt::format(", some of which take one another's place at random ({})", names);
  }
  if (hint.applied)
    return fmt::format("geometry alone gave no grid; {}, so analyze went on as with {}{}{}, which gives {} ({}--geometry-only{} "
                       "keeps to geometry)",
                       description, quote, flags, quote, grids, quote, quote);
  return fmt::format("{}: {}{}{} gives {}", description, quote, flags, quote, grids);
}

// Whether analyze went on with the materials matched as the material hint found.
bool materials_applied(const AnalysisReport& report) { return report.material_hint && report.material_hint->applied; }

// Tolerances of cell matching that the symmetries were found with.
CellTolerances match_tolerances(const AnalysisReport& report) {
  return cell_tolerances(report.symmetries.region, report.prepared.model.is_point_cloud());
}

// The suggestion to widen --tolerance, when analyze made one; empty otherwise.
// When no grid was found: the repeating translation with the most r-symmetric area (the one a
// reader most likely expected a grid from) and why it gave none, or "" when there is none or it
// is named elsewhere (by the tolerance hint, or as a repeat the grids leave unused under "Not
// yet built", which takes families of at least GridOptions::min_repeats repeats).
std::string strongest_translation_text(const AnalysisReport& report) {
  if (!report.grammar.grids.empty()) return "";
  const SymmetryResult& result = report.symmetries;
  const DetectedSymmetry* strongest = nullptr;
  std::size_t index = 0;
  for (std::size_t i = 0; i < result.symmetries.size(); ++i) {
    const DetectedSymmetry& s = result.symmetries[i];
    if (s.kind != "translation" || result.families[s.family].count == 0) continue;  // slides are no repeat
    if (!strongest || s.r_symmetric_area > strongest->r_symmetric_area) strongest = &s, index = i;
  }
  if (!strongest || (report.tolerance_hint && report.tolerance_hint->family == strongest->family) ||
      static_cast<int>(result.families[strongest->family].count) >= GridOptions{}.min_repeats)
    return "";
  const Vec3& t = strongest->transform.translation;
  return fmt::format(
      "The repeating translation with the most r-symmetric area is #{} (F{}, t = {}, |t| = {:.6g}; {:.1f} % of the "
      "surface). No two of its units could be cut apart by planes across the model that cross only surface it maps onto "
      "copies: surface that does not repeat with them lies between or around its copies (`dockgrammar symmetry MODEL -o "
      "DIR` draws where it repeats). Its copies may still be docking sites of the context-free rules below.\n\n",
      index + 1, strongest->family + 1, vec(t), t.norm(), 100.0 * strongest->r_symmetric_fraction);
}

std::string tolerance_hint_text(const AnalysisReport& report, std::string_view quote = "") {
  if (!report.tolerance_hint) return "";
  const ToleranceHint& hint = *report.tolerance_hint;
  return fmt::format(
      "translation F{} repeats {} times, but {}; its repeats differ a little: at {}--tolerance {}{} its r-symmetric area "
      "grows from {:.1f} % to {:.1f} % of the surface, which may give {}",
      hint.family + 1, hint.repeats,
      hint.grid_units == 0 ? std::string("no grid was found")
                           : fmt::format("no grid has more than {} unit{}", hint.grid_units, hint.grid_units == 1 ? "" : "s"),
      quote, hint.tolerance_eps, quote, 100.0 * hint.r_symmetric_now, 100.0 * hint.r_symmetric_wider,
      hint.grid_units == 0 ? "a grid" : "more units");
}

}  // namespace

std::string analysis_text(const AnalysisReport& report) {
  std::string out = fmt::format("model {}: r = {:.6g}, eps = {:.6g}\n", report.prepared.model.source_path,
                                report.prepared.surface.r(), report.prepared.surface.eps());
  if (report.prepared.model.is_point_cloud()) out += fmt::format("point cloud: {}\n", cloud_density_text(report.prepared));
  if (const std::string moved = origin_text(report.prepared); !moved.empty()) out += fmt::format("origin: {}\n", moved);
  if (report.symmetries.symmetries.empty())
    out += fmt::format("symmetries: none ({})\n", report.symmetries.note);
  else
    out += fmt::format("symmetries: {} in {} families\n", report.symmetries.symmetries.size(), report.symmetries.families.size());
  if (report.grammar.grids.empty()) out += "grids: none found\n";
  for (std::size_t g = 0; g < report.grammar.grids.size(); ++g) {
    const GridWithPieces& grid = report.grammar.grids[g];
    out += fmt::format("grid {}: {}-grid, counts {} (resize with --grid {}={})\n", grid.rule.name, grid.rule.directions.size(),
                       counts_text(grid.rule), grid.rule.name, counts_text(grid.rule));
    if (const std::string further = further_run_text(report, g); !further.empty()) out += fmt::format("  a further run {}\n", further);
    if (const std::string grouped = grouped_units_text(report, g); !grouped.empty()) out += fmt::format("  it {}\n", grouped);
    for (const GridDirection& d : grid.rule.directions)
      out += fmt::format("  direction {}: cut planes across {} every {:.6g}, {} unit{}, first cut at {:.6g}{}{}\n",
                         grid_motion_text(d, report.prepared), vec(d.direction), d.pitch, d.count,
                         d.count == 1 ? "" : "s", first_cut(d, report.prepared.origin),
                         kept_units_text(d), whole_parts_note(d, report.prepared.model.mesh));
  }
  if (const std::string hint = tolerance_hint_text(report); !hint.empty()) out += fmt::format("hint: {}\n", hint);
  if (const std::string hint = material_hint_text(report); !hint.empty())
    out += fmt::format("{}: {}\n", materials_applied(report) ? "materials" : "hint", hint);
  const ContextFreeGrammar& cf = report.grammar.context_free;
  const nlohmann::json ops = operation_counts(report.docking);
  out += fmt::format("docking sites: {} ({} insert, {} delete, {} replace)\n", report.docking.sites.size(),
                     ops["insert"].get<int>(), ops["delete"].get<int>(), ops["replace"].get<int>());
  if (cf.empty())
    out += fmt::format("context-free rules: none ({} of the docking sites slide along themselves, {} have dockers that do not fit each other's seam{})\n",
                       report.context_free.sites_slippable, report.context_free.sites_without_fit,
                       stray_seam_text(report.context_free) + unpaired_sites_text(report) + dropped_rules_text(report.context_free));
  else
    out += fmt::format("context-free rules: {} non-terminal(s), {} production(s) plus the axiom ({})\n", cf.nonterminals.size(),
                       cf.productions.size(), generate_rules_text(report));
  out += fmt::format("grammar written to {}, report to {}\n", report.grammar_path.string(), report.report_path.string());
  std::string pictures;
  for (const std::filesystem::path& png : report.pictures) pictures += (pictures.empty() ? "" : ", ") + png.filename().string();
  if (!pictures.empty()) out += fmt::format("pictures (and coloured .ply of each): {}\n", pictures);
  if (const std::vector<std::string> items = not_built_items(report); !items.empty())
    out += fmt::format("not built: {}\n", fmt::join(items, "; "));
  return out;
}

nlohmann::json pictures_json(const AnalysisReport& report) {
  nlohmann::json pictures = nlohmann::json::array();
  for (const std::filesystem::path& png : report.pictures) pictures.push_back(png.string());
  return pictures;
}

nlohmann::json analysis_json(const AnalysisReport& report) {
  nlohmann::json grids = nlohmann::json::array();
  for (const GridWithPieces& grid : report.grammar.grids) {
    nlohmann::json counts = nlohmann::json::array(), transforms = nlohmann::json::array(), pieces = nlohmann::json::array();
    nlohmann::json lowest = nlohmann::json::array(), kept_whole = nlohmann::json::array();
    for (std::size_t i = 0; i < grid.rule.directions.size(); ++i) {
      const GridDirection& d = grid.rule.directions[i];
      counts.push_back(d.count);
      transforms.push_back(matrix_json(shifted_motion(d.motion, report.prepared.origin)));
      lowest.push_back(lowest_count(grid.rule, i));
      kept_whole.push_back({{"head", parts_among(d.whole_in_head, report.prepared.model.mesh)},
                            {"tail", parts_among(d.whole_in_tail, report.prepared.model.mesh)}});
    }
    for (const GridPiece& p : grid.pieces)
      pieces.push_back(report.prepared.model.is_point_cloud()
                           ? nlohmann::json{{"name", piece_name(p.classes)}, {"points", p.points.positions.size()}}
                           : nlohmann::json{{"name", piece_name(p.classes)}, {"triangles", p.mesh.triangles.size()}});
    grids.push_back({{"name", grid.rule.name},
                     {"dims", grid.rule.directions.size()},
                     {"counts", counts},
                     {"transforms", transforms},
                     {"count_range", {grid.rule.min_count, grid.rule.max_count}},
                     {"min_counts", lowest},
                     {"seam_misfit", grid.rule.seam_misfit},
                     {"parts_kept_whole", kept_whole},
                     {"further_run_of", nlohmann::json(nullptr)},
                     {"groups_units_of", nlohmann::json(nullptr)},
                     {"pieces", pieces}});
    if (const auto of = further_run_of(report, grids.size() - 1))
      grids.back()["further_run_of"] = {{"grid", report.grammar.grids[of->first].rule.name}, {"direction", of->second + 1}};
    if (const auto of = grouped_units_of(report, grids.size() - 1))
      grids.back()["groups_units_of"] = {{"grid", report.grammar.grids[of->first].rule.name},
                                         {"direction", of->second.direction + 1},
                                         {"factor", of->second.factor}};
  }
  const bool cloud = report.prepared.model.is_point_cloud();
  return {{"model", report.prepared.model.source_path},
          {"r", report.prepared.surface.r()},
          {"eps", report.prepared.surface.eps()},
          {"origin", coordinates_json(report.prepared.origin)},
          {"up", report.grammar.up_axis.empty() ? nlohmann::json(nullptr) : nlohmann::json(report.grammar.up_axis)},
          {"tolerance", match_tolerances(report).offset_eps},
          {"point_cloud", cloud ? nlohmann::json{{"points", report.prepared.model.cloud.positions.size()},
                                                 {"points_per_voxel", points_per_voxel(report.prepared)},
                                                 {"noise_eps", noise_eps(report.prepared)}}
                                : nlohmann::json(nullptr)},
          {"materials", material_names(report.prepared.model.materials)},
          {"match_materials", report.prepared.materials_matched()},
          {"material_groups", material_groups(report.prepared)},
          {"material_hint", report.material_hint ? nlohmann::json{{"same_material", report.material_hint->groups},
                                                                  {"grid_counts", report.material_hint->grid_counts},
                                                                  {"applied", report.material_hint->applied}}
                                                 : nlohmann::json(nullptr)},
          {"symmetries", report.symmetries.symmetries.size()},
          {"families", report.symmetries.families.size()},
          {"docking_sites", docking_sites_json(report)},
          {"dockers", report.docking.sites.size()},
          {"unverified_candidates", report.symmetries.stats.unverified},
          {"unexamined_symmetries", report.docking.stats.symmetries_skipped},
          {"locations_kept_apart", report.context_free.locations_kept_apart},
          {"operations", operation_counts(report.docking)},
          {"nonterminals", nonterminals_json(report.grammar.context_free)},
          {"productions", productions_json(report.grammar.context_free)},
          {"grids", grids},
          {"grammar_file", report.grammar_path.string()},
          {"report_file", report.report_path.string()},
          {"pictures", pictures_json(report)},
          {"timings_s", timings_json(report)},
          {"missing", not_built_items(report)}};
}

void write_analysis_report(const AnalysisReport& report) {
  const PreparedModel& prepared = report.prepared;
  const CleaningReport& c = prepared.cleaning;
  std::string md = fmt::format("# Analysis of {}\n\n", prepared.model.source_path);
  if (prepared.model.is_point_cloud())
    md += fmt::format("r = {:.6g}, eps = {:.6g} (model units). A point cloud: {} ({} exact repeats and {} with invalid "
                      "normals dropped).\n\n",
                      prepared.surface.r(), prepared.surface.eps(), cloud_density_text(prepared), c.duplicate_points_dropped,
                      c.invalid_normals_dropped);
  else
    md += fmt::format("r = {:.6g}, eps = {:.6g} (model units). {} vertices, {} triangles ({} degenerate dropped, {} duplicated), "
                      "{} boundary and {} non-manifold edges, {} components; {} open edges split at T-junctions for the "
                      "analysis.\n\n",
                      prepared.surface.r(), prepared.surface.eps(), c.vertices, c.triangles, c.degenerate_dropped,
                      c.duplicate_triangles, c.boundary_edges, c.non_manifold_edges, c.components, c.t_junctions_split);
  md += fmt::format("Cells match when the planes and feature lines of one, moved, lie within {:.3g}° and {:.3g} eps "
                    "of the other's (`--tolerance`).\n\n",
                    match_tolerances(report).angle_degrees, match_tolerances(report).offset_eps);
  if (const std::optional<TurnAxis>& turn = report.up.turn) {
    const SymmetryFamily& family = report.symmetries.families[turn->family];
    md += fmt::format("Up axis {}: the axis of {} F{} ({:.3g} deg steps), whose motions map {:.1f} % of the surface onto "
                      "itself. Pictures stand the model on it and generate keeps pieces upright about it (`--up` sets "
                      "another).\n\n",
                      report.grammar.up_axis, family.kind, turn->family + 1, family.generator.angle() * 180.0 / std::numbers::pi,
                      100.0 * turn->fraction);
  } else if (const std::optional<AxisFacing>& facing = report.up.one_sided) {
    const char* surface = prepared.model.is_point_cloud() ? "points face" : "surface area faces";
    md += fmt::format("Up axis {0}: {1:.1f} % of the {2} +{0} and {3:.2f} % -{0}, as in a scan seen from above or "
                      "a model without floors or undersides. Pictures stand the model on it and generate keeps pieces "
                      "upright about it (`--up` sets another).\n\n",
                      report.grammar.up_axis, 100.0 * facing->up, surface, 100.0 * facing->down);
  } else if (report.up.stl_convention) {
    md += "Up axis z: STL files are z-up by convention (CAD, 3D printing, Blender's STL export), and the model has no "
          "turn or one-sided surface that says otherwise. Pictures stand the model on it and generate keeps pieces "
          "upright about it (`--up` sets another).\n\n";
  }
  md += materials_paragraph(prepared);
  if (const std::string moved = origin_text(prepared); !moved.empty()) md += moved + "\n\n";
  md += "## Symmetries\n\nOrdered by r-symmetric area; families group a motion with its powers.\n\n```\n";
  md += symmetry_table(report.symmetries, 20, report.prepared);
  md += "```\n\n";
  if (const std::string unverified = unverified_candidates_text(report.symmetries); !unverified.empty()) md += unverified + "\n";
  md += "## Grid rules\n\n";
  if (report.grammar.grids.empty()) {
    const std::string unused = translations_without_grid_text(report);
    md += unused.empty() ? "No grid found (no translation or screw motion with at least two units whose cut planes cross "
                           "only r-symmetric area).\n\n"
                         : fmt::format("No grid found. Repeating, but without a grid: {}; \"Not yet built\" below says "
                                       "why.\n\n",
                                       unused);
  }
  md += strongest_translation_text(report);
  if (const std::string hint = tolerance_hint_text(report, "`"); !hint.empty()) md += fmt::format("Hint: {}.\n\n", hint);
  if (const std::string hint = material_hint_text(report, "`"); !hint.empty())
    md += fmt::format("{}: {}.\n\n", materials_applied(report) ? "Materials" : "Hint", hint);
  for (std::size_t g = 0; g < report.grammar.grids.size(); ++g) {
    const GridWithPieces& grid = report.grammar.grids[g];
    md += fmt::format("### {} ({}-grid, counts {})\n\n", grid.rule.name, grid.rule.directions.size(), counts_text(grid.rule));
    if (const std::string further = further_run_text(report, g); !further.empty())
      md += fmt::format("A further run {}.\n\n", further);
    if (const std::string grouped = grouped_units_text(report, g); !grouped.empty())
      md += fmt::format("It {}.\n\n", grouped);
    md += "| direction | motion | pitch | units | first cut | repeated unit |\n|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < grid.rule.directions.size(); ++i) {
      const GridDirection& d = grid.rule.directions[i];
      md += fmt::format("| {} | {} | {:.6g} | {} | {:.6g} | {}{} |\n", i + 1, grid_motion_text(d, report.prepared),
                        d.pitch, d.count, first_cut(d, report.prepared.origin),
                        d.head_units + 1, kept_units_text(d));
    }
    for (std::size_t i = 0; i < grid.rule.directions.size(); ++i)
      if (grid.rule.directions[i].count == 1)
        md += fmt::format(
            "\nDirection {} has one unit: its motion repeats across the model (its multiples are symmetries too), "
            "but planes across the whole model fit only one unit, because other parts (such as structures on a roof) "
            "lie across the rest. Resizing adds units at that place.\n",
            i + 1);
    for (const GridDirection& d : grid.rule.directions)
      if (const std::string parts = whole_parts_text(d, report.prepared.model.mesh); !parts.empty())
        md += fmt::format(
            "\nNo plane crosses the whole model between the units: the planes cut the rest and pass by {}, parts "
            "that do not repeat with the units. Parts placed with the head stay where they are; parts moved with the "
            "tail keep their place at the end. Counts below {} would bring a part within r of the other side.\n",
            parts, grid.rule.min_count);
    md += "\nPieces (class per direction: 1 = head, placed once; 2 = repeated unit; 3 = tail, placed after the last unit):\n\n";
    for (const GridPiece& p : grid.pieces)
      md += report.prepared.model.is_point_cloud()
                ? fmt::format("- {}: {} points\n", piece_name(p.classes), p.points.positions.size())
                : fmt::format("- {}: {} triangles\n", piece_name(p.classes), p.mesh.triangles.size());
    std::string ranges;
    for (std::size_t i = 0; i < grid.rule.directions.size(); ++i)
      ranges += fmt::format("{}direction {}: {}..{}", i == 0 ? "" : ", ", i + 1, lowest_count(grid.rule, i), grid.rule.max_count);
    md += fmt::format("\nAllowed counts: {}. Picture: `{}.png`.\n\n", ranges, model_stem(report) + "." + grid.rule.name);
    if (!report.prepared.model.is_point_cloud())
      md += fmt::format("Where a resize joins its pieces, their seams lie up to {:.2g} eps apart; resize welds them within {:.2g} eps.\n\n",
                        grid.rule.seam_misfit / report.grammar.eps, grid_weld_tolerance(grid.rule, report.grammar.eps) / report.grammar.eps);
  }
  md += context_free_markdown(report);
  if (const std::vector<std::string> items = not_built_items(report); !items.empty()) {
    md += "## Not yet built\n\n";
    for (const std::string& item : items) md += fmt::format("- {}.\n", item);
    md += "\n";
  }
  md += "## Timings (seconds)\n\n";
  for (const StageTiming& t : stage_timings(report)) md += fmt::format("- {}: {:.3f}\n", t.stage, t.seconds);
  write_file_atomically(report.report_path, [&](std::ostream& out) { out << md; }, false);
}

namespace {

// Colour of what lies in `slabs` (one per direction) in a grid picture: the piece class per
// direction as stored in the grammar; later units (copies) shade like the unit, alternately
// darker so the repeats can be counted.
Rgba8 grid_piece_color(const GridRule& grid, const std::vector<std::size_t>& slabs) {
  std::size_t class_index = 0, parity = 0;
  for (std::size_t i = 0; i < grid.directions.size(); ++i) {
    const int cls = slab_class(slabs[i], grid.directions[i]);
    class_index = 3 * class_index + static_cast<std::size_t>(cls < 0 ? 1 : cls);
    if (cls != 0 && cls != 2) parity += slabs[i];
  }
  const Rgba8 color = class_color(class_index);
  if (parity % 2 == 0) return color;
  return {static_cast<std::uint8_t>(color.r * 3 / 4), static_cast<std::uint8_t>(color.g * 3 / 4),
          static_cast<std::uint8_t>(color.b * 3 / 4), 255};
}

// NAME.rules.png/.ply: the exemplar rebuilt from its own productions, each piece coloured by
// the non-terminal it fills (the axiom's terminal light grey), like the paper's Figure 8.
std::optional<std::filesystem::path> write_rules_picture(const std::filesystem::path& folder, const std::string& stem,
                                                         const AnalysisReport& report) {
  const ContextFreeGrammar& cf = report.grammar.context_free;
  if (cf.empty()) return std::nullopt;
  ShapeDerivationOptions options;
  options.exemplar_only = true;
  options.weld_seams = false;
  const ShapeDerivation d = derive_shape(cf, report.grammar.eps, options);
  const BoundingBox bounds = report.prepared.model.bounds();
  auto color_of = [](std::size_t nonterminal) {
    return nonterminal == kNoProduction ? Rgba8{215, 215, 215, 255} : class_color(nonterminal);
  };
  if (cf.of_points()) {
    std::vector<Rgb> point_colors;
    for (std::size_t n : d.point_nonterminal) {
      const Rgba8 c = color_of(n);
      point_colors.push_back({c.r, c.g, c.b});
    }
    write_colored_cloud(folder / (stem + ".rules.png"), folder / (stem + ".rules.ply"), d.points, point_colors,
                        report.grammar.eps, picture_options(bounds, report.grammar.up_axis));
    return folder / (stem + ".rules.png");
  }
  std::vector<Rgba8> colors(d.mesh.triangles.size());
  std::vector<Rgb> vertex_colors(d.mesh.positions.size());
  for (std::size_t t = 0; t < colors.size(); ++t) {
    colors[t] = color_of(d.triangle_nonterminal[t]);
    for (std::uint32_t v : d.mesh.triangles[t]) vertex_colors[v] = {colors[t].r, colors[t].g, colors[t].b};
  }
  write_mesh(folder / (stem + ".rules.ply"), d.mesh, &vertex_colors);
  write_mesh_picture(folder / (stem + ".rules.png"), d.mesh, colors, {},
                     picture_options(bounds, report.grammar.up_axis));
  return folder / (stem + ".rules.png");
}

}  // namespace

std::vector<std::filesystem::path> write_analysis_pictures(const std::filesystem::path& folder, const std::string& stem,
                                                           const AnalysisReport& report) {
  std::vector<std::filesystem::path> written;
  const TriangleMesh& mesh = report.prepared.model.mesh;
  const PointCloud& cloud = report.prepared.model.cloud;
  const bool points = report.prepared.model.is_point_cloud();
  for (const GridWithPieces& grid : report.grammar.grids) {
    const std::filesystem::path png = folder / (stem + "." + grid.rule.name + ".png"),
                                ply = folder / (stem + "." + grid.rule.name + ".ply");
    if (points) {
      std::vector<Rgb> point_colors;
      for (const Vec3& p : cloud.positions) {
        std::vector<std::size_t> slabs;
        for (const GridDirection& d : grid.rule.directions) slabs.push_back(slab_of_point(d, p));
        const Rgba8 color = grid_piece_color(grid.rule, slabs);
        point_colors.push_back({color.r, color.g, color.b});
      }
      write_colored_cloud(png, ply, cloud, point_colors, report.grammar.eps, picture_options(cloud.bounds(), report.grammar.up_axis));
      written.push_back(png);
      continue;
    }
    const GridCut grid_cut = cut_along_grid(mesh, grid.rule, report.grammar.eps);
    const TriangleMesh& cut = grid_cut.mesh;
    std::vector<Rgba8> colors(cut.triangles.size());
    std::vector<Rgb> vertex_colors(cut.positions.size());
    for (std::size_t t = 0; t < cut.triangles.size(); ++t) {
      colors[t] = grid_piece_color(grid.rule, grid_cut.slabs[t]);
      for (std::uint32_t v : cut.triangles[t]) vertex_colors[v] = {colors[t].r, colors[t].g, colors[t].b};
    }
    write_mesh(ply, cut, &vertex_colors);
    write_mesh_picture(png, cut, colors, {}, picture_options(mesh.bounds(), report.grammar.up_axis));
    written.push_back(png);
  }
  if (const auto rules = write_rules_picture(folder, stem, report)) written.push_back(*rules);
  if (write_docking_site_picture(folder / (stem + ".sites.png"), folder / (stem + ".sites.ply"), report.prepared,
                                 report.docking, report.grammar.up_axis))
    written.push_back(folder / (stem + ".sites.png"));
  return written;
}

}  // namespace dg::cli
