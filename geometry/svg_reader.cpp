#include "geometry/svg_reader.h"

#include "geometry/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

namespace dg {

namespace {

using Polyline = std::vector<Vec2>;

// ---------------------------------------------------------------------------------------------
// Numbers and lists of numbers as SVG writes them ("1.5.5" is 1.5 then .5, "1e-3", "-2-3").

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

void skip_separators(std::string_view text, std::size_t& pos) {
  while (pos < text.size() && (is_space(text[pos]) || text[pos] == ',')) ++pos;
}

// Reads one number at pos (after separators); false when none starts there.
bool read_number(std::string_view text, std::size_t& pos, double& value) {
  skip_separators(text, pos);
  std::size_t p = pos;
  if (p < text.size() && (text[p] == '+' || text[p] == '-')) ++p;
  bool digits = false;
  while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) ++p, digits = true;
  if (p < text.size() && text[p] == '.') {
    ++p;
    while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) ++p, digits = true;
  }
  if (!digits) return false;
  if (p < text.size() && (text[p] == 'e' || text[p] == 'E')) {
    std::size_t q = p + 1;
    if (q < text.size() && (text[q] == '+' || text[q] == '-')) ++q;
    if (q < text.size() && std::isdigit(static_cast<unsigned char>(text[q]))) {
      while (q < text.size() && std::isdigit(static_cast<unsigned char>(text[q]))) ++q;
      p = q;
    }
  }
  const std::string token(text.substr(pos, p - pos));
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  if (!std::isfinite(value)) throw InputError("number out of range: " + token);
  pos = p;
  return true;
}

// Reads an arc flag: a single 0 or 1, which may be written without a separator ("a1 1 0 00 1 1").
bool read_flag(std::string_view text, std::size_t& pos, bool& flag) {
  skip_separators(text, pos);
  if (pos < text.size() && (text[pos] == '0' || text[pos] == '1')) {
    flag = text[pos] == '1';
    ++pos;
    return true;
  }
  return false;
}

std::vector<double> read_number_list(std::string_view text, const char* what) {
  std::vector<double> values;
  std::size_t pos = 0;
  double v = 0;
  while (read_number(text, pos, v)) values.push_back(v);
  skip_separators(text, pos);
  if (pos != text.size()) throw InputError(std::string(what) + ": unexpected '" + std::string(1, text[pos]) + "'");
  return values;
}

// ---------------------------------------------------------------------------------------------
// Curve flattening.

int piece_count(double length, const SvgReadOptions& options) {
  const int n = static_cast<int>(std::ceil(length / std::max(options.max_piece, 1e-9)));
  const int most = std::max(1, options.max_pieces_per_curve);
  return std::clamp(n, std::clamp(options.min_pieces_per_curve, 1, most), most);
}

void add_cubic(Polyline& out, const Vec2& p0, const Vec2& c1, const Vec2& c2, const Vec2& p3, const SvgReadOptions& options) {
  const int n = piece_count((c1 - p0).norm() + (c2 - c1).norm() + (p3 - c2).norm(), options);
  for (int k = 1; k <= n; ++k) {
    const double t = static_cast<double>(k) / n, u = 1 - t;
    out.push_back(u * u * u * p0 + 3 * u * u * t * c1 + 3 * u * t * t * c2 + t * t * t * p3);
  }
}

void add_quadratic(Polyline& out, const Vec2& p0, const Vec2& c, const Vec2& p2, const SvgReadOptions& options) {
  const int n = piece_count((c - p0).norm() + (p2 - c).norm(), options);
  for (int k = 1; k <= n; ++k) {
    const double t = static_cast<double>(k) / n, u = 1 - t;
    out.push_back(u * u * p0 + 2 * u * t * c + t * t * p2);
  }
}

