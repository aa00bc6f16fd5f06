#pragma once
// Command-line options of the form `--name value` after a positional argument.
// Bad input throws UsageError (app/usage_error.hpp).
#include <map>
#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "app/usage_error.hpp"
#include "core/present/localized_document.hpp"

namespace ll::cli {

class Options {
public:
    // args: everything after the command name. `allowed`: option names without "--".
    // `flags`: options that take no value.
    Options(const std::vector<std::string>& args, const std::set<std::string>& allowed, const std::set<std::string>& flags = {});

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::string text(const std::string& name, const std::string& fallback = "") const;
    double number(const std::string& name, double fallback) const;  // finite, else UsageError
    // "v1,v2,..." of exactly `size` finite numbers.
    Eigen::VectorXd vector(const std::string& name, int size) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
};

double parseNumber(const std::string& option, const std::string& text);

// The language and notation every command takes (`--lang da|en`, `--notation
// notes|siciliano|spong|craig`), taken out of `args`; without --lang, LANGUAGE, LC_ALL,
// LC_MESSAGES and LANG decide as Debian's tools read them (English by default). codegen's
// own --lang c|python is left in place. The process keeps it: presentation().
void takePresentation(std::vector<std::string>& args, bool codegen);
const present::Presentation& presentation();
// Whether --lang / --notation was given (else the environment's language, the notes').
bool languageGiven();
bool notationGiven();

}  // namespace ll::cli
