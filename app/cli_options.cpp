#include "app/cli_options.hpp"

#include <cmath>
#include <sstream>

namespace ll::cli {

Options::Options(const std::vector<std::string>& args, const std::set<std::string>& allowed, const std::set<std::string>& flags) {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.rfind("--", 0) != 0) {
            positional_.push_back(arg);
            continue;
        }
        std::string name = arg.substr(2), value;
        if (const size_t eq = name.find('='); eq != std::string::npos) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
        } else if (flags.count(name)) {
            value = "1";
        } else if (i + 1 < args.size()) {
            value = args[++i];
        } else if (allowed.count(name)) {
            throw UsageError(UsageId::OptionNeedsValue, name);
        }
        if (!allowed.count(name) && !flags.count(name)) {
            std::string known;
            for (const std::string& a : allowed) known += (known.empty() ? "--" : ", --") + a;
            for (const std::string& f : flags) known += (known.empty() ? "--" : ", --") + f;
            if (known.empty()) throw UsageError(UsageId::UnknownOption, name);
            throw UsageError(UsageId::UnknownOptionAmong, name, known);
        }
        values_[name] = value;
    }
}

std::string Options::text(const std::string& name, const std::string& fallback) const {
    const auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
}

double parseNumber(const std::string& option, const std::string& text) {
    std::istringstream in(text);
    double value = 0;
    in >> value;
    if (in.fail() || !in.eof() || !std::isfinite(value)) throw UsageError(UsageId::ExpectedFiniteNumber, option, text);
    return value;
}

double Options::number(const std::string& name, double fallback) const { return has(name) ? parseNumber(name, text(name)) : fallback; }

Eigen::VectorXd Options::vector(const std::string& name, int size) const {
    std::vector<double> values;
    std::stringstream in(text(name));
    std::string item;
    while (std::getline(in, item, ',')) values.push_back(parseNumber(name, item));
    if (static_cast<int>(values.size()) != size) throw UsageError(UsageId::ExpectedNumberPerJoint, name, size, values.size(), text(name));
    return Eigen::Map<Eigen::VectorXd>(values.data(), size);
}

namespace {
bool givenLanguage = false, givenNotation = false;
present::Presentation& chosen() {
    static present::Presentation p{present::languageFromEnvironment(), present::Notation::Notes};
    return p;
}
}  // namespace

void takePresentation(std::vector<std::string>& args, bool codegen) {
    for (std::size_t k = 0; k < args.size();) {
        const bool lang = args[k] == "--lang", notation = args[k] == "--notation";
        if (!lang && !notation) {
            ++k;
            continue;
        }
        if (k + 1 >= args.size()) throw UsageError(UsageId::NeedsValue, args[k].substr(2));
        const std::string value = args[k + 1];
        if (lang) {
            const auto l = present::languageNamed(value);
            if (!l || value == "C" || value == "POSIX") {
                if (codegen) {  // codegen's own --lang c|python
                    k += 2;
                    continue;
                }
                throw UsageError(UsageId::ExpectedOneOf, "lang", "da", "en", value);
            }
            chosen().language = *l;
            givenLanguage = true;
        } else {
            const auto n = present::notationNamed(value);
            if (!n) throw UsageError(UsageId::ExpectedOneOf, "notation", "notes, siciliano, spong", "craig", value);
            chosen().notation = *n;
            givenNotation = true;
        }
        args.erase(args.begin() + static_cast<std::ptrdiff_t>(k), args.begin() + static_cast<std::ptrdiff_t>(k) + 2);
    }
}

const present::Presentation& presentation() { return chosen(); }
bool languageGiven() { return givenLanguage; }
bool notationGiven() { return givenNotation; }

}  // namespace ll::cli