double vector_angle(const Vec2& u, const Vec2& v) {
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

// Elliptical arc from p0 to p1 (SVG endpoint parameterization, implementation notes F.6.5/F.6.6).
void add_arc(Polyline& out, const Vec2& p0, double rx, double ry, double x_rotation_deg, bool large_arc, bool sweep,
             const Vec2& p1, const SvgReadOptions& options) {
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (p0 == p1) return;
  if (rx == 0 || ry == 0) {
    out.push_back(p1);
    return;
  }
  const double phi = x_rotation_deg * std::numbers::pi / 180;
  const double c = std::cos(phi), s = std::sin(phi);
  const Vec2 h = (p0 - p1) / 2;
  const Vec2 q(c * h.x() + s * h.y(), -s * h.x() + c * h.y());
  const double lambda = q.x() * q.x() / (rx * rx) + q.y() * q.y() / (ry * ry);
  if (lambda > 1) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  const double num = rx * rx * ry * ry - rx * rx * q.y() * q.y() - ry * ry * q.x() * q.x();
  const double den = rx * rx * q.y() * q.y() + ry * ry * q.x() * q.x();
  double factor = den > 0 ? std::sqrt(std::max(0.0, num / den)) : 0;
  if (large_arc == sweep) factor = -factor;
  const Vec2 cq(factor * rx * q.y() / ry, -factor * ry * q.x() / rx);
  const Vec2 center = Vec2(c * cq.x() - s * cq.y(), s * cq.x() + c * cq.y()) + (p0 + p1) / 2;
  const Vec2 u((q.x() - cq.x()) / rx, (q.y() - cq.y()) / ry);
  const Vec2 v((-q.x() - cq.x()) / rx, (-q.y() - cq.y()) / ry);
  const double theta = vector_angle(Vec2(1, 0), u);
  double delta = vector_angle(u, v);
  if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
  if (sweep && delta < 0) delta += 2 * std::numbers::pi;
  const int n = piece_count(std::abs(delta) * std::max(rx, ry), options);
  for (int k = 1; k < n; ++k) {
    const double t = theta + delta * k / n;
    const Vec2 e(rx * std::cos(t), ry * std::sin(t));
    out.push_back(center + Vec2(c * e.x() - s * e.y(), s * e.x() + c * e.y()));
  }
  out.push_back(p1);
}

// Full ellipse centred at (cx, cy), starting at angle 0, closed.
Polyline ellipse_polyline(double cx, double cy, double rx, double ry, const SvgReadOptions& options) {
  const int n = std::max(8, piece_count(2 * std::numbers::pi * std::max(rx, ry), options));
  Polyline out;
  for (int k = 0; k <= n; ++k) {
    const double t = 2 * std::numbers::pi * (k % n) / n;
    out.emplace_back(cx + rx * std::cos(t), cy + ry * std::sin(t));
  }
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Path data.

std::vector<std::vector<Vec2>> flatten_svg_path_data(std::string_view data, const SvgReadOptions& options) {
  std::vector<Polyline> result;
  Polyline current;
  Vec2 point = Vec2::Zero(), start = Vec2::Zero(), last_control = Vec2::Zero();
  char previous = 0;
  std::size_t pos = 0;
  auto fail = [&](const std::string& problem) { throw InputError("path data: " + problem); };
  auto finish = [&]() {
    if (current.size() > 1) result.push_back(std::move(current));
    current.clear();
  };
  auto need = [&](double& v) {
    if (!read_number(data, pos, v)) fail(std::string("missing number after '") + previous + "'");
  };
  char command = 0;
  while (true) {
    skip_separators(data, pos);
    if (pos >= data.size()) break;
    const char c = data[pos];
    if (std::isalpha(static_cast<unsigned char>(c))) {
      command = c;
      ++pos;
      if (std::string_view("MmLlHhVvCcSsQqTtAaZz").find(command) == std::string_view::npos)
        fail(std::string("unknown command '") + command + "'");
    } else if (command == 0) {
      fail("does not start with a command");
    } else if (command == 'Z' || command == 'z') {
      fail("number after 'Z'");
    }
    if (previous == 0 && command != 'M' && command != 'm') fail("does not start with M");
    const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
    const Vec2 base = relative ? point : Vec2::Zero();
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(command)));
    Vec2 control = point;  // reflected control point for S and T
    switch (upper) {
      case 'M': {
        double x = 0, y = 0;
        need(x), need(y);
        finish();
        point = base + Vec2(x, y);
        start = point;
        current.push_back(point);
        command = relative ? 'l' : 'L';  // further pairs are line-tos
        break;
      }
      case 'L': {
        double x = 0, y = 0;
        need(x), need(y);
        point = base + Vec2(x, y);
        current.push_back(point);
        break;
      }
      case 'H': {
        double x = 0;
        need(x);
        point = Vec2(relative ? point.x() + x : x, point.y());
        current.push_back(point);
        break;
      }
      case 'V': {
        double y = 0;
        need(y);
        point = Vec2(point.x(), relative ? point.y() + y : y);
        current.push_back(point);
        break;
      }
      case 'C': case 'S': {
        double v[6] = {0, 0, 0, 0, 0, 0};
        const int first = upper == 'C' ? 0 : 2;
        for (int k = first; k < 6; ++k) need(v[k]);
        const Vec2 c1 = upper == 'C' ? Vec2(base + Vec2(v[0], v[1]))
                                     : Vec2(std::string_view("CcSs").find(previous) != std::string_view::npos
                                                ? Vec2(2 * point - last_control) : point);
        const Vec2 c2 = base + Vec2(v[2], v[3]), end = base + Vec2(v[4], v[5]);
        add_cubic(current, point, c1, c2, end, options);
        control = c2;
        point = end;
        break;
      }
      case 'Q': case 'T': {
        double v[4] = {0, 0, 0, 0};
        const int first = upper == 'Q' ? 0 : 2;
        for (int k = first; k < 4; ++k) need(v[k]);
        const Vec2 c1 = upper == 'Q' ? Vec2(base + Vec2(v[0], v[1]))
                                     : Vec2(std::string_view("QqTt").find(previous) != std::string_view::npos
                                                ? Vec2(2 * point - last_control) : point);
        const Vec2 end = base + Vec2(v[2], v[3]);
        add_quadratic(current, point, c1, end, options);
        control = c1;
        point = end;
        break;
      }
      case 'A': {
        double rx = 0, ry = 0, rotation = 0, x = 0, y = 0;
        bool large = false, sweep = false;
        need(rx), need(ry), need(rotation);
        if (!read_flag(data, pos, large) || !read_flag(data, pos, sweep)) fail("arc flags must be 0 or 1");
        need(x), need(y);
        const Vec2 end = base + Vec2(x, y);
        add_arc(current, point, rx, ry, rotation, large, sweep, end, options);
        point = end;
        break;
      }
      case 'Z': {
        if (!current.empty() && current.back() != start) current.push_back(start);
        finish();
        point = start;
        current.push_back(point);
        break;
      }
      default: break;
    }
    last_control = control;
    previous = command;
  }
  finish();
  return result;
}

