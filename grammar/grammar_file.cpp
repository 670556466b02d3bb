#include "grammar/grammar_file.h"

#include "geometry/atomic_file.h"
#include "geometry/errors.h"
#include "geometry/model_io.h"
#include "geometry/submesh.h"
#include "grammar/grid_cut.h"
#include "grammar/material_json.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>

namespace dg {
namespace {

nlohmann::json matrix_json(const Mat4& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return rows;
}

std::filesystem::path pieces_folder(const std::filesystem::path& path) {
  std::string stem = path.filename().string();
  if (stem.size() > 5 && stem.ends_with(".json")) stem.resize(stem.size() - 5);
  return path.parent_path() / (stem + ".pieces");
}

template <class T>
T field(const nlohmann::json& object, const char* key, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) throw InputError(where + ": missing field \"" + key + "\"");
  try {
    return object.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + ": field \"" + key + "\" has the wrong type");
  }
}

Vec3 vec3_field(const nlohmann::json& object, const char* key, const std::string& where) {
  const auto v = field<std::vector<double>>(object, key, where);
  if (v.size() != 3) throw InputError(where + ": field \"" + key + "\" needs three numbers");
  return Vec3(v[0], v[1], v[2]);
}

// `what` names the value in the error message.
RigidTransform rigid_from_rows(const std::vector<std::vector<double>>& rows, const std::string& what) {
  Mat4 m = Mat4::Identity();
  if (rows.size() != 4) throw InputError(what + " must be a 4x4 matrix");
  for (int r = 0; r < 4; ++r) {
    if (rows[r].size() != 4) throw InputError(what + " must be a 4x4 matrix");
    for (int c = 0; c < 4; ++c) m(r, c) = rows[r][c];
  }
  return rigid_from_matrix(m);
}

RigidTransform matrix_field(const nlohmann::json& object, const char* key, const std::string& where) {
  return rigid_from_rows(field<std::vector<std::vector<double>>>(object, key, where), where + ": field \"" + key + "\"");
}

nlohmann::json seam_json(const SeamSurface& seam) {
  if (seam.kind == SeamSurface::Kind::plane)
    return {{"kind", "plane"}, {"normal", {seam.normal.x(), seam.normal.y(), seam.normal.z()}}, {"offset", seam.offset}};
  nlohmann::json faces = nlohmann::json::array();
  for (const VoxelFace& f : seam.faces) faces.push_back({f.voxel[0], f.voxel[1], f.voxel[2], f.axis});
  return {{"kind", "voxel_faces"}, {"eps", seam.eps}, {"faces", faces}};
}

// A seam object (version 3), or the plane fields of version 2.
SeamSurface read_seam(const nlohmann::json& nonterminal, int version, const std::string& where) {
  SeamSurface seam;
  if (version < 3) {
    seam.normal = vec3_field(nonterminal, "seam_normal", where);
    seam.offset = field<double>(nonterminal, "seam_offset", where);
    return seam;
  }
  const nlohmann::json object = field<nlohmann::json>(nonterminal, "seam", where);
  const std::string kind = field<std::string>(object, "kind", where);
  if (kind == "plane") {
    seam.normal = vec3_field(object, "normal", where);
    seam.offset = field<double>(object, "offset", where);
    return seam;
  }
  if (kind != "voxel_faces") throw InputError(where + ": unknown seam kind \"" + kind + "\"");
  seam.kind = SeamSurface::Kind::voxel_faces;
  seam.eps = field<double>(object, "eps", where);
  if (!(seam.eps > 0.0)) throw InputError(where + ": a seam's eps must be positive");
  for (const auto& f : field<std::vector<std::vector<std::int32_t>>>(object, "faces", where)) {
    if (f.size() != 4 || f[3] < 0 || f[3] > 2) throw InputError(where + ": a seam face needs i, j, k and an axis 0..2");
    seam.faces.push_back({{f[0], f[1], f[2]}, f[3]});
  }
  std::sort(seam.faces.begin(), seam.faces.end());
  return seam;
}

// Adds `key`: the material runs of `mesh` when the grammar has materials and `mesh` carries them.
void add_material_runs(nlohmann::json& object, const char* key, const TriangleMesh& mesh, const ShapeGrammar& grammar) {
  if (!grammar.materials.empty() && mesh.has_materials()) object[key] = material_runs_json(mesh);
}

