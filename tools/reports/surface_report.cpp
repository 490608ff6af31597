#include "surface_report.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace subdiv {
namespace {

std::string number(double x) { return fmt::format("{:.6g}", std::abs(x) < 5e-13 ? 0.0 : x); }

std::string complex_text(std::complex<double> z) {
  if (std::abs(z.imag()) < 1e-7 * std::max(1.0, std::abs(z))) return number(z.real());
  return fmt::format("{}{}{}i", number(z.real()), z.imag() < 0 ? "-" : "+", number(std::abs(z.imag())));
}

nlohmann::json complex_json(std::complex<double> z) {
  if (std::abs(z.imag()) < 1e-7 * std::max(1.0, std::abs(z))) return z.real();
  return nlohmann::json{{"re", z.real()}, {"im", z.imag()}};
}

nlohmann::json eigen_json(const std::vector<std::complex<double>>& ev) {
  nlohmann::json a = nlohmann::json::array();
  for (auto z : ev) a.push_back(complex_json(z));
  return a;
}

std::string yes(bool b) { return b ? "yes" : "no"; }

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// An SVG document's opening: size, white background, the title at the top left.
std::string svg_start(int W, int H, double left, const std::string& title) {
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      W, H, W, H);
  s += fmt::format("<text x=\"{}\" y=\"22\" font-size=\"15\">{}</text>\n", left, xml_escape(title));
  return s;
}

// Horizontal grid lines and labels at moduli 0, 0.2, ..., 1; Y maps a modulus to a row.
template <typename RowOf>
std::string modulus_grid(double left, double pw, RowOf Y) {
  std::string s;
  for (int t = 0; t <= 5; ++t) {
    const double v = 0.2 * t, y = Y(v);
    s += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", left, y, left + pw, y);
    s += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{:.1f}</text>\n", left - 6, y + 4, v);
  }
  return s;
}

}  // namespace

std::vector<std::string> surface_summary_lines(const SurfaceAnalysis& a) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format("{} at {}", a.scheme, a.config.describe()));
  if (!a.error.empty()) {
    lines.push_back("verdict: " + a.verdict);
    return lines;
  }
  lines.push_back(fmt::format("steps per analysed step: {}{}", a.steps, a.steps == 2 ? " (R S^2: the rotation undone)" : ""));
  lines.push_back(fmt::format("minimal invariant neighbourhood: {}-ring, {} points; analysed: {}-ring, {} points",
                              a.minimal_ring, a.minimal_size, a.ring, a.size));
  std::string ev;
  for (size_t i = 0; i < a.eigenvalues.size() && i < 12; ++i) ev += (i ? ", " : "") + complex_text(a.eigenvalues[i]);
  if (a.eigenvalues.size() > 12) ev += fmt::format(", ... ({} in all)", a.eigenvalues.size());
  lines.push_back("eigenvalues: " + ev);
  lines.push_back(fmt::format("affine (rows sum to 1): {}", yes(a.affine)));
  lines.push_back(fmt::format("lambda_0 = 1 simple: {}", yes(a.lambda0_one)));
  lines.push_back(fmt::format("lambda_1 = {}, lambda_2 = {}: real {}, equal {}, two eigenvectors {}", number(a.lambda1),
                              number(a.lambda2), yes(a.subdominant_real), yes(a.subdominant_equal), yes(a.subdominant_semisimple)));
  lines.push_back(fmt::format("|lambda_3| = {} < lambda_2: {}", number(a.lambda3), yes(a.subdominant_dominates)));
  if (!a.curvature.empty()) lines.push_back("curvature: " + a.curvature);
  const auto& cm = a.characteristic_map;
  if (cm.computed)
    lines.push_back(fmt::format("characteristic map ({} steps, {} faces): regular {}, injective {}{}{}", cm.refinement_steps,
                                cm.faces, yes(cm.regular), yes(cm.injective),
                                cm.winding_checked ? fmt::format(", winding number {}", cm.winding) : "",
                                cm.note.empty() ? "" : " (" + cm.note + ")"));
  else if (!cm.note.empty())
    lines.push_back("characteristic map: " + cm.note);
  if (a.has_limit_mask) {
    std::string mask;
    for (size_t i = 0; i < a.limit_mask.size() && i < 16; ++i) mask += (i ? ", " : "") + number(a.limit_mask[i]);
    if (a.limit_mask.size() > 16) mask += ", ...";
    lines.push_back(fmt::format("limit mask (labels 0..{}): {}", a.limit_mask.size() - 1, mask));
  }
  lines.push_back("verdict: " + a.verdict);
  return lines;
}

