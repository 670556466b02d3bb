#pragma once
// Internal helpers for the text model readers: walking a file held in memory line by line
// and parsing numbers with std::from_chars (locale independent, no allocation).

#include "geometry/errors.h"

#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>

namespace dg::detail {

/// Walks a text buffer line by line. Accepts "\n", "\r\n" and "\r" line ends.
/// When `continuation` is on, a line ending in a backslash is joined with the next one
/// (the backslash becomes a space); line() then reports the first physical line.
class LineReader {
 public:
  explicit LineReader(std::string_view text, bool continuation = false)
      : text_(text), continuation_(continuation) {}

  /// Moves to the next logical line; false at the end of the text.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    line_number_ = next_line_number_;
    std::string_view physical = next_physical();
    if (!continuation_ || !ends_with_backslash(physical)) {
      line = physical;
      return true;
    }
    joined_.assign(physical.substr(0, physical.size() - 1));
    joined_ += ' ';
    while (pos_ < text_.size()) {
      physical = next_physical();
      if (!ends_with_backslash(physical)) {
        joined_ += physical;
        break;
      }
      joined_.append(physical.substr(0, physical.size() - 1));
      joined_ += ' ';
    }
    line = joined_;
    return true;
  }
  /// 1-based number of the (first physical) line returned by the last next().
  std::size_t line() const { return line_number_; }
  /// Byte offset of the first character not yet read.
  std::size_t offset() const { return pos_; }

 private:
  static bool ends_with_backslash(std::string_view s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return !s.empty() && s.back() == '\\';
  }
  std::string_view next_physical() {
    const std::size_t start = pos_;
    std::size_t end = start;
    while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
    pos_ = end;
    if (pos_ < text_.size() && text_[pos_] == '\r') ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '\n' && (pos_ == end || text_[pos_ - 1] == '\r')) ++pos_;
    ++next_line_number_;
    std::string_view line = text_.substr(start, end - start);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    return line;
  }

  std::string_view text_;
  bool continuation_;
  std::size_t pos_ = 0;
  std::size_t line_number_ = 0;
  std::size_t next_line_number_ = 1;
  std::string joined_;
};

/// True for the blanks that separate tokens inside a line.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

/// Removes leading blanks from `s`.
inline void skip_blanks(std::string_view& s) {
  std::size_t i = 0;
  while (i < s.size() && is_blank(s[i])) ++i;
  s.remove_prefix(i);
}

/// Cuts the next blank-separated token off the front of `s` ("" when none is left).
inline std::string_view next_token(std::string_view& s) {
  skip_blanks(s);
  std::size_t i = 0;
  while (i < s.size() && !is_blank(s[i])) ++i;
  std::string_view token = s.substr(0, i);
  s.remove_prefix(i);
  return token;
}

/// Parses a whole token as a number (a leading '+' is accepted). False when malformed.
template <typename Number>
bool parse_number(std::string_view token, Number& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

/// Parses the next token of `s` as a number; false when there is none or it is malformed.
template <typename Number>
bool read_number(std::string_view& s, Number& value) {
  return parse_number(next_token(s), value);
}

/// Shortest decimal form of `value` for messages ("7", "-1.5", "2e+15").
inline std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// Throws InputError "<file>: line <n>: <problem>".
[[noreturn]] inline void throw_line_error(const std::string& file, std::size_t line, const std::string& problem) {
  throw InputError(file + ": line " + std::to_string(line) + ": " + problem);
}

}  // namespace dg::detail