// Writes the exemplar point indices of a point cloud's terminal: little-endian uint32 each.
void write_point_indices(const std::filesystem::path& path, const std::vector<std::uint32_t>& indices) {
  write_file_atomically(path, [&](std::ostream& out) {
    for (std::uint32_t i : indices) {
      const std::array<char, 4> bytes{static_cast<char>(i & 0xFFu), static_cast<char>((i >> 8) & 0xFFu),
                                      static_cast<char>((i >> 16) & 0xFFu), static_cast<char>((i >> 24) & 0xFFu)};
      out.write(bytes.data(), 4);
    }
  });
}

// Whether a point cloud's terminal can be stored as indices of the exemplar's points.
bool stored_as_indices(const ShapeGrammar& grammar, const ShapeProduction& p) {
  const std::size_t n = grammar.exemplar_points.positions.size();
  return p.source_frame && !p.terminal_source_points.empty() &&
         p.terminal_source_points.size() == p.terminal_points.positions.size() &&
         std::all_of(p.terminal_source_points.begin(), p.terminal_source_points.end(), [&](std::uint32_t i) { return i < n; });
}

// One production: its terminal goes to a sidecar file (none when it has no triangles or points):
// a mesh, or a point cloud's terminal as indices of the exemplar's points (else as points).
nlohmann::json production_json(const ShapeGrammar& grammar, const ShapeProduction& p, const std::filesystem::path& folder,
                               const std::string& file) {
  const ContextFreeGrammar& g = grammar.context_free;
  nlohmann::json children = nlohmann::json::array();
  for (const ChildSlot& c : p.children)
    children.push_back({{"nonterminal", g.nonterminals[c.nonterminal].name},
                        {"placement", matrix_json(c.placement.matrix())},
                        {"original_production", c.original_production}});
  nlohmann::json terminal = nullptr;
  const bool as_indices = p.terminal.triangles.empty() && stored_as_indices(grammar, p);
  if (!p.terminal.triangles.empty()) {
    write_mesh(folder / file, p.terminal);
    terminal = folder.filename().string() + "/" + file;
  } else if (as_indices) {
    const std::string indices = std::filesystem::path(file).replace_extension(".u32").string();
    write_point_indices(folder / indices, p.terminal_source_points);
    terminal = folder.filename().string() + "/" + indices;
  } else if (!p.terminal_points.positions.empty()) {
    write_point_cloud(folder / file, p.terminal_points);
    terminal = folder.filename().string() + "/" + file;
  }
  nlohmann::json out = {{"lhs", p.lhs == kNoProduction ? nlohmann::json(nullptr) : nlohmann::json(g.nonterminals[p.lhs].name)},
                        {"terminal", terminal},
                        {"triangles", p.terminal.triangles.size()},
                        {"points", p.terminal_points.positions.size()},
                        {"children", children},
                        {"source_site", p.source_site}};
  if (p.source_frame) out["source_frame"] = matrix_json(p.source_frame->matrix());
  if (as_indices) out["terminal_of"] = "exemplar_points";
  add_material_runs(out, "material_runs", p.terminal, grammar);
  return out;
}

}  // namespace

std::string file_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  std::uint64_t hash = 1469598103934665603ull;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ull;
    }
  }
  return fmt::format("{:016x}", hash);
}

