#pragma once
// `subdiv validate`: structural checks (the loader), then semantic checks over valences:
// each rule is affine (weights sum to one) and symmetric where its neighbourhood is.
#include <string>
#include <vector>

namespace subdiv {

struct ValidationIssue {
  std::string message;  // "file:line: rules.vertex (smooth): ..."
};

struct ValidationReport {
  std::string scheme_name, kind;
  std::vector<ValidationIssue> errors;
  int checks = 0;  // how many (rule, valence) combinations were checked
  // Why (part of) the scheme could not be checked: a plugin's rules written in C++. Empty when
  // everything was checked.
  std::string skipped;
  // What the scheme cannot do, though nothing in it is wrong (it refines no boundaries).
  std::vector<std::string> notes;
  bool ok() const { return errors.empty(); }
};

// The valences validation may check. Edge rules are checked for every pair of end
// valences, so the work grows with the square of the range: the bound keeps it to seconds.
constexpr int kMinCheckedValence = 2;
constexpr int kMaxCheckedValence = 128;

// Loads and checks a scheme file, or a scheme a plugin registered (by name: its JSON rules are
// checked like a file's, rules written in C++ are reported in `skipped`); load errors become
// the report's single error. Throws
// subdiv::Error unless kMinCheckedValence <= min_valence <= max_valence <= kMaxCheckedValence.
ValidationReport validate_scheme_file(const std::string& path, int min_valence = 3, int max_valence = 16);

}  // namespace subdiv