// ---------------------------------------------------------------------------------------------
// Transforms.

Affine2 parse_svg_transform(std::string_view text) {
  Affine2 total;
  std::size_t pos = 0;
  auto fail = [&](const std::string& problem) { throw InputError("transform: " + problem); };
  while (true) {
    skip_separators(text, pos);
    if (pos >= text.size()) break;
    std::size_t name_end = pos;
    while (name_end < text.size() && std::isalpha(static_cast<unsigned char>(text[name_end]))) ++name_end;
    const std::string name(text.substr(pos, name_end - pos));
    if (name.empty()) fail("expected a transform name at '" + std::string(text.substr(pos, 10)) + "'");
    pos = name_end;
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos >= text.size() || text[pos] != '(') fail("missing '(' after " + name);
    const std::size_t close = text.find(')', pos);
    if (close == std::string_view::npos) fail("missing ')' after " + name);
    const std::vector<double> a = read_number_list(text.substr(pos + 1, close - pos - 1), "transform");
    pos = close + 1;
    auto count_ok = [&](std::initializer_list<std::size_t> counts) {
      if (std::find(counts.begin(), counts.end(), a.size()) == counts.end())
        fail(name + " has " + std::to_string(a.size()) + " numbers");
    };
    Affine2 t;
    const double deg = std::numbers::pi / 180;
    if (name == "matrix") {
      count_ok({6});
      t.linear << a[0], a[2], a[1], a[3];
      t.offset = Vec2(a[4], a[5]);
    } else if (name == "translate") {
      count_ok({1, 2});
      t.offset = Vec2(a[0], a.size() > 1 ? a[1] : 0);
    } else if (name == "scale") {
      count_ok({1, 2});
      t.linear << a[0], 0, 0, a.size() > 1 ? a[1] : a[0];
    } else if (name == "rotate") {
      count_ok({1, 3});
      const double c = std::cos(a[0] * deg), s = std::sin(a[0] * deg);
      t.linear << c, -s, s, c;
      if (a.size() == 3) t.offset = Vec2(a[1], a[2]) - t.linear * Vec2(a[1], a[2]);
    } else if (name == "skewX") {
      count_ok({1});
      t.linear << 1, std::tan(a[0] * deg), 0, 1;
    } else if (name == "skewY") {
      count_ok({1});
      t.linear << 1, 0, std::tan(a[0] * deg), 1;
    } else {
      fail("unknown transform '" + name + "'");
    }
    total = total.then_after(t);
  }
  return total;
}