void write_grammar(const std::filesystem::path& path, const ShapeGrammar& grammar) {
  const std::filesystem::path folder = pieces_folder(path);
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw InputError(folder.string() + ": cannot create the folder for grammar pieces");
  const std::string folder_name = folder.filename().string();

  const bool points = is_point_grammar(grammar);
  if (points)
    write_point_cloud(folder / "exemplar.ply", grammar.exemplar_points);
  else
    write_mesh(folder / "exemplar.ply", grammar.exemplar);
  nlohmann::json grids = nlohmann::json::array();
  for (const GridWithPieces& grid : grammar.grids) {
    nlohmann::json directions = nlohmann::json::array(), transforms = nlohmann::json::array(), counts = nlohmann::json::array();
    for (const GridDirection& d : grid.rule.directions) {
      directions.push_back({{"translation", {d.translation.x(), d.translation.y(), d.translation.z()}},
                            {"pitch", d.pitch},
                            {"cut", d.cut},
                            {"count", d.count},
                            {"head_units", d.head_units},
                            {"tail_units", d.tail_units}});
      if (d.split_unit) directions.back()["split_unit"] = true;
      transforms.push_back(matrix_json(d.motion.matrix()));
      counts.push_back(d.count);
    }
    nlohmann::json pieces = nlohmann::json::array();
    for (const GridPiece& piece : grid.pieces) {
      const std::string file = grid.rule.name + "_" + piece_name(piece.classes) + ".ply";
      nlohmann::json entry = {{"name", piece_name(piece.classes)}, {"classes", piece.classes}, {"file", folder_name + "/" + file}};
      if (points) {
        write_point_cloud(folder / file, piece.points);
        entry["points"] = piece.points.positions.size();
      } else {
        write_mesh(folder / file, piece.mesh);
        entry["triangles"] = piece.mesh.triangles.size();
        add_material_runs(entry, "material_runs", piece.mesh, grammar);
      }
      pieces.push_back(std::move(entry));
    }
    grids.push_back({{"name", grid.rule.name},
                     {"dims", grid.rule.directions.size()},
                     {"counts", counts},
                     {"transforms", transforms},
                     {"count_range", {grid.rule.min_count, grid.rule.max_count}},
                     {"seam_misfit", grid.rule.seam_misfit},
                     {"directions", directions},
                     {"pieces", pieces}});
  }
  const ContextFreeGrammar& cf = grammar.context_free;
  nlohmann::json nonterminals = nlohmann::json::array(), productions = nlohmann::json::array(), axiom = nullptr;
  for (const ShapeNonterminal& n : cf.nonterminals)
    nonterminals.push_back({{"name", n.name}, {"seam", seam_json(n.seam)}, {"sites", n.sites}, {"seam_misfit", n.seam_misfit}});
  if (!cf.empty()) {
    axiom = production_json(grammar, cf.axiom, folder, "axiom.ply");
    for (std::size_t i = 0; i < cf.productions.size(); ++i)
      productions.push_back(production_json(grammar, cf.productions[i], folder, fmt::format("production_{}.ply", i + 1)));
  }
  nlohmann::json document = {{"format", "dockgrammar-grammar"},
                             {"version", kGrammarFileVersion},
                             {"units", "model units of the source file"},
                             {"source", {{"name", grammar.source_name}, {"hash_fnv1a64", grammar.source_hash}}},
                             {"surface", points ? "points" : "mesh"},
                             {"r", grammar.r},
                             {"eps", grammar.eps},
                             {"exemplar", folder_name + "/exemplar.ply"},
                             {"grids", grids},
                             {"nonterminals", nonterminals},
                             {"axiom", axiom},
                             {"productions", productions}};
  if (!grammar.up_axis.empty()) document["up"] = grammar.up_axis;
  if (!grammar.origin.isZero()) document["origin"] = {grammar.origin.x(), grammar.origin.y(), grammar.origin.z()};
  if (!grammar.materials.empty()) document["materials"] = materials_json(grammar.materials);
  add_material_runs(document, "exemplar_material_runs", grammar.exemplar, grammar);
  write_file_atomically(path, [&](std::ostream& out) { out << document.dump(2) << '\n'; }, false);
}

