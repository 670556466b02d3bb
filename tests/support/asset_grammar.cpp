#include "support/asset_grammar.h"

#include "assets/generator/asset.h"
#include "grammar/context_free.h"
#include "grammar/docking_sites.h"
#include "grammar/grid_cut.h"
#include "grammar/grid_seams.h"

namespace dg::test {

ShapeGrammar asset_grammar(const std::string& name, const nlohmann::json& params, bool context_free) {
  Model model;
  model.mesh = assets::make_asset(name, params).mesh;
  return model_grammar(std::move(model), context_free);
}

ShapeGrammar model_grammar(Model model, bool context_free, const PrepareOptions& options) {
  const PreparedModel prepared = prepare_model(std::move(model), options);
  const SymmetryResult symmetries = detect_symmetries(prepared);
  ShapeGrammar grammar;
  grammar.r = prepared.surface.r();
  grammar.eps = prepared.surface.eps();
  grammar.exemplar = prepared.model.mesh;
  grammar.materials = prepared.model.materials;
  if (context_free) grammar.context_free = build_context_free_grammar(prepared, find_docking_sites(prepared, symmetries), {});
  for (GridRule& rule : find_grids(prepared, symmetries)) {
    auto pieces = cut_grid_pieces(prepared.model.mesh, rule, grammar.eps);
    rule.seam_misfit = grid_seam_misfit(rule, pieces, grammar.eps);
    grammar.grids.push_back({std::move(rule), std::move(pieces)});
  }
  return grammar;
}

}  // namespace dg::test