// ---------------------------------------------------------------------------------------------
// XML tokenizer and element walk.

namespace {

struct Tag {
  std::string name;
  std::map<std::string, std::string> attributes;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name/>
  std::size_t line = 0;
};

class XmlReader {
 public:
  XmlReader(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  // Next start or end tag; false at the end of the text. Skips text, comments, CDATA,
  // processing instructions and declarations.
  bool next(Tag& tag) {
    while (true) {
      const std::size_t open = text_.find('<', pos_);
      if (open == std::string_view::npos) {
        advance_to(text_.size());
        return false;
      }
      advance_to(open);
      if (starts_with("<!--")) {
        skip_past("-->", "comment is not closed");
      } else if (starts_with("<![CDATA[")) {
        skip_past("]]>", "CDATA section is not closed");
      } else if (starts_with("<?")) {
        skip_past("?>", "processing instruction is not closed");
      } else if (starts_with("<!")) {
        skip_declaration();
      } else {
        read_tag(tag);
        return true;
      }
    }
  }

  std::size_t line() const { return line_; }

  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw InputError(source_ + ":" + std::to_string(line) + ": " + problem);
  }

 private:
  bool starts_with(std::string_view prefix) const { return text_.substr(pos_, prefix.size()) == prefix; }

  void advance_to(std::size_t target) {
    line_ += static_cast<std::size_t>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                                 text_.begin() + static_cast<std::ptrdiff_t>(target), '\n'));
    pos_ = target;
  }

  void skip_past(std::string_view end, const char* problem) {
    const std::size_t found = text_.find(end, pos_ + 2);
    if (found == std::string_view::npos) fail(line_, problem);
    advance_to(found + end.size());
  }

  // <!DOCTYPE ...> with an optional internal subset in [ ].
  void skip_declaration() {
    const std::size_t start_line = line_;
    int depth = 0;
    for (std::size_t p = pos_ + 2; p < text_.size(); ++p) {
      if (text_[p] == '[') ++depth;
      if (text_[p] == ']') --depth;
      if (text_[p] == '>' && depth <= 0) {
        advance_to(p + 1);
        return;
      }
    }
    fail(start_line, "declaration is not closed");
  }

  std::string decode(std::string_view raw, std::size_t line) const {
    std::string out;
    for (std::size_t p = 0; p < raw.size(); ++p) {
      if (raw[p] != '&') {
        out += raw[p];
        continue;
      }
      const std::size_t semi = raw.find(';', p);
      if (semi == std::string_view::npos) fail(line, "'&' without ';' in an attribute value");
      const std::string_view entity = raw.substr(p + 1, semi - p - 1);
      if (entity == "lt") out += '<';
      else if (entity == "gt") out += '>';
      else if (entity == "amp") out += '&';
      else if (entity == "quot") out += '"';
      else if (entity == "apos") out += '\'';
      else if (entity.size() > 1 && entity[0] == '#') {
        const bool hex = entity[1] == 'x' || entity[1] == 'X';
        const std::string digits(entity.substr(hex ? 2 : 1));
        char* end = nullptr;
        const long code = std::strtol(digits.c_str(), &end, hex ? 16 : 10);
        if (digits.empty() || *end != '\0' || code <= 0 || code > 0x10FFFF) fail(line, "bad character reference &" + std::string(entity) + ";");
        if (code < 0x80) {
          out += static_cast<char>(code);
        } else if (code < 0x800) {
          out += static_cast<char>(0xC0 | (code >> 6));
          out += static_cast<char>(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
          out += static_cast<char>(0xE0 | (code >> 12));
          out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
          out += static_cast<char>(0x80 | (code & 0x3F));
        } else {
          out += static_cast<char>(0xF0 | (code >> 18));
          out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
          out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
          out += static_cast<char>(0x80 | (code & 0x3F));
        }
      } else {
        fail(line, "unknown entity &" + std::string(entity) + ";");
      }
      p = semi;
    }
    return out;
  }

  static bool name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == ':' || c == '.';
  }

  void read_tag(Tag& tag) {
    tag = Tag{};
    tag.line = line_;
    std::size_t p = pos_ + 1;
    if (p < text_.size() && text_[p] == '/') {
      tag.closing = true;
      ++p;
    }
    const std::size_t name_start = p;
    while (p < text_.size() && name_char(text_[p])) ++p;
    tag.name = std::string(text_.substr(name_start, p - name_start));
    if (tag.name.empty()) fail(tag.line, "'<' not followed by a tag name");
    while (true) {
      while (p < text_.size() && is_space(text_[p])) ++p;
      if (p >= text_.size()) fail(tag.line, "tag <" + tag.name + "> is not closed");
      if (text_[p] == '>') {
        ++p;
        break;
      }
      if (text_[p] == '/' && !tag.closing && p + 1 < text_.size() && text_[p + 1] == '>') {
        tag.self_closing = true;
        p += 2;
        break;
      }
      if (tag.closing) fail(tag.line, "unexpected text in end tag </" + tag.name + ">");
      const std::size_t attr_start = p;
      while (p < text_.size() && name_char(text_[p])) ++p;
      const std::string attr(text_.substr(attr_start, p - attr_start));
      if (attr.empty()) fail(tag.line, "unexpected '" + std::string(1, text_[p]) + "' in tag <" + tag.name + ">");
      while (p < text_.size() && is_space(text_[p])) ++p;
      if (p >= text_.size() || text_[p] != '=') fail(tag.line, "attribute '" + attr + "' has no value");
      ++p;
      while (p < text_.size() && is_space(text_[p])) ++p;
      if (p >= text_.size() || (text_[p] != '"' && text_[p] != '\'')) fail(tag.line, "value of '" + attr + "' is not quoted");
      const char quote = text_[p];
      const std::size_t end = text_.find(quote, p + 1);
      if (end == std::string_view::npos) fail(tag.line, "value of '" + attr + "' is not closed");
      const std::string_view raw = text_.substr(p + 1, end - p - 1);
      if (raw.find('<') != std::string_view::npos) fail(tag.line, "'<' in the value of '" + attr + "'");
      if (!tag.attributes.emplace(attr, decode(raw, tag.line)).second) fail(tag.line, "attribute '" + attr + "' given twice");
      p = end + 1;
    }
    advance_to(p);
  }

  std::string_view text_;
  std::string source_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

