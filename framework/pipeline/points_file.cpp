#include "framework/pipeline/points_file.h"

#include <cctype>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <tuple>

#include "framework/util/decimal_number.h"
#include "framework/util/error.h"
#include "framework/util/input_file.h"
#include "framework/util/quoted_text.h"
#include "framework/util/short_text.h"

namespace subdiv {
namespace {

std::string_view trimmed(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string_view::npos ? std::string_view() : s.substr(b, e - b + 1);
}

// A field as written, without the blanks around it and the double quotes a spreadsheet or R's
// write.csv puts around it ("face","u","v"; "0","0.5"): a field holds no comma, so quoting
// changes nothing else.
std::string_view unquoted(std::string_view s) {
  s = trimmed(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = trimmed(s.substr(1, s.size() - 2));
  return s;
}

bool same_letters(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// A face number written as a decimal with a whole value, "3.0" or "3e0": pandas writes a
// column of integers as floats once it holds a missing value, R's write.csv a double column.
// Empty when it is one (then `out` holds it), else why not.
std::string whole_decimal(std::string_view t, Index& out) {
  double x = 0;
  if (parse_decimal(t, x) != DecimalParse::ok || !std::isfinite(x) || x != std::floor(x)) return "is not a whole number";
  if (std::fabs(x) > double(std::numeric_limits<Index>::max())) return "is out of range";
  out = Index(x);
  return {};
}

// Empty when `text` is a whole number, else why not, for the message ("is not a whole number").
std::string parse_field(std::string_view text, Index& out) {
  std::string_view t = unquoted(text);
  // from_chars takes no '+', which spreadsheets may write: "+1" is a whole number.
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  if (ec == std::errc::result_out_of_range) return "is out of range";
  if (t.empty()) return "is not a whole number";
  if (ec != std::errc() || end != t.data() + t.size()) return whole_decimal(t, out);
  return {};
}

// The same for a u or v: one too small for a double (1e-400) is 0, as a subnormal (4e-320)
// is already close to it, and lies in the domain; one too large (1e400) is refused.
std::string parse_field(std::string_view text, double& out) {
  switch (parse_decimal(unquoted(text), out)) {
    case DecimalParse::ok:
      out += 0.0;  // -0.0 is the parameter 0 (the domain has no signed zero): echoed as 0, not "-0"
      return {};
    case DecimalParse::overflow: return "is out of range: larger than a double holds (about 1.8e308)";
    case DecimalParse::not_a_number: break;
  }
  return "is not a number";
}

// A field or header in a message: quoted as it is (control bytes escaped, quoted_text.h), its
// beginning only when it is long — a 10 MB line made a 10 MB message.
std::string shown(std::string_view text) {
  if (text.size() <= kQuotedTextChars) return subdiv::quoted(text);
  return fmt::format("{}... ({} characters)", subdiv::quoted(text.substr(0, kQuotedTextChars)), text.size());
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

// face,u,v in any case ("Face,U,V"), each name possibly quoted.
bool is_header(std::string_view line) {
  const std::vector<std::string_view> fields = split(without_utf8_bom(line), ',');
  return fields.size() == 3 && same_letters(unquoted(fields[0]), "face") && same_letters(unquoted(fields[1]), "u") &&
         same_letters(unquoted(fields[2]), "v");
}

void check_header(std::string_view line, const std::string& file) {
  // Classic Mac OS ("CSV (Macintosh)") ends lines in CR alone: the whole file is one line.
  if (trimmed(line).find('\r') != std::string_view::npos && !is_header(line))
    throw Error(fmt::format("{} line 1: the lines end in a carriage return alone (CR, old Mac text); save the file "
                            "with LF or CRLF line endings",
                            file));
  if (is_header(line)) return;
  // A spreadsheet in a locale with decimal commas separates its fields with ';'.
  const bool semicolons = line.find(';') != std::string_view::npos && line.find(',') == std::string_view::npos;
  throw Error(fmt::format("{} line 1: the header is {}; it must be 'face,u,v'{}", file, shown(trimmed(line)),
                          semicolons ? " (the fields are separated by ';': save the file with ',' between fields "
                                       "and '.' as the decimal point)"
                                     : ""));
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
  if (const std::string why = parse_field(fields[0], face); !why.empty())
    throw Error(fmt::format("{}: face {} {}", where, shown(trimmed(fields[0])), why));
  for (const auto& [name, field, value] : {std::tuple{"u", fields[1], &u}, std::tuple{"v", fields[2], &v}})
    if (const std::string why = parse_field(field, *value); !why.empty())
      throw Error(fmt::format("{}: {} = {} {}; u and v must be numbers", where, name, shown(unquoted(field)), why));
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
SurfacePoints read_points_file(const std::string& file, const PointCheck& check,
                               const std::function<void(double done)>& fraction) {
  // A FIFO would block, /dev/zero would fill memory with one endless line, and a directory
  // would read as an empty file: each is named for what it is first.
  check_input_file(file, "points (.csv)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read {}: no such file or it is not readable", subdiv::quoted(file)));
  std::string line;
  if (!std::getline(in, line)) throw Error(fmt::format("{}: empty file; the first line must be 'face,u,v'", file));
  check_header(line, file);
  SurfacePoints out;
  std::error_code ec;
  const double bytes = double(std::filesystem::file_size(file, ec));
  constexpr size_t kRowsPerReport = 1 << 16;
  for (size_t number = 2; std::getline(in, line); ++number) {
    parse_row(line, number, file, check, out);
    if (fraction && !ec && bytes > 0 && number % kRowsPerReport == 0) fraction(std::min(1.0, double(in.tellg()) / bytes));
  }
  check_not_empty(out, file);
  return out;
}

}  // namespace subdiv
