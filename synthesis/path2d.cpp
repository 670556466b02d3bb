#include "synthesis/path2d.h"

#include "geometry/errors.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace dg {

namespace {

[[noreturn]] void fail(const std::string& problem) { throw InputError("path data: " + problem); }

class PathReader {
 public:
  explicit PathReader(std::string_view data) : data_(data) {}

  Path2d read() {
    Path2d path;
    char command = 0;
    Vec2 current = Vec2::Zero();
    Vec2 start = Vec2::Zero();
    skip_separators();
    while (pos_ < data_.size()) {
      if (std::isalpha(static_cast<unsigned char>(data_[pos_]))) {
        command = data_[pos_++];
      } else if (command == 0) {
        fail("must start with a command such as M");
      } else if (command == 'Z' || command == 'z') {
        fail("unexpected number after Z");
      }
      const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
      const Vec2 base = relative ? current : Vec2::Zero();
      const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
      if (path.commands.empty() && upper != 'M') fail("must start with M");
      PathCommand c;
      switch (upper) {
        case 'M':
          c.type = PathCommand::Type::Move;
          c.points[0] = base + point();
          start = c.points[0];
          command = relative ? 'l' : 'L';  // further pairs are line-tos
          break;
        case 'L':
          c.type = PathCommand::Type::Line;
          c.points[0] = base + point();
          break;
        case 'H':
          c.type = PathCommand::Type::Line;
          c.points[0] = Vec2(number() + (relative ? current.x() : 0), current.y());
          break;
        case 'V':
          c.type = PathCommand::Type::Line;
          c.points[0] = Vec2(current.x(), number() + (relative ? current.y() : 0));
          break;
        case 'C':
          c.type = PathCommand::Type::Cubic;
          for (Vec2& p : c.points) p = base + point();
          break;
        case 'Z':
          c.type = PathCommand::Type::Close;
          break;
        default: fail(std::string("unsupported command '") + command + "' (motifs use M, L, H, V, C and Z)");
      }
      if (c.type == PathCommand::Type::Close)
        current = start;
      else
        current = c.type == PathCommand::Type::Cubic ? c.points[2] : c.points[0];
      path.commands.push_back(c);
      skip_separators();
    }
    if (path.commands.empty()) fail("empty");
    return path;
  }

 private:
  void skip_separators() {
    while (pos_ < data_.size() && (std::isspace(static_cast<unsigned char>(data_[pos_])) || data_[pos_] == ','))
      ++pos_;
  }

  double number() {
    skip_separators();
    double value = 0;
    const char* begin = data_.data() + pos_;
    const char* end = data_.data() + data_.size();
    if (begin != end && *begin == '+') ++begin;
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc() || !std::isfinite(value))
      fail("expected a number at character " + std::to_string(pos_ + 1));
    pos_ = static_cast<std::size_t>(stop - data_.data());
    skip_separators();
    return value;
  }

  Vec2 point() {
    const double x = number();
    return Vec2(x, number());
  }

  std::string_view data_;
  std::size_t pos_ = 0;
};

}  // namespace

Path2d parse_svg_path(std::string_view data) { return PathReader(data).read(); }

Path2d map_path(const Path2d& path, const std::function<Vec2(const Vec2&)>& map) {
  Path2d out = path;
  for (PathCommand& c : out.commands) {
    const int used = c.type == PathCommand::Type::Cubic ? 3 : c.type == PathCommand::Type::Close ? 0 : 1;
    for (int i = 0; i < used; ++i) c.points[i] = map(c.points[i]);
  }
  return out;
}

std::vector<std::vector<Vec2>> flatten_path(const Path2d& path, double max_piece) {
  std::vector<std::vector<Vec2>> lines;
  Vec2 current = Vec2::Zero();
  for (const PathCommand& c : path.commands) {
    switch (c.type) {
      case PathCommand::Type::Move:
        lines.push_back({c.points[0]});
        current = c.points[0];
        break;
      case PathCommand::Type::Line:
        lines.back().push_back(c.points[0]);
        current = c.points[0];
        break;
      case PathCommand::Type::Cubic: {
        const Vec2 p0 = current, p1 = c.points[0], p2 = c.points[1], p3 = c.points[2];
        const double hull = (p1 - p0).norm() + (p2 - p1).norm() + (p3 - p2).norm();
        const int pieces = std::clamp(static_cast<int>(std::ceil(hull / std::max(max_piece, 1e-9))), 1, 256);
        for (int i = 1; i <= pieces; ++i) {
          const double t = static_cast<double>(i) / pieces, u = 1 - t;
          lines.back().push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
        }
        current = p3;
        break;
      }
      case PathCommand::Type::Close:
        lines.back().push_back(lines.back().front());
        current = lines.back().front();
        break;
    }
  }
  return lines;
}

void add_path_bounds(const Path2d& path, Vec2& low, Vec2& high) {
  for (const PathCommand& c : path.commands) {
    const int used = c.type == PathCommand::Type::Cubic ? 3 : c.type == PathCommand::Type::Close ? 0 : 1;
    for (int i = 0; i < used; ++i) {
      low = low.cwiseMin(c.points[i]);
      high = high.cwiseMax(c.points[i]);
    }
  }
}

std::string format_svg_number(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string text = buffer;
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  if (text == "-0") text = "0";
  return text;
}

std::string format_svg_path(const Path2d& path, int decimals) {
  std::string text;
  auto add_point = [&](const Vec2& p) {
    text += ' ' + format_svg_number(p.x(), decimals) + ' ' + format_svg_number(p.y(), decimals);
  };
  for (const PathCommand& c : path.commands) {
    if (!text.empty()) text += ' ';
    switch (c.type) {
      case PathCommand::Type::Move: text += 'M'; add_point(c.points[0]); break;
      case PathCommand::Type::Line: text += 'L'; add_point(c.points[0]); break;
      case PathCommand::Type::Cubic:
        text += 'C';
        for (const Vec2& p : c.points) add_point(p);
        break;
      case PathCommand::Type::Close: text += 'Z'; break;
    }
  }
  return text;
}

}  // namespace dg
