#include "framework/pipeline/points_file.h"

#include <charconv>
#include <fmt/format.h>
#include <fstream>

#include "framework/util/error.h"
#include "framework/util/quoted_text.h"

namespace subdiv {
namespace {

std::string_view trimmed(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string_view::npos ? std::string_view() : s.substr(b, e - b + 1);
}

template <class T>
bool parse_field(std::string_view text, T& out) {
  const std::string_view t = trimmed(text);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  return ec == std::errc() && end == t.data() + t.size() && !t.empty();
}

std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> fields;
  size_t start = 0;
  for (size_t comma = line.find(separator); comma != std::string_view::npos; comma = line.find(separator, start)) {
    fields.push_back(line.substr(start, comma - start));
    start = comma + 1;
  }
  fields.push_back(line.substr(start));
  return fields;
}

void check_header(std::string_view line, const std::string& file) {
  if (trimmed(line) != "face,u,v")
    throw Error(fmt::format("{} line 1: the header is {}; it must be 'face,u,v'", file, subdiv::quoted(trimmed(line))));
}

// Line `number` (from 1) of the file, after the header.
void parse_row(std::string_view line, size_t number, const std::string& file, const PointCheck& check,
               SurfacePoints& out) {
  if (trimmed(line).empty()) return;
  const std::string where = fmt::format("{} line {} (row {})", file, number, out.size() + 1);
  const std::vector<std::string_view> fields = split(line, ',');
  if (fields.size() != 3) throw Error(fmt::format("{}: {} fields; a row is face,u,v", where, fields.size()));
  Index face = 0;
  double u = 0, v = 0;
  if (!parse_field(fields[0], face))
    throw Error(fmt::format("{}: face {} is not a whole number", where, subdiv::quoted(trimmed(fields[0]))));
  if (!parse_field(fields[1], u) || !parse_field(fields[2], v))
    throw Error(fmt::format("{}: u and v must be numbers", where));
  if (const std::string why = check(face, u, v); !why.empty()) throw Error(fmt::format("{}: {}", where, why));
  out.faces.push_back(face);
  out.uv.insert(out.uv.end(), {u, v});
}

void check_not_empty(const SurfacePoints& points, const std::string& file) {
  if (points.faces.empty()) throw Error(fmt::format("{}: no points after the header", file));
}

}  // namespace

SurfacePoints parse_points(std::string_view text, const std::string& file, const PointCheck& check) {
  if (text.empty()) throw Error(fmt::format("{}: empty file; the first line must be 'face,u,v'", file));
  const std::vector<std::string_view> lines = split(text, '\n');
  check_header(lines.front(), file);
  SurfacePoints out;
  for (size_t number = 2; number <= lines.size(); ++number) parse_row(lines[number - 1], number, file, check, out);
  check_not_empty(out, file);
  return out;
}

// Line by line, so that a large file is never held whole.
SurfacePoints read_points_file(const std::string& file, const PointCheck& check) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read {}: no such file or it is not readable", subdiv::quoted(file)));
  std::string line;
  if (!std::getline(in, line)) throw Error(fmt::format("{}: empty file; the first line must be 'face,u,v'", file));
  check_header(line, file);
  SurfacePoints out;
  for (size_t number = 2; std::getline(in, line); ++number) parse_row(line, number, file, check, out);
  check_not_empty(out, file);
  return out;
}

}  // namespace subdiv
