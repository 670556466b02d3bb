#include "grammar/d0l_chain.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace dg {

namespace {

// A block: the letters it writes (0 = F, 1 = G), the turns between them and before / after it.
struct Block {
  std::vector<int> letters;
  std::vector<int> inner;  // turn before letters[1..]
  int lead = 0, trail = 0;
};

// `steps` as the turn in (-full/2, full/2] when a full turn is `full` steps (0: no wrapping).
int wrap_steps(int steps, int full) {
  if (full <= 0) return steps;
  int w = ((steps % full) + full) % full;
  return 2 * w > full ? w - full : w;
}

// One level of a chain: letters and the net turn before each (turns[0]: before the first).
struct Level {
  std::vector<int> letters;
  std::vector<int> turns;
};

std::string turn_text(int steps) { return std::string(static_cast<std::size_t>(std::abs(steps)), steps > 0 ? '+' : '-'); }

std::string block_text(const Block& b) {
  std::string s = turn_text(b.lead);
  for (std::size_t k = 0; k < b.letters.size(); ++k) {
    if (k > 0) s += turn_text(b.inner[k - 1]);
    s += b.letters[k] == 0 ? 'F' : 'G';
  }
  return s + turn_text(b.trail);
}

// The level as an axiom, without its leading turn (the start heading takes it).
std::string level_text(const Level& level) {
  std::string s;
  for (std::size_t k = 0; k < level.letters.size(); ++k) s += turn_text(k == 0 ? 0 : level.turns[k]) + (level.letters[k] == 0 ? 'F' : 'G');
  return s;
}

std::size_t grammar_length_of(const std::string& axiom, const std::string& f, const std::string& g) {
  bool plus = false, minus = false;
  for (const std::string* s : {&axiom, &f, &g})
    for (char c : *s) plus |= c == '+', minus |= c == '-';
  return axiom.size() + f.size() + g.size() + (g.empty() ? 1 : 2) + (plus ? 1 : 0) + (minus ? 1 : 0);
}

// The coarser level whose letters, rewritten by the blocks (`blocks[letter]`) and joined with
// their turns, give `level`. The inner turns decide which block a group of r letters is; with
// `known` (levels above the drawing, where letters are F or G) a block's letters are learnt from
// its first group and every later group of that block must repeat them. On the drawing itself F
// and G look alike, so letters are not compared there (`known` null).
std::optional<Level> coarsen(const Level& level, Block blocks[2], int count, std::size_t r, bool* known, int full) {
  if (level.letters.size() % r != 0 || level.letters.size() < r) return std::nullopt;
  Level out;
  const std::size_t groups = level.letters.size() / r;
  out.letters.reserve(groups);
  out.turns.reserve(groups);
  for (std::size_t g = 0; g < groups; ++g) {
    const auto first = level.letters.begin() + static_cast<long>(g * r);
    int match = -1;
    for (int b = 0; b < count && match < 0; ++b)
      if (std::equal(blocks[b].inner.begin(), blocks[b].inner.end(), level.turns.begin() + static_cast<long>(g * r + 1))) match = b;
    if (match < 0) return std::nullopt;
    if (known && !known[match]) {
      blocks[match].letters.assign(first, first + static_cast<long>(r));
      known[match] = true;
    } else if (known && !std::equal(first, first + static_cast<long>(r), blocks[match].letters.begin())) {
      return std::nullopt;
    }
    const int before = g == 0 ? 0 : blocks[out.letters.back()].trail;
    out.turns.push_back(wrap_steps(level.turns[g * r] - before - blocks[match].lead, full));
    out.letters.push_back(match);
  }
  return out;
}

}  // namespace

std::optional<ChainGrammar> recover_chain_grammar(const std::string& text, int turn_factor, int full_turn,
                                                  int max_block_letters, int max_edge_turns) {
  Level drawn;
  int turn = 0;
  for (char c : text) {
    if (c == '+') turn += turn_factor;
    else if (c == '-') turn -= turn_factor;
    else if (c == 'F') drawn.letters.push_back(0), drawn.turns.push_back(wrap_steps(turn, full_turn)), turn = 0;
    else return std::nullopt;
  }
  std::optional<ChainGrammar> best;
  const std::size_t n = drawn.letters.size();
  for (std::size_t r = 2; r <= static_cast<std::size_t>(max_block_letters); ++r) {
    if (n % r != 0 || n < 2 * r) continue;
    // The two inner-turn patterns of the drawn groups.
    std::vector<std::vector<int>> patterns;
    for (std::size_t g = 0; g < n / r && patterns.size() <= 2; ++g) {
      const std::vector<int> inner(drawn.turns.begin() + static_cast<long>(g * r + 1), drawn.turns.begin() + static_cast<long>(g * r + r));
      bool known = false;
      for (const auto& p : patterns) known |= p == inner;
      if (!known) patterns.push_back(inner);
    }
    if (patterns.size() > 2) continue;
    const int count = static_cast<int>(patterns.size());
    Block blocks[2];
    for (int b = 0; b < count; ++b) blocks[b].inner = patterns[static_cast<std::size_t>(b)];
    const int span = 2 * max_edge_turns + 1;
    for (int edges = 0; edges < (count == 2 ? span * span : 1) * span * span; ++edges) {
      int e = edges;
      for (Block& b : blocks) {
        b.lead = e % span - max_edge_turns, e /= span;
        b.trail = e % span - max_edge_turns, e /= span;
      }
      for (Block& b : blocks) b.letters.assign(r, 0);
      std::optional<Level> level = coarsen(drawn, blocks, count, r, nullptr, full_turn);
      bool known[2] = {false, false};
      for (int iterations = 1; level; ++iterations) {
        const std::string f = block_text(blocks[0]), g = count == 2 ? block_text(blocks[1]) : "";
        // The axiom holds at least one symbol per letter: build it only when that can be shorter.
        if (!best || level->letters.size() + f.size() + g.size() + static_cast<std::size_t>(count) < best->length) {
          const std::string axiom = level_text(*level);
          const std::size_t length = grammar_length_of(axiom, f, g);
          if (!best || length < best->length) best = ChainGrammar{axiom, f, g, iterations, length, level->turns[0]};
        }
        level = coarsen(*level, blocks, count, r, known, full_turn);
      }
    }
  }
  return best;
}

}  // namespace dg
