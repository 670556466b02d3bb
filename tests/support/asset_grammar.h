#pragma once
// The grammar `dockgrammar analyze` would write for a generated asset, built in memory.

#include "grammar/grammar_file.h"

#include <nlohmann/json.hpp>

#include <string>

namespace dg::test {

/// Grid rules with their pieces for the asset `name` (assets/generator) with `params`, and its
/// context-free rules when `context_free` is set; r, eps and the exemplar as analyze sets them.
ShapeGrammar asset_grammar(const std::string& name, const nlohmann::json& params, bool context_free);

/// The same for a model built in code, with its materials, prepared with `options`.
ShapeGrammar model_grammar(Model model, bool context_free, const PrepareOptions& options = {});

}  // namespace dg::test
