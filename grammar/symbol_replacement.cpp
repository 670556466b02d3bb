#include "grammar/symbol_replacement.h"

namespace dg {

std::size_t replace_symbol(LSystem& system, const std::string& from, const std::string& to) {
  std::size_t count = 0;
  for (Module& module : system.axiom)
    if (module.symbol == from) module.symbol = to, ++count;
  for (Production& production : system.productions)
    for (SuccessorItem& item : production.successor)
      if (item.symbol == from) item.symbol = to, ++count;
  return count;
}

}  // namespace dg