nlohmann::json surface_json(const SurfaceAnalysis& a) {
  nlohmann::json j;
  j["configuration"] = a.config.describe();
  j["centre"] = a.config.centre == CentreKind::Face ? "face" : "vertex";
  j["valence"] = a.config.valence;
  j["boundary"] = a.config.boundary;
  j["verdict"] = a.verdict;
  j["c1"] = a.c1;
  if (!a.error.empty()) {
    j["error"] = a.error;
    return j;
  }
  j["steps"] = a.steps;
  j["minimal_ring"] = a.minimal_ring;
  j["minimal_size"] = a.minimal_size;
  j["ring"] = a.ring;
  j["size"] = a.size;
  j["eigenvalues"] = eigen_json(a.eigenvalues);
  j["minimal_eigenvalues"] = eigen_json(a.minimal_eigenvalues);
  j["crease_eigenvalues"] = eigen_json(a.crease_eigenvalues);
  j["checks"] = {{"affine", a.affine},
                 {"lambda0_simple_one", a.lambda0_one},
                 {"subdominant_real", a.subdominant_real},
                 {"subdominant_equal", a.subdominant_equal},
                 {"subdominant_two_eigenvectors", a.subdominant_semisimple},
                 {"subdominant_dominates", a.subdominant_dominates}};
  j["lambda1"] = a.lambda1;
  j["lambda2"] = a.lambda2;
  j["abs_lambda3"] = a.lambda3;
  j["lambda1_squared"] = a.lambda1 * a.lambda1;
  j["curvature"] = a.curvature;
  const auto& cm = a.characteristic_map;
  j["characteristic_map"] = {{"computed", cm.computed}, {"regular", cm.regular},       {"injective", cm.injective},
                             {"winding", cm.winding},   {"faces", cm.faces},           {"folded", cm.folded},
                             {"min_area_ratio", cm.min_area_ratio}, {"note", cm.note}};
  j["limit_mask"] = a.has_limit_mask ? nlohmann::json(a.limit_mask) : nlohmann::json(nullptr);
  j["tangent_masks"] = a.has_tangent_masks ? nlohmann::json{a.tangent_u, a.tangent_v} : nlohmann::json(nullptr);
  j["label_distance"] = a.distance;
  return j;
}

std::string surface_table(const std::vector<SurfaceAnalysis>& analyses) {
  std::string out = fmt::format("{:>4} {:>5} {:>9} {:>10} {:>10} {:>10} {:>10}  {:<6} {:<5} {:<7}  {}\n", "n", "steps",
                                "points", "lambda_1", "lambda_2", "|lambda_3|", "lambda_1^2", "l1=l2", "|l3|<", "charmap",
                                "verdict");
  for (const auto& a : analyses) {
    if (!a.error.empty()) {
      out += fmt::format("{:>4} {}\n", a.config.valence, a.verdict);
      continue;
    }
    const auto& cm = a.characteristic_map;
    const std::string charmap = !cm.computed ? "-" : cm.injective ? "ok" : cm.regular ? "overlap" : "folded";
    out += fmt::format("{:>4} {:>5} {:>4}/{:<4} {:>10} {:>10} {:>10} {:>10}  {:<6} {:<5} {:<7}  {}\n", a.config.valence,
                       a.steps, a.minimal_size, a.size, number(a.lambda1), number(a.lambda2), number(a.lambda3),
                       number(a.lambda1 * a.lambda1), yes(a.subdominant_equal), yes(a.subdominant_dominates), charmap,
                       a.verdict);
  }
  return out;
}

nlohmann::json surface_report_json(const std::vector<SurfaceAnalysis>& analyses) {
  nlohmann::json j;
  j["kind"] = "surface";
  if (!analyses.empty()) {
    j["scheme"] = analyses.front().scheme;
    j["path"] = analyses.front().path;
    j["centre"] = analyses.front().config.centre == CentreKind::Face ? "face" : "vertex";
  }
  j["analyses"] = nlohmann::json::array();
  for (const auto& a : analyses) j["analyses"].push_back(surface_json(a));
  return j;
}