namespace {

// `load_terminal(relative path, production json, production)` reads a terminal's sidecar into
// the production (its mesh, or its points for a point-cloud grammar).
template <class LoadTerminal>
ShapeProduction read_production(const nlohmann::json& p, const std::string& where, const std::map<std::string, std::size_t>& names,
                           std::size_t production_count, const LoadTerminal& load_terminal) {
  auto nonterminal = [&](const std::string& name) {
    auto it = names.find(name);
    if (it == names.end()) throw InputError(where + ": unknown non-terminal \"" + name + "\"");
    return it->second;
  };
  ShapeProduction production;
  if (!p.contains("lhs")) throw InputError(where + ": a production has no \"lhs\"");
  if (!p.at("lhs").is_null()) production.lhs = nonterminal(field<std::string>(p, "lhs", where));
  if (!p.contains("terminal")) throw InputError(where + ": a production has no \"terminal\"");
  production.source_site = field<std::size_t>(p, "source_site", where);
  if (p.contains("source_frame")) production.source_frame = matrix_field(p, "source_frame", where);
  if (!p.at("terminal").is_null()) load_terminal(field<std::string>(p, "terminal", where), p, production);
  for (const nlohmann::json& c : field<nlohmann::json>(p, "children", where)) {
    ChildSlot slot;
    slot.nonterminal = nonterminal(field<std::string>(c, "nonterminal", where));
    slot.placement = matrix_field(c, "placement", where);
    slot.original_production = field<std::size_t>(c, "original_production", where);
    if (slot.original_production >= production_count)
      throw InputError(where + ": a child slot names production " + std::to_string(slot.original_production) +
                       ", which does not exist");
    production.children.push_back(slot);
  }
  return production;
}

// The exemplar point indices of a point cloud's terminal (write_point_indices); each must be
// below `exemplar_points`.
std::vector<std::uint32_t> read_point_indices(const std::filesystem::path& file, std::size_t exemplar_points,
                                              const std::string& where) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(where + ": sidecar point indices " + file.string() + " are missing");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() % 4 != 0) throw InputError(where + ": " + file.string() + " is not a list of 4-byte point indices");
  std::vector<std::uint32_t> indices(bytes.size() / 4);
  for (std::size_t i = 0; i < indices.size(); ++i) {
    for (int b = 3; b >= 0; --b) indices[i] = (indices[i] << 8) | static_cast<unsigned char>(bytes[4 * i + static_cast<std::size_t>(b)]);
    if (indices[i] >= exemplar_points)
      throw InputError(where + ": " + file.string() + " names point " + std::to_string(indices[i]) + " of an exemplar of " +
                       std::to_string(exemplar_points));
  }
  return indices;
}

// Each slot's exemplar production must belong to the slot's non-terminal, and following them
// from the axiom must end (they retrace the exemplar's inclusion tree): else rebuilding the
// exemplar, the fallback of every derivation, would never finish.
void check_exemplar_productions(const ContextFreeGrammar& cf, const std::string& where) {
  const std::size_t n = cf.productions.size();
  auto production = [&](std::size_t i) -> const ShapeProduction& { return i < n ? cf.productions[i] : cf.axiom; };
  std::vector<char> state(n + 1, 0);  // 0 unseen, 1 on the walk's path, 2 finished
  std::vector<std::pair<std::size_t, std::size_t>> path{{n, 0}};  // production, next child
  state[n] = 1;
  while (!path.empty()) {
    auto& [index, next] = path.back();
    const ShapeProduction& p = production(index);
    if (next == p.children.size()) {
      state[index] = 2;
      path.pop_back();
      continue;
    }
    const ChildSlot& slot = p.children[next++];
    if (cf.productions[slot.original_production].lhs != slot.nonterminal)
      throw InputError(where + ": a child slot of non-terminal " + cf.nonterminals[slot.nonterminal].name + " names production " +
                       std::to_string(slot.original_production) + ", which is not one of its productions");
    if (state[slot.original_production] == 1)
      throw InputError(where + ": production " + std::to_string(slot.original_production) +
                       " rebuilds the exemplar through itself (the slots' original productions form a cycle)");
    if (state[slot.original_production] == 0) {
      state[slot.original_production] = 1;
      path.push_back({slot.original_production, 0});
    }
  }
}

template <class LoadTerminal>
void read_context_free(const nlohmann::json& document, int version, const std::string& where, const LoadTerminal& load_terminal,
                       ContextFreeGrammar& cf) {
  std::map<std::string, std::size_t> names;
  for (const nlohmann::json& n : field<nlohmann::json>(document, "nonterminals", where)) {
    ShapeNonterminal nt;
    nt.name = field<std::string>(n, "name", where);
    nt.seam = read_seam(n, version, where);
    nt.sites = field<std::size_t>(n, "sites", where);
    if (n.contains("seam_misfit")) {
      nt.seam_misfit = field<double>(n, "seam_misfit", where);
      if (!(nt.seam_misfit >= 0.0 && std::isfinite(nt.seam_misfit)))
        throw InputError(where + ": non-terminal " + nt.name + " has a seam_misfit that is not a finite number >= 0");
    }
    names[nt.name] = cf.nonterminals.size();
    cf.nonterminals.push_back(nt);
  }
  if (cf.nonterminals.empty()) return;
  const nlohmann::json productions = field<nlohmann::json>(document, "productions", where);
  for (const nlohmann::json& p : productions) {
    cf.productions.push_back(read_production(p, where, names, productions.size(), load_terminal));
    if (cf.productions.back().lhs == kNoProduction) throw InputError(where + ": a production has no left-hand side");
  }
  cf.axiom = read_production(field<nlohmann::json>(document, "axiom", where), where, names, productions.size(), load_terminal);
  check_exemplar_productions(cf, where);
}

}  // namespace

