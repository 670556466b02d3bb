// XYZ point reader: one point per line, "x y z" or "x y z nx ny nz"; '#' starts a comment.

#include "geometry/model_reader.h"
#include "geometry/text_reader.h"

namespace dg::detail {

Model read_xyz(const std::string& name, std::string_view text) {
  Model model;
  PointCloud& cloud = model.cloud;
  cloud.positions.reserve(text.size() / 32);
  int columns = 0;  // 3 or 6, fixed by the first point
  LineReader reader(text);
  std::string_view line;
  while (reader.next(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    double values[6];
    int count = 0;
    std::string_view rest = line;
    for (std::string_view token = next_token(rest); !token.empty(); token = next_token(rest)) {
      if (count == 6 || !parse_number(token, values[count])) {
        throw_line_error(name, reader.line(), "malformed point (expected 'x y z' or 'x y z nx ny nz')");
      }
      ++count;
    }
    if (count == 0) continue;
    if (count != 3 && count != 6) {
      throw_line_error(name, reader.line(), "malformed point (expected 'x y z' or 'x y z nx ny nz')");
    }
    if (columns == 0) columns = count;
    if (count != columns) {
      throw_line_error(name, reader.line(),
                       "point has " + std::to_string(count) + " values but earlier points have " +
                           std::to_string(columns));
    }
    cloud.positions.emplace_back(values[0], values[1], values[2]);
    if (count == 6) cloud.normals.emplace_back(values[3], values[4], values[5]);
  }
  return model;
}

}  // namespace dg::detail
