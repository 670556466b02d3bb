#include "grammar/grammar_length.h"

#include <set>
#include <string>

namespace dg {

std::size_t grammar_length(const LSystem& system) {
  std::set<std::string> distinct;
  std::size_t length = system.axiom.size();
  for (const Module& module : system.axiom) distinct.insert(module.symbol);
  for (const Production& production : system.productions) {
    distinct.insert(production.predecessor);
    length += production.successor.size();
    for (const SuccessorItem& item : production.successor) distinct.insert(item.symbol);
  }
  return length + distinct.size();
}

}  // namespace dg