std::string spectrum_svg(const std::vector<SurfaceAnalysis>& analyses, const std::string& title, int shown) {
  const double W = 640, H = 420, left = 60, right = 150, top = 40, bottom = 50;
  const double pw = W - left - right, ph = H - top - bottom;
  int lo = 1 << 30, hi = -1;
  for (const auto& a : analyses) lo = std::min(lo, a.config.valence), hi = std::max(hi, a.config.valence);
  if (hi < lo) lo = 3, hi = 12;
  if (hi == lo) --lo, ++hi;
  auto X = [&](double n) { return left + pw * (n - lo) / double(hi - lo); };
  auto Y = [&](double v) { return top + ph * (1.0 - std::clamp(v, 0.0, 1.05) / 1.05); };
  std::string s = svg_start(W, H, left, title);
  // Axes and grid.
  s += modulus_grid(left, pw, Y);
  for (int n = lo; n <= hi; ++n) {
    const double x = X(n);
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{}\" x2=\"{:.1f}\" y2=\"{}\" stroke=\"#eee\"/>\n", x, top, x, top + ph);
    s += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", x, top + ph + 16, n);
  }
  s += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", left, top, pw, ph);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">valence n</text>\n", left + pw / 2, H - 12);
  s += fmt::format("<text transform=\"translate(16,{}) rotate(-90)\" text-anchor=\"middle\">|lambda_i|</text>\n", top + ph / 2);
  // lambda_1^2 as a polyline, lambda_1 as a polyline, all moduli as dots.
  std::string l1_line, sq_line;
  for (const auto& a : analyses) {
    if (!a.error.empty() || a.eigenvalues.size() < 2) continue;
    const double x = X(a.config.valence);
    l1_line += fmt::format("{:.1f},{:.1f} ", x, Y(std::abs(a.eigenvalues[1])));
    sq_line += fmt::format("{:.1f},{:.1f} ", x, Y(std::norm(a.eigenvalues[1])));
    for (int i = 0; i < shown && i < int(a.eigenvalues.size()); ++i) {
      const double v = std::abs(a.eigenvalues[size_t(i)]);
      const char* colour = i == 0 ? "#000" : i <= 2 ? "#d62728" : "#1f77b4";
      s += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{}\" fill=\"{}\" fill-opacity=\"0.75\"><title>n={} "
                       "|lambda_{}|={:.6g}</title></circle>\n",
                       x, Y(v), i <= 2 ? 4 : 3, colour, a.config.valence, i, v);
    }
  }
  if (!l1_line.empty()) {
    s += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"#d62728\"/>\n", l1_line);
    s += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"#2ca02c\" stroke-dasharray=\"5,3\"/>\n", sq_line);
  }
  // Legend.
  const double lx = left + pw + 12;
  s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"#000\"/><text x=\"{}\" y=\"{}\">lambda_0</text>\n", lx, top + 10, lx + 10, top + 14);
  s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"#d62728\"/><text x=\"{}\" y=\"{}\">lambda_1, lambda_2</text>\n", lx, top + 30, lx + 10, top + 34);
  s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"#1f77b4\"/><text x=\"{}\" y=\"{}\">lambda_3 ...</text>\n", lx, top + 50, lx + 10, top + 54);
  s += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#2ca02c\" stroke-dasharray=\"5,3\"/><text x=\"{}\" y=\"{}\">lambda_1^2</text>\n",
                   lx - 4, top + 70, lx + 6, top + 70, lx + 10, top + 74);
  s += "</svg>\n";
  return s;
}

std::string eigenvalue_svg(const std::vector<std::complex<double>>& eigenvalues, const std::string& title) {
  const double W = 520, H = 360, left = 60, right = 20, top = 40, bottom = 50;
  const double pw = W - left - right, ph = H - top - bottom;
  const int count = std::max<int>(2, int(eigenvalues.size()));
  auto X = [&](double i) { return left + pw * (i + 0.5) / double(count); };
  auto Y = [&](double v) { return top + ph * (1.0 - std::clamp(v, 0.0, 1.05) / 1.05); };
  std::string s = svg_start(W, H, left, title);
  s += modulus_grid(left, pw, Y);
  s += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", left, top, pw, ph);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">index i</text>\n", left + pw / 2, H - 12);
  s += fmt::format("<text transform=\"translate(16,{}) rotate(-90)\" text-anchor=\"middle\">|lambda_i|</text>\n", top + ph / 2);
  for (size_t i = 0; i < eigenvalues.size(); ++i) {
    const double v = std::abs(eigenvalues[i]);
    s += fmt::format("<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#1f77b4\" stroke-width=\"6\"/>"
                     "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>"
                     "<title>lambda_{} = {}</title>\n",
                     X(double(i)), Y(0), X(double(i)), Y(v), X(double(i)), top + ph + 16, i, i, complex_text(eigenvalues[i]));
  }
  s += "</svg>\n";
  return s;
}

}  // namespace subdiv