ShapeGrammar read_grammar(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where + ": cannot read the grammar file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (document.is_discarded()) throw InputError(where + ": not valid JSON (truncated or not a grammar file)");
  if (field<std::string>(document, "format", where) != "dockgrammar-grammar")
    throw InputError(where + ": not a dockgrammar grammar file");
  const int version = field<int>(document, "version", where);
  if (version < 1 || version > kGrammarFileVersion)
    throw InputError(fmt::format("{}: grammar file version {} is not supported (this program reads version {})", where,
                                 version, kGrammarFileVersion));
  ShapeGrammar grammar;
  const nlohmann::json source = field<nlohmann::json>(document, "source", where);
  grammar.source_name = field<std::string>(source, "name", where);
  grammar.source_hash = field<std::string>(source, "hash_fnv1a64", where);
  grammar.r = field<double>(document, "r", where);
  grammar.eps = field<double>(document, "eps", where);
  if (document.contains("up")) {
    grammar.up_axis = field<std::string>(document, "up", where);
    if (grammar.up_axis != "x" && grammar.up_axis != "y" && grammar.up_axis != "z")
      throw InputError(where + ": \"up\" must be \"x\", \"y\" or \"z\"");
  }
  if (document.contains("origin")) {
    grammar.origin = vec3_field(document, "origin", where);
    if (!grammar.origin.allFinite()) throw InputError(where + ": \"origin\" must hold three finite numbers");
  }
  if (document.contains("materials")) grammar.materials = read_materials_json(document.at("materials"), where);
  // A sidecar mesh with the material runs stored under `runs_key` in `owner` (none when absent).
  auto load = [&](const std::string& relative, const nlohmann::json& owner, const char* runs_key = "material_runs") {
    const std::filesystem::path file = path.parent_path() / relative;
    if (!std::filesystem::exists(file)) throw InputError(where + ": sidecar mesh " + file.string() + " is missing");
    TriangleMesh mesh = read_model(file).mesh;  // a PLY sidecar: no materials of its own
    if (owner.contains(runs_key))
      mesh.materials = read_material_runs(owner.at(runs_key), mesh.triangles.size(), grammar.materials.size(),
                                          where + ": " + relative);
    return mesh;
  };
  // "surface": "points" (version 4) when the exemplar and the pieces are point clouds.
  const std::string surface = version >= 4 ? field<std::string>(document, "surface", where) : "mesh";
  if (surface != "mesh" && surface != "points") throw InputError(where + ": \"surface\" must be \"mesh\" or \"points\"");
  const bool points = surface == "points";
  auto load_points = [&](const std::string& relative) {
    const std::filesystem::path file = path.parent_path() / relative;
    if (!std::filesystem::exists(file)) throw InputError(where + ": sidecar point cloud " + file.string() + " is missing");
    Model model = read_model(file);
    if (!model.is_point_cloud()) throw InputError(where + ": sidecar " + file.string() + " is not a point cloud");
    return std::move(model.cloud);
  };
  if (points)
    grammar.exemplar_points = load_points(field<std::string>(document, "exemplar", where));
  else
    grammar.exemplar = load(field<std::string>(document, "exemplar", where), document, "exemplar_material_runs");
  for (const nlohmann::json& grid : field<nlohmann::json>(document, "grids", where)) {
    GridWithPieces entry;
    entry.rule.name = field<std::string>(grid, "name", where);
    const auto range = field<std::vector<int>>(grid, "count_range", where);
    if (range.size() != 2) throw InputError(where + ": count_range must have two numbers");
    entry.rule.min_count = range[0];
    entry.rule.max_count = range[1];
    if (grid.contains("seam_misfit")) {
      entry.rule.seam_misfit = field<double>(grid, "seam_misfit", where);
      if (!(entry.rule.seam_misfit >= 0.0 && std::isfinite(entry.rule.seam_misfit)))
        throw InputError(where + ": grid " + entry.rule.name + " has a seam_misfit that is not a finite number >= 0");
    }
    for (const nlohmann::json& d : field<nlohmann::json>(grid, "directions", where)) {
      GridDirection direction;
      const auto t = field<std::vector<double>>(d, "translation", where);
      if (t.size() != 3) throw InputError(where + ": a grid translation needs three numbers");
      direction.translation = Vec3(t[0], t[1], t[2]);
      direction.pitch = field<double>(d, "pitch", where);
      if (!(direction.pitch > 0.0)) throw InputError(where + ": a grid pitch must be positive");
      direction.direction = direction.translation / direction.translation.norm();
      direction.cut = field<double>(d, "cut", where);
      direction.count = field<int>(d, "count", where);
      // Optional (files written before they existed: no unit kept in the head or tail).
      if (d.contains("head_units")) direction.head_units = field<int>(d, "head_units", where);
      if (d.contains("tail_units")) direction.tail_units = field<int>(d, "tail_units", where);
      if (d.contains("split_unit")) direction.split_unit = field<bool>(d, "split_unit", where);
      if (direction.count < 1 || direction.head_units < 0 || direction.tail_units < 0 ||
          direction.head_units + direction.tail_units >= direction.count || (direction.split_unit && direction.head_units < 1))
        throw InputError(where + ": grid " + entry.rule.name +
                         ": a direction needs count >= 1 and head_units + tail_units < count (both >= 0), and a "
                         "head unit when its unit is split");
      entry.rule.directions.push_back(direction);
    }
    // The generators: a translation by `translation`, or a screw whose slide is `translation`.
    const auto transforms = field<std::vector<std::vector<std::vector<double>>>>(grid, "transforms", where);
    if (transforms.size() != entry.rule.directions.size())
      throw InputError(where + ": grid " + entry.rule.name + " needs one transform per direction");
    for (std::size_t i = 0; i < transforms.size(); ++i) {
      GridDirection& direction = entry.rule.directions[i];
      const std::string what = fmt::format("{}: grid {} transform {}", where, entry.rule.name, i + 1);
      direction.motion = rigid_from_rows(transforms[i], what);
      if (std::abs(direction.motion.translation.dot(direction.direction) - direction.pitch) > 1e-6 * direction.pitch)
        throw InputError(what + " does not move by the pitch along its direction");
    }
    for (const nlohmann::json& p : field<nlohmann::json>(grid, "pieces", where)) {
      GridPiece piece;
      piece.classes = field<std::vector<int>>(p, "classes", where);
      if (piece.classes.size() != entry.rule.directions.size())
        throw InputError(where + ": piece " + field<std::string>(p, "name", where) + " has the wrong number of classes");
      if (points)
        piece.points = load_points(field<std::string>(p, "file", where));
      else
        piece.mesh = load(field<std::string>(p, "file", where), p);
      entry.pieces.push_back(std::move(piece));
    }
    grammar.grids.push_back(std::move(entry));
  }
  auto load_terminal = [&](const std::string& relative, const nlohmann::json& owner, ShapeProduction& production) {
    if (!points) {
      production.terminal = load(relative, owner);
    } else if (owner.contains("terminal_of")) {
      if (field<std::string>(owner, "terminal_of", where) != "exemplar_points" || !production.source_frame)
        throw InputError(where + ": \"terminal_of\" must be \"exemplar_points\", with a source_frame");
      production.terminal_source_points =
          read_point_indices(path.parent_path() / relative, grammar.exemplar_points.positions.size(), where);
      production.terminal_points =
          transformed(subcloud(grammar.exemplar_points, production.terminal_source_points), production.source_frame->inverse());
    } else {
      production.terminal_points = load_points(relative);
    }
  };
  if (version >= 2) read_context_free(document, version, where, load_terminal, grammar.context_free);
  return grammar;
}

}  // namespace dg
