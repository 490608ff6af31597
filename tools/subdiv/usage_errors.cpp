#include "usage_errors.h"

#include <algorithm>
#include <cstdlib>
#include <fmt/format.h>
#include "framework/util/quoted_text.h"

namespace subdiv::cli {
namespace {

// Edit distance with adjacent transpositions counted as one edit ("levles" is one edit
// from "levels"): the optimal string alignment distance (Damerau 1964).
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string without_dashes(const std::string& s) { return s.substr(std::min(s.find_first_not_of('-'), s.size())); }

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(s->get_name());
  return names;
}

std::vector<std::string> long_options(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd.get_options())
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
  return names;
}

bool is_option_of(const CLI::App& cmd, const std::string& arg) {
  for (const CLI::Option* o : cmd.get_options())
    if (o->check_name(arg)) return true;
  return false;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string best = closest_spelling(word, candidates);
  return best.empty() ? "" : fmt::format("; did you mean `{}`?", best);
}

// CLI11's "--levels: 1 required INT:INT in [0 - 30] missing" in our words.
std::string reworded(const CLI::ParseError& e) {
  const std::string what = e.what();
  const size_t colon = what.find(": ");
  if (colon != std::string::npos && what.rfind("-", 0) == 0 && what.find(" required ") != std::string::npos &&
      what.size() > 8 && what.compare(what.size() - 8, 8, " missing") == 0)
    return fmt::format("{} needs a value ({})", what.substr(0, colon),
                       what.substr(colon + 2, what.size() - colon - 2 - 8));
  // CLI::NonNegativeNumber's range ends at the largest double, which CLI11 prints in full
  // (309 digits): "--threads: Value -1 not in range 0.000000 to 1797...".
  // It says the same of a value that is no number at all ("--threads: Value abc not in range").
  if (const size_t at = what.find(" not in range 0.000000 to 17976931348623157"); at != std::string::npos) {
    const size_t value = what.find(": Value ");
    if (value != std::string::npos && value < at) {
      const std::string given = what.substr(value + 8, at - value - 8);
      char* end = nullptr;
      std::strtod(given.c_str(), &end);
      if (given.empty() || *end != '\0')
        return fmt::format("{}: {} is not a number; give a whole number, 0 or more", what.substr(0, value),
                           subdiv::quoted(given));
    }
    return what.substr(0, at) + " is negative; give 0 or more";
  }
  // A value the option's type cannot hold: "Could not convert: --threads = 1e3".
  if (const std::string prefix = "Could not convert: "; what.rfind(prefix, 0) == 0) {
    const size_t equals = what.find(" = ", prefix.size());
    if (equals != std::string::npos)
      return fmt::format("{}: {} is not a value of its type (a whole number is written without a point or an "
                         "exponent); see its type in --help",
                         what.substr(prefix.size(), equals - prefix.size()), subdiv::quoted(what.substr(equals + 3)));
  }
  return what;
}

// The first word that is neither an option nor the value of the app's own --plugin.
std::string first_word(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--plugin") ++i;
    else if (a.empty() || a[0] != '-') return a;
    else if (!is_option_of(app, a.substr(0, a.find('=')))) return "";
  }
  return "";
}

// An option the chosen command does not have ("--levles"), or "".
std::string unknown_option(const CLI::App& app, const CLI::App& cmd, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") break;
    if (a.size() < 2 || a[0] != '-' || (a[1] != '-' && !std::isalpha(static_cast<unsigned char>(a[1])))) continue;
    const std::string name = a.substr(0, a.find('='));
    if (a[1] != '-' && name.size() > 2) {  // -l2: a short option with its value
      if (is_option_of(cmd, name.substr(0, 2)) || is_option_of(app, name.substr(0, 2))) continue;
    }
    if (!is_option_of(cmd, name) && !is_option_of(app, name)) return name;
  }
  return "";
}

}  // namespace

std::string closest_spelling(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string w = without_dashes(word);
  if (w.empty()) return "";
  std::string best;
  size_t best_distance = std::string::npos;
  for (const std::string& c : candidates) {
    const std::string bare = without_dashes(c);
    const size_t d = bare.rfind(w, 0) == 0 && w.size() >= 3 ? 1 : edit_distance(w, bare);  // a prefix is close
    if (d < best_distance) best = c, best_distance = d;
  }
  // One edit in four letters, at most three: "refin", "levles", "scheems"; not "foo" -> "pc".
  const size_t allowed = std::min<size_t>(3, std::max<size_t>(1, w.size() / 4));
  return best_distance <= allowed ? best : "";
}

std::string exit_code_help() {
  return fmt::format("Exit codes: 0 done; {} input or a value refused (the message says why and where); "
                     "{} usage error (an unknown command or option, a missing or malformed value); "
                     "{} internal error (a bug: please report it).",
                     kExitRefused, kExitUsage, kExitInternal);
}

int report_parse_error(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
  const std::vector<CLI::App*> chosen = app.get_subcommands();
  std::string message, help = "subdiv --help";
  if (chosen.empty()) {
    const std::string word = first_word(app, argc, argv);
    const std::vector<std::string> commands = command_names(app);
    const std::string option = unknown_option(app, app, argc, argv);
    if (!word.empty())
      message = fmt::format("unknown command {}{} The commands are: {}.", subdiv::quoted(word),
                            suggestion(word, commands).empty() ? "." : suggestion(word, commands), joined(commands));
    else if (!option.empty())
      message = fmt::format("unknown option {}; a command comes first: subdiv COMMAND [OPTIONS]", subdiv::quoted(option));
    else
      message = fmt::format("no command given; the commands are: {}", joined(commands));
  } else {
    const CLI::App& cmd = *chosen.back();
    help = fmt::format("subdiv {} --help", cmd.get_name());
    const std::string option = unknown_option(app, cmd, argc, argv);
    if (!option.empty())
      message = fmt::format("unknown option {} for `subdiv {}`{}", subdiv::quoted(option), cmd.get_name(),
                            suggestion(option, long_options(cmd)));
    else
      message = reworded(e);
  }
  fmt::print(stderr, "subdiv: error: {}\nRun `{}` for the options.\n", terminal_safe(message), help);
  return kExitUsage;
}

}  // namespace subdiv::cli
