#pragma once
// Command-line options of the form `--name value` after a positional argument.
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace ll::cli {

// Bad command-line input: exit code 2, one line.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Options {
public:
    // args: everything after the command name. `allowed`: option names without "--".
    // `flags`: options that take no value.
    Options(const std::vector<std::string>& args, const std::set<std::string>& allowed,
            const std::set<std::string>& flags = {});

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

}  // namespace ll::cli
