#pragma once
// JSON scheme files to Scheme and CurveScheme values. The language is documented in
// docs/scheme-format.md and schemes/scheme.schema.json.
#include <filesystem>
#include <functional>
#include <memory>
#include <set>

#include "framework/scheme/scheme.h"
#include "framework/scheme/scheme_registry.h"

namespace subdiv {

// Finds a curve scheme named in a surface scheme ("curve": name or relative path).
// Overrides the curve has parameters for are applied and added to `used`.
using CurveResolver = std::function<std::shared_ptr<const CurveScheme>(
    const std::string& name, const std::filesystem::path& referring_file,
    const ParameterOverrides& overrides, std::set<std::string>* used)>;

std::shared_ptr<const Scheme> load_surface_scheme(const std::filesystem::path& path,
                                                  const ParameterOverrides& overrides,
                                                  const CurveResolver& resolve_curve);
std::shared_ptr<const CurveScheme> load_curve_scheme(const std::filesystem::path& path,
                                                     const ParameterOverrides& overrides,
                                                     std::set<std::string>* used = nullptr);

// "surface" or "curve", from the file's "kind" (default surface).
std::string scheme_file_kind(const std::filesystem::path& path);

// The same from JSON text, for schemes that plugins carry; `label` stands for the file name
// in messages, and a relative "curve" path is resolved from its folder.
std::shared_ptr<const Scheme> load_surface_scheme_text(const std::string& text, const std::string& label,
                                                       const ParameterOverrides& overrides,
                                                       const CurveResolver& resolve_curve);
std::shared_ptr<const CurveScheme> load_curve_scheme_text(const std::string& text, const std::string& label,
                                                          const ParameterOverrides& overrides,
                                                          std::set<std::string>* used = nullptr);
std::string scheme_text_kind(const std::string& text, const std::string& label);

// Applies the overrides that name one of `params` (their names go to `used`) and checks
// every value against its range, with the messages of scheme files (`label` names the
// scheme). For schemes defined in code.
void apply_parameter_overrides(std::vector<ParameterSpec>& params, const ParameterOverrides& overrides,
                               const std::string& label, std::set<std::string>* used);

}  // namespace subdiv
