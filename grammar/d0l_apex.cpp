#include "grammar/d0l_apex.h"

#include "grammar/turtle_string.h"

#include <set>
#include <vector>

namespace dg {

namespace {

// The contents of the bracket groups of `text` opened at depth 0 or 1, without their leading
// turns, distinct, in order of appearance; at most `limit`.
std::vector<std::string> branch_contents(const std::string& text, std::size_t limit) {
  std::vector<std::string> contents;
  std::vector<std::size_t> open;
  for (std::size_t k = 0; k < text.size() && contents.size() < limit; ++k) {
    if (text[k] == '[') open.push_back(k);
    if (text[k] == ']' && !open.empty()) {
      const std::size_t start = open.back();
      open.pop_back();
      if (open.size() > 1) continue;
      std::size_t begin = start + 1;
      while (begin < k && (text[begin] == '+' || text[begin] == '-')) ++begin;
      std::string content = text.substr(begin, k - begin);
      bool known = false;
      for (const std::string& c : contents) known |= c == content;
      if (!known && !content.empty()) contents.push_back(std::move(content));
    }
  }
  return contents;
}

// `text` with every copy of `lower` that ends a branch replaced by X and runs of `run` F by one F;
// nothing when a run is left over.
std::optional<std::string> apex_successor(const std::string& text, const std::string& lower, std::size_t run) {
  std::string u;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t after = i + lower.size();
    if (text.compare(i, lower.size(), lower) == 0 && (after == text.size() || text[after] == ']')) {
      u += 'X';
      i = after;
    } else if (text[i] == 'F') {
      if (text.compare(i, run, std::string(run, 'F')) != 0) return std::nullopt;
      u += 'F';
      i += run;
    } else {
      u += text[i++];
    }
  }
  return u;
}

// σ^n(X) for X -> u, F -> F^m with X erased; empty when it would hold more than `max_f` F.
std::string derive_apex(const std::string& u, int m, int n, std::size_t max_f) {
  std::string current = "X";
  for (int step = 0; step < n; ++step) {
    std::string next;
    std::size_t fs = 0;
    for (char c : current) {
      if (c == 'X') next += u;
      else if (c == 'F') next.append(static_cast<std::size_t>(m), 'F');
      else next += c;
    }
    for (char c : next) fs += c == 'F';
    if (fs > max_f) return {};
    current = std::move(next);
  }
  std::string drawn;
  for (char c : current)
    if (c != 'X') drawn += c;
  return drawn;
}

}  // namespace

std::optional<ApexGrammar> recover_apex_grammar(const std::string& text, bool descending_turns, int max_m) {
  std::size_t first_run = 0, total = 0;
  while (first_run < text.size() && text[first_run] == 'F') ++first_run;
  for (char c : text) total += c == 'F';
  if (first_run == 0) return std::nullopt;
  const std::vector<std::string> lowers = branch_contents(text, 16);
  std::optional<ApexGrammar> best;
  for (int m = 2; m <= max_m; ++m)
    for (std::size_t run = static_cast<std::size_t>(m), n = 2; run <= first_run; run *= static_cast<std::size_t>(m), ++n)
      for (const std::string& lower : lowers) {
        const std::optional<std::string> u = apex_successor(text, lower, run);
        if (!u || u->find('X') == std::string::npos) continue;
        std::set<char> distinct(u->begin(), u->end());
        distinct.insert({'X', 'F'});
        const std::size_t length = 1 + u->size() + static_cast<std::size_t>(m) + distinct.size();
        if (best && length >= best->length) continue;
        const std::string drawn = derive_apex(*u, m, static_cast<int>(n), total);
        if (drawn.empty() || canonical_turtle_string(drawn, descending_turns) != text) continue;
        best = ApexGrammar{*u, m, static_cast<int>(n), length};
      }
  return best;
}

}  // namespace dg