double attribute_number(const Tag& tag, const std::string& name, double fallback, const XmlReader& reader) {
  const auto it = tag.attributes.find(name);
  if (it == tag.attributes.end()) return fallback;
  std::string_view value = it->second;
  std::size_t pos = 0;
  double v = 0;
  if (!read_number(value, pos, v)) reader.fail(tag.line, "attribute " + name + "=\"" + it->second + "\" is not a number");
  const std::string_view rest = value.substr(pos);
  if (!rest.empty() && rest != "px") reader.fail(tag.line, "attribute " + name + "=\"" + it->second + "\": unsupported unit");
  return v;
}

// Polylines of one drawn element in its own coordinates; empty for tags that draw nothing.
std::vector<Polyline> element_shape(const Tag& tag, const SvgReadOptions& options, const XmlReader& reader) {
  auto number = [&](const std::string& name, double fallback) { return attribute_number(tag, name, fallback, reader); };
  auto points_of = [&](bool close) {
    const auto it = tag.attributes.find("points");
    const std::vector<double> v = read_number_list(it == tag.attributes.end() ? "" : it->second, "points");
    if (v.size() % 2 != 0) reader.fail(tag.line, "<" + tag.name + "> has an odd number of coordinates");
    Polyline out;
    for (std::size_t k = 0; k + 1 < v.size(); k += 2) out.emplace_back(v[k], v[k + 1]);
    if (close && out.size() > 2 && out.front() != out.back()) out.push_back(out.front());
    return out;
  };
  std::vector<Polyline> shape;
  if (tag.name == "path") {
    const auto it = tag.attributes.find("d");
    if (it != tag.attributes.end()) shape = flatten_svg_path_data(it->second, options);
  } else if (tag.name == "line") {
    shape.push_back({Vec2(number("x1", 0), number("y1", 0)), Vec2(number("x2", 0), number("y2", 0))});
  } else if (tag.name == "polyline" || tag.name == "polygon") {
    Polyline p = points_of(tag.name == "polygon");
    if (p.size() > 1) shape.push_back(std::move(p));
  } else if (tag.name == "rect") {
    const double x = number("x", 0), y = number("y", 0), w = number("width", 0), h = number("height", 0);
    if (w < 0 || h < 0) reader.fail(tag.line, "<rect> with a negative size");
    if (w > 0 && h > 0) {
      const bool has_rx = tag.attributes.count("rx") != 0, has_ry = tag.attributes.count("ry") != 0;
      double rx = number("rx", 0), ry = number("ry", 0);
      if (has_rx && !has_ry) ry = rx;
      if (has_ry && !has_rx) rx = ry;
      rx = std::clamp(rx, 0.0, w / 2);
      ry = std::clamp(ry, 0.0, h / 2);
      std::ostringstream d;
      d.precision(17);
      d << "M " << x + rx << ' ' << y << " H " << x + w - rx;
      if (rx > 0 && ry > 0) d << " A " << rx << ' ' << ry << " 0 0 1 " << x + w << ' ' << y + ry;
      d << " V " << y + h - ry;
      if (rx > 0 && ry > 0) d << " A " << rx << ' ' << ry << " 0 0 1 " << x + w - rx << ' ' << y + h;
      d << " H " << x + rx;
      if (rx > 0 && ry > 0) d << " A " << rx << ' ' << ry << " 0 0 1 " << x << ' ' << y + h - ry;
      d << " V " << y + ry;
      if (rx > 0 && ry > 0) d << " A " << rx << ' ' << ry << " 0 0 1 " << x + rx << ' ' << y;
      d << " Z";
      shape = flatten_svg_path_data(d.str(), options);
    }
  } else if (tag.name == "circle" || tag.name == "ellipse") {
    const double cx = number("cx", 0), cy = number("cy", 0);
    const double rx = tag.name == "circle" ? number("r", 0) : number("rx", 0);
    const double ry = tag.name == "circle" ? rx : number("ry", 0);
    if (rx < 0 || ry < 0) reader.fail(tag.line, "<" + tag.name + "> with a negative radius");
    if (rx > 0 && ry > 0) shape.push_back(ellipse_polyline(cx, cy, rx, ry, options));
  }
  return shape;
}

