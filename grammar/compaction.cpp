#include "grammar/compaction.h"

#include <algorithm>
#include <set>

namespace dg {

std::size_t compact_grammar_length(const std::string& axiom, const std::string& successor, int iterations) {
  std::set<char> distinct(axiom.begin(), axiom.end());
  std::size_t length = axiom.size();
  if (iterations > 0) {
    distinct.insert('F');
    distinct.insert(successor.begin(), successor.end());
    length += successor.size();
  }
  return length + distinct.size();
}

std::string elide_trailing_branches(const std::string& block) {
  std::string text = block;
  while (!text.empty() && text.back() == ']') {
    int depth = 0;
    std::size_t open = text.size();
    for (std::size_t k = text.size(); k-- > 0;) {
      if (text[k] == ']') ++depth;
      if (text[k] == '[' && --depth == 0) {
        open = k;
        break;
      }
    }
    if (open == text.size()) break;
    text = text.substr(0, open) + text.substr(open + 1, text.size() - open - 2);
  }
  return text;
}

std::optional<std::string> replace_blocks(const std::string& text, const std::string& block) {
  if (block.empty()) return std::nullopt;
  const std::string elided = elide_trailing_branches(block);
  std::string out;
  out.reserve(text.size() / 2 + 1);
  std::size_t i = 0;
  while (i < text.size()) {
    if (text.compare(i, block.size(), block) == 0) {
      out += 'F';
      i += block.size();
    } else if (elided != block && text.compare(i, elided.size(), elided) == 0 &&
               (i + elided.size() == text.size() || text[i + elided.size()] == ']')) {
      out += 'F';
      i += elided.size();
    } else if (text[i] == 'F') {
      return std::nullopt;
    } else {
      out += text[i++];
    }
  }
  return out;
}

CompactGrammar compact_turtle_string(const std::string& text, std::size_t max_block) {
  CompactGrammar best{text, "", 0, compact_grammar_length(text, "", 0)};
  int depth = 0, fs = 0;
  const std::size_t limit = std::min(max_block, text.size() / 2);
  for (std::size_t k = 1; k <= limit; ++k) {
    const char c = text[k - 1];
    if (c == '[') ++depth;
    if (c == ']' && --depth < 0) break;
    if (c == 'F') ++fs;
    if (k < 2 || depth != 0 || fs < 2 || text[0] != 'F') continue;
    const std::string block = text.substr(0, k);
    std::string current = text;
    int iterations = 0;
    while (current.size() > 1) {
      std::optional<std::string> coarser = replace_blocks(current, block);
      if (!coarser || coarser->size() >= current.size()) break;
      current = std::move(*coarser);
      ++iterations;
      const std::size_t length = compact_grammar_length(current, block, iterations);
      if (length < best.length) best = CompactGrammar{current, block, iterations, length};
    }
  }
  return best;
}

}  // namespace dg
