#include "grammar/generalization.h"

#include "grammar/grammar_length.h"

#include <algorithm>
#include <limits>
#include <set>

namespace dg {

namespace {

// The first production of each predecessor, in file order.
std::vector<const Production*> rule_heads(const LSystem& system) {
  std::vector<const Production*> heads;
  std::set<std::string> seen;
  for (const Production& p : system.productions)
    if (seen.insert(p.predecessor).second) heads.push_back(&p);
  return heads;
}

void rename_items(std::vector<SuccessorItem>& items, const std::string& from, const std::string& to) {
  for (SuccessorItem& item : items)
    if (item.symbol == from) item.symbol = to;
}

// `system` with predecessor `merged` written as `kept`; the productions of both get equal
// total weight, and identical productions are folded into one.
LSystem merge_rules(const LSystem& system, const std::string& kept, const std::string& merged) {
  LSystem out = system;
  for (Module& m : out.axiom)
    if (m.symbol == merged) m.symbol = kept;
  std::vector<Production> productions;
  for (Production p : out.productions) {
    const bool from_kept = p.predecessor == kept, from_merged = p.predecessor == merged;
    if (from_merged) p.predecessor = kept;
    rename_items(p.successor, merged, kept);
    if (from_kept || from_merged) p.probability *= 0.5;
    const auto same = std::find_if(productions.begin(), productions.end(), [&](const Production& q) {
      return q.predecessor == p.predecessor && q.formals == p.formals && q.condition == p.condition && q.successor == p.successor;
    });
    if (same != productions.end()) same->probability += p.probability;
    else productions.push_back(std::move(p));
  }
  out.productions = std::move(productions);
  for (std::string& s : out.turtle.draw_symbols)
    if (s == merged) s = kept;
  return out;
}

}  // namespace

double weighted_edit_distance(const std::vector<SuccessorItem>& a, const std::vector<SuccessorItem>& b,
                              const GeneralizationOptions& options) {
  std::vector<double> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = static_cast<double>(j) * options.insert_cost;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = static_cast<double>(i) * options.delete_cost;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const double replace = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : options.replace_cost);
      current[j] = std::min({replace, previous[j] + options.delete_cost, current[j - 1] + options.insert_cost});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

Generalization generalize(const LSystem& system, const GeneralizationOptions& options) {
  Generalization result{system, {}};
  for (;;) {
    const std::vector<const Production*> heads = rule_heads(result.system);
    const double length = static_cast<double>(grammar_length(result.system));
    RuleMerge best;
    best.cost = std::numeric_limits<double>::infinity();
    LSystem best_system;
    for (std::size_t i = 0; i < heads.size(); ++i)
      for (std::size_t j = i + 1; j < heads.size(); ++j) {
        const Production &a = *heads[i], &b = *heads[j];
        if (a.formals.size() != b.formals.size()) continue;
        std::vector<SuccessorItem> renamed = b.successor;
        rename_items(renamed, b.predecessor, a.predecessor);
        std::vector<SuccessorItem> own = a.successor;
        rename_items(own, b.predecessor, a.predecessor);
        const double distance = weighted_edit_distance(own, renamed, options);
        LSystem merged = merge_rules(result.system, a.predecessor, b.predecessor);
        const double cost = options.w0 * (static_cast<double>(grammar_length(merged)) - length) + (1 - options.w0) * distance;
        if (cost < best.cost) {
          best = RuleMerge{a.predecessor, b.predecessor, distance, cost};
          best_system = std::move(merged);
        }
      }
    if (!(best.cost < 0)) break;
    result.system = std::move(best_system);
    result.merges.push_back(best);
  }
  return result;
}

}  // namespace dg