bool is_hidden_container(const std::string& name) {
  return name == "defs" || name == "symbol" || name == "clipPath" || name == "mask" || name == "pattern" ||
         name == "marker" || name == "text" || name == "title" || name == "desc" || name == "metadata" || name == "style";
}

}  // namespace

namespace {

// The element tree: start tags in document order; subtree_end[i] is the index after the last
// descendant of tag i.
struct TagTree {
  std::vector<Tag> tags;
  std::vector<std::size_t> subtree_end;
  std::map<std::string, std::size_t> ids;
};

TagTree read_tag_tree(XmlReader& reader) {
  TagTree tree;
  std::vector<std::size_t> open;
  Tag tag;
  while (reader.next(tag)) {
    if (tag.closing) {
      if (open.empty()) reader.fail(tag.line, "end tag </" + tag.name + "> without a start tag");
      const Tag& start = tree.tags[open.back()];
      if (start.name != tag.name)
        reader.fail(tag.line, "end tag </" + tag.name + "> does not match <" + start.name + "> of line " + std::to_string(start.line));
      tree.subtree_end[open.back()] = tree.tags.size();
      open.pop_back();
      continue;
    }
    if (open.empty()) {
      if (!tree.tags.empty()) reader.fail(tag.line, "more than one root element");
      if (tag.name != "svg") reader.fail(tag.line, "root element is <" + tag.name + ">, not <svg>");
    }
    const std::size_t index = tree.tags.size();
    if (const auto it = tag.attributes.find("id"); it != tag.attributes.end()) tree.ids.emplace(it->second, index);
    tree.subtree_end.push_back(index + 1);
    if (!tag.self_closing) open.push_back(index);
    tree.tags.push_back(std::move(tag));
  }
  if (!open.empty()) reader.fail(tree.tags[open.back()].line, "<" + tree.tags[open.back()].name + "> is never closed");
  if (tree.tags.empty()) reader.fail(reader.line(), "no <svg> element");
  return tree;
}

struct TreeWalk {
  const TagTree& tree;
  const XmlReader& reader;
  const std::string& source;
  const SvgReadOptions& options;
  SvgDrawing& drawing;

  // Draws tag i and its subtree under `parent`; `via_use` draws a referenced symbol or an element
  // inside defs; `depth` counts nested <use> references.
  void walk(std::size_t i, const Affine2& parent, bool hidden, bool via_use, int depth) {
    const Tag& tag = tree.tags[i];
    Affine2 own;
    if (const auto it = tag.attributes.find("transform"); it != tag.attributes.end()) {
      try {
        own = parse_svg_transform(it->second);
      } catch (const InputError& e) {
        reader.fail(tag.line, e.what());
      }
    }
    const Affine2 transform = parent.then_after(own);
    const bool now_hidden = hidden || (!via_use && is_hidden_container(tag.name));
    if (!now_hidden && tag.name == "use") {
      draw_use(tag, transform, depth);
      return;
    }
    if (!now_hidden) {
      std::vector<Polyline> shape;
      try {
        shape = element_shape(tag, options, reader);
      } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.rfind(source + ":", 0) == 0) throw;
        reader.fail(tag.line, what);
      }
      if (!shape.empty()) {
        SvgElement element{tag.name, tag.line, {}};
        for (Polyline& polyline : shape) {
          for (Vec2& p : polyline) p = transform(p);
          element.polylines.push_back(std::move(polyline));
        }
        drawing.elements.push_back(std::move(element));
      }
    }
    for (std::size_t child = i + 1; child < tree.subtree_end[i]; child = tree.subtree_end[child])
      walk(child, transform, now_hidden, false, depth);
  }

  // <use href="#id" x y>: the referenced element drawn translated by (x, y).
  void draw_use(const Tag& tag, const Affine2& transform, int depth) {
    auto it = tag.attributes.find("href");
    if (it == tag.attributes.end()) it = tag.attributes.find("xlink:href");
    if (it == tag.attributes.end()) return;
    if (it->second.empty() || it->second[0] != '#') reader.fail(tag.line, "<use> refers to \"" + it->second + "\", not to #id");
    const auto target = tree.ids.find(it->second.substr(1));
    if (target == tree.ids.end()) reader.fail(tag.line, "<use> refers to the unknown id \"" + it->second.substr(1) + "\"");
    if (depth >= 32) reader.fail(tag.line, "<use> references nest too deep (a cycle?)");
    Affine2 shift;
    shift.offset = Vec2(attribute_number(tag, "x", 0, reader), attribute_number(tag, "y", 0, reader));
    walk(target->second, transform.then_after(shift), false, true, depth + 1);
  }
};

}  // namespace

SvgDrawing parse_svg(std::string_view text, const std::string& source, const SvgReadOptions& options) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  XmlReader reader(text, source);
  const TagTree tree = read_tag_tree(reader);
  SvgDrawing drawing;
  const Tag& root = tree.tags.front();
  double width = attribute_number(root, "width", 0, reader), height = attribute_number(root, "height", 0, reader);
  if (const auto it = root.attributes.find("viewBox"); it != root.attributes.end()) {
    std::vector<double> box;
    try {
      box = read_number_list(it->second, "viewBox");
    } catch (const InputError& e) {
      reader.fail(root.line, e.what());
    }
    if (box.size() != 4 || box[2] < 0 || box[3] < 0) reader.fail(root.line, "viewBox needs four numbers with a non-negative size");
    width = box[2];
    height = box[3];
  }
  drawing.width = width;
  drawing.height = height;
  TreeWalk{tree, reader, source, options, drawing}.walk(0, Affine2{}, false, false, 0);
  return drawing;
}

SvgDrawing read_svg(const std::filesystem::path& path, const SvgReadOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path.string() + ": cannot read");
  return parse_svg(buffer.str(), path.string(), options);
}

}  // namespace dg
