// A set of exercises from one scene: the students' robots drawn from the seed, the
// manifest, the fingerprints and the answer templates (core/pipeline/exercise_set.hpp).
#include "core/pipeline/exercise_set.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <regex>
#include <set>
#include <stdexcept>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_derivation.hpp"

namespace ll {
namespace {

std::uint64_t fnv1a(const std::string& text, std::uint64_t hash = 0xcbf29ce484222325ull) {
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 0x100000001b3ull;
    }
    return hash;
}

// splitmix64: a small generator whose numbers are the same on every platform and library.
std::uint64_t nextRandom(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double power10(int decimals) { return std::pow(10.0, decimals); }

// The grid's ends as whole numbers of 10^-decimals.
std::pair<long long, long long> gridEnds(const ParameterRange& r) {
    const double scale = power10(r.decimals);
    const long long low = static_cast<long long>(std::ceil(r.low * scale - 1e-9));
    const long long high = static_cast<long long>(std::floor(r.high * scale + 1e-9));
    return {low, std::max(low, high)};
}

// The names a field's expression uses (identifiers), in order.
std::vector<std::string> namesIn(const std::string& text) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (std::isalpha(c) || c == '_') {
            std::size_t end = i + 1;
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
            names.push_back(text.substr(i, end - i));
            i = end;
        } else if (std::isdigit(c) || c == '.') {  // a number, with its exponent (1e-3)
            ++i;
            while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
        } else {
            ++i;
        }
    }
    return names;
}

// A robot field's unit by its path (robot.joints[1].com[0] → m), "" for the others.
std::string fieldUnit(const std::string& path) {
    const std::string prefix = "robot.joints[";
    if (path.rfind(prefix, 0) != 0) return "";
    const std::size_t dot = path.find("].", prefix.size());
    if (dot == std::string::npos) return "";
    std::string field = path.substr(dot + 2);
    field = field.substr(0, field.find_first_of(".["));
    if (field == "a" || field == "d" || field == "com") return "m";
    if (field == "mass") return "kg";
    if (field == "inertia") return "kg·m²";
    return "";
}

// Every parameter a physical field uses, with the unit it gives (""): the robot's a, d,
// mass, centre of mass and inertia, a Lagrangian's energies and forces.
std::vector<std::pair<std::string, std::string>> physicalUses(const Scene& scene) {
    std::set<std::string> parameters;
    for (const auto& [name, value] : scene.parameters) parameters.insert(name);
    std::vector<std::pair<std::string, std::string>> uses;
    auto use = [&](const std::string& text, const std::string& unit) {
        for (const std::string& name : namesIn(text))
            if (parameters.count(name)) uses.emplace_back(name, unit);
    };
    for (const auto& [path, text] : scene.expressions) {
        // a field's unit is its names' when the field adds or halves them (a, lc1-a1, l1/2);
        // in a product (m1*l1^2/12) the names' units are not the field's
        const std::string unit = fieldUnit(path);
        if (!unit.empty()) use(text, text.find_first_of("*^") == std::string::npos ? unit : "");
    }
    if (scene.lagrangian) {
        use(scene.lagrangian->kinetic, "");
        use(scene.lagrangian->potential, "");
        for (const std::string& force : scene.lagrangian->forces) use(force, "");
    }
    return uses;
}

// `value` with `decimals` decimals (the grid's).
std::string formatValue(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

}  // namespace

ParameterRange roundedRange(const std::string& name, double low, double high) {
    ParameterRange r{name, low, high, 0};
    const double width = high - low;
    if (width > 0) {
        r.decimals = std::clamp(static_cast<int>(-std::floor(std::log10(width / 10))), 0, 6);
    } else {  // one value: as many decimals as it has, to six
        while (r.decimals < 6 && std::abs(low * power10(r.decimals) - std::round(low * power10(r.decimals))) > 1e-9) ++r.decimals;
    }
    const auto [lo, hi] = gridEnds(r);
    r.low = lo / power10(r.decimals);
    r.high = hi / power10(r.decimals);
    return r;
}

std::string shortNumber(double value) {
    if (value == 0.0) return "0";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::vector<RobotTableRow> robotTable(const Scene& scene) {
    std::vector<RobotTableRow> rows;
    auto shown = [&](const std::string& path, double value, bool angle) -> std::string {
        if (auto it = scene.expressions.find(path); it != scene.expressions.end()) return it->second;
        if (angle && value != 0.0) {  // k/12 π, reduced
            const double twelfths = value / (M_PI / 12);
            const long k = std::lround(twelfths);
            if (std::abs(twelfths - k) < 1e-9) {
                const long g = std::gcd(std::abs(k), 12L), num = k / g, den = 12 / g;
                std::string t = num == 1 ? "π" : num == -1 ? "−π" : std::to_string(num) + "π";
                return den == 1 ? t : t + "/" + std::to_string(den);
            }
        }
        return shortNumber(value);
    };
    for (std::size_t i = 0; i < scene.robot.joints.size(); ++i) {
        const Joint& j = scene.robot.joints[i];
        const std::string path = "robot.joints[" + std::to_string(i) + "]";
        RobotTableRow row;
        row.prismatic = j.dh.type == JointType::Prismatic;
        row.a = shown(path + ".a", j.dh.a, false);
        row.alpha = shown(path + ".alpha", j.dh.alpha, true);
        const std::string q = "q" + std::to_string(i + 1);
        const auto plusQ = [&](const std::string& constant) { return constant == "0" ? q : constant + " + " + q; };
        row.d = shown(path + ".d", j.dh.d, false);
        row.theta = shown(path + ".theta", j.dh.theta, true);
        (row.prismatic ? row.d : row.theta) = plusQ(row.prismatic ? row.d : row.theta);
        row.mass = shown(path + ".mass", j.link.mass, false);
        for (int k = 0; k < 3; ++k) row.com[k] = shown(path + ".com[" + std::to_string(k) + "]", j.link.com[k], false);
        const char* names[6] = {"xx", "yy", "zz", "xy", "xz", "yz"};
        const int r[6] = {0, 1, 2, 0, 0, 1}, c[6] = {0, 1, 2, 1, 2, 2};
        for (int k = 0; k < 6; ++k) row.inertia[k] = shown(path + ".inertia." + names[k], j.link.inertia(r[k], c[k]), false);
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string entryLatex(const std::string& id) {
    static const std::regex indexed(R"(([A-Za-z]+)([0-9]+))");
    static const std::regex item(R"(([A-Za-z]+)_\{?([A-Za-z0-9]+)\}?(?:\^\{?([A-Za-z0-9]+)\}?)?(?:\(([0-9]+)(?:,([0-9]+))?\))?)");
    static const std::regex word(R"(([A-Za-z])_([a-z]+))");
    std::smatch m;
    if (id.rfind("equation", 0) == 0) return id;  // a word, not e·q·u… with an index
    if (std::regex_match(id, m, indexed)) return m.str(1) + "_{" + m.str(2) + "}";
    if (std::regex_match(id, m, word)) return m.str(1) + "_{" + m.str(2) + "}";
    if (std::regex_match(id, m, item)) {
        std::string sub = m.str(2);
        if (m[4].matched) {
            const bool wide = m.str(4).size() > 1 || m.str(5).size() > 1;
            sub += "," + m.str(4) + (m[5].matched ? (wide ? "," : "") + m.str(5) : "");
        }
        return m.str(1) + "_{" + sub + "}" + (m[3].matched ? "^{" + m.str(3) + "}" : "");
    }
    return id;
}

std::vector<ParameterRange> defaultRanges(const Scene& scene) {
    std::set<std::string> used;
    for (const auto& [name, unit] : physicalUses(scene)) used.insert(name);
    std::vector<ParameterRange> ranges;
    for (const auto& [name, value] : scene.parameters) {
        if (!used.count(name) || value == 0.0) continue;
        if (scene.expressions.count("parameters." + name)) continue;  // an expression of others: follows them
        const double a = 0.8 * value, b = 1.2 * value;
        ranges.push_back(roundedRange(name, std::min(a, b), std::max(a, b)));
    }
    return ranges;
}

std::vector<std::string> usedParameters(const Scene& scene) {
    std::set<std::string> used;
    for (const auto& [name, unit] : physicalUses(scene)) used.insert(name);
    std::vector<std::string> names;
    for (const auto& [name, value] : scene.parameters)
        if (used.count(name)) names.push_back(name);
    return names;
}

std::map<std::string, std::string> parameterUnits(const Scene& scene) {
    std::map<std::string, std::string> units;
    std::set<std::string> conflicting;
    for (const auto& [name, unit] : physicalUses(scene)) {
        if (unit.empty()) continue;
        auto [it, inserted] = units.emplace(name, unit);
        if (!inserted && it->second != unit) conflicting.insert(name);
    }
    for (const std::string& name : conflicting) units.erase(name);
    return units;
}

namespace {

// Every number as the double it stands for: 2, 2.0 and 2e0 are one value, whichever a
// program that saved the file wrote.
void numbersAsValues(nlohmann::json& j) {
    if (j.is_number()) j = j.get<double>();
    else if (j.is_structured())
        for (nlohmann::json& child : j) numbersAsValues(child);
}

}  // namespace

std::string sceneFingerprint(const std::string& sceneText) {
    nlohmann::json canonical = nlohmann::json::parse(sceneText);  // keys sorted
    if (canonical.is_object()) canonical.erase("exercise");       // the student's work on the robot, not the robot
    numbersAsValues(canonical);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(canonical.dump())));
    return hex;
}

const ExerciseStudent* ExerciseSet::student(const std::string& id) const {
    for (const ExerciseStudent& s : students)
        if (s.id == id) return &s;
    return nullptr;
}

ExerciseSet makeExerciseSet(const ExerciseSpec& spec) {
    std::vector<nlohmann::ordered_json> family;
    std::vector<ExerciseSet::Member> members;
    for (const ExerciseScene& member : spec.scenes) {
        family.push_back(nlohmann::ordered_json::parse(member.text));
        members.push_back({member.file, member.ranges});
    }
    ExerciseSet set{.name = family.at(0).value("name", members.at(0).file),
                    .scenes = members,
                    .seed = spec.seed,
                    .mode = spec.mode,
                    .entries = spec.entries,
                    .dhTable = spec.dhTable,
                    .students = {}};
    std::set<std::vector<long long>> drawn;  // the grids' numbers of every robot so far
    for (const std::string& id : spec.students) {
        ExerciseStudent student;
        student.id = id;
        std::uint64_t pick = spec.seed ^ fnv1a(id) ^ 0x2545f4914f6cdd1dull;
        const std::size_t m = family.size() == 1 ? 0 : static_cast<std::size_t>(nextRandom(pick) % family.size());
        const nlohmann::ordered_json& base = family[m];
        const std::vector<ParameterRange>& ranges = members[m].ranges;
        student.scene = members[m].file;
        std::vector<long long> grid{static_cast<long long>(m)};
        for (int attempt = 0; attempt < 64; ++attempt) {  // a robot no earlier student has, when the ranges allow
            std::uint64_t state = spec.seed ^ fnv1a(id) ^ (0x5851f42d4c957f2dull * static_cast<std::uint64_t>(attempt));
            grid.resize(1);
            for (const ParameterRange& r : ranges) {
                const auto [lo, hi] = gridEnds(r);
                const auto count = static_cast<std::uint64_t>(hi - lo + 1);
                grid.push_back(lo + static_cast<long long>(nextRandom(state) % count));
            }
            if (!drawn.count(grid)) break;
        }
        drawn.insert(grid);
        nlohmann::ordered_json scene = base;
        for (std::size_t k = 0; k < ranges.size(); ++k) {
            const ParameterRange& r = ranges[k];
            const double value = std::stod(formatValue(grid[k + 1] / power10(r.decimals), r.decimals));
            student.values.emplace_back(r.name, value);
            scene["parameters"][r.name] = value;
        }
        for (auto item : scene["parameters"].items()) {  // the others as a sheet shows them: six digits
            const std::string& name = item.key();
            if (item.value().is_number_float() &&
                !std::any_of(ranges.begin(), ranges.end(), [&](const ParameterRange& r) { return r.name == name; }))
                item.value() = std::stod(shortNumber(item.value().get<double>()));
        }
        scene["name"] = base.value("name", members[m].file) + " (" + id + ")";
        // opened in the window, the tasks are asked in its exercise mode (their answers hidden)
        if (!spec.entries.empty()) scene["exercise"] = {{"entries", spec.entries}};
        student.sceneText = scene.dump(2) + "\n";
        parseScene(student.sceneText);  // throws InputError when a drawn value breaks the scene
        student.fingerprint = sceneFingerprint(student.sceneText);
        set.students.push_back(std::move(student));
    }
    return set;
}

nlohmann::ordered_json ExerciseSet::manifest() const {
    nlohmann::ordered_json m;
    m["lagrangelab_exercise"] = 1;
    m["name"] = name;
    nlohmann::ordered_json family = nlohmann::ordered_json::array();
    for (const Member& member : scenes) {
        nlohmann::ordered_json ranges = nlohmann::ordered_json::array();
        for (const ParameterRange& r : member.ranges)
            ranges.push_back({{"name", r.name}, {"low", r.low}, {"high", r.high}, {"decimals", r.decimals}});
        family.push_back({{"file", member.file}, {"ranges", ranges}});
    }
    m["scenes"] = family;
    m["seed"] = seed;
    m["mode"] = modeName(mode);  // numeric, symbolic or parameters, as derive --format json says
    m["entries"] = entries;
    m["dh_table"] = dhTable;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ExerciseStudent& s : students) {
        nlohmann::ordered_json values = nlohmann::ordered_json::object();
        for (const auto& [name, value] : s.values) values[name] = value;
        list.push_back({{"id", s.id}, {"folder", s.id}, {"scene", s.scene}, {"robot", s.fingerprint}, {"values", values}});
    }
    m["students"] = list;
    return m;
}

ExerciseSet ExerciseSet::fromManifest(const nlohmann::json& m, const std::function<std::string(const std::string&)>& sceneText) {
    auto need = [&](const nlohmann::json& object, const char* key) -> const nlohmann::json& {
        if (!object.is_object() || !object.contains(key)) throw std::invalid_argument(std::string("no \"") + key + "\"");
        return object.at(key);
    };
    try {
        if (need(m, "lagrangelab_exercise").get<int>() != 1) throw std::invalid_argument("\"lagrangelab_exercise\" is not 1");
        ExerciseSet set;
        set.name = need(m, "name").get<std::string>();
        for (const nlohmann::json& member : need(m, "scenes")) {
            set.scenes.push_back({need(member, "file").get<std::string>(), {}});
            for (const nlohmann::json& r : need(member, "ranges"))
                set.scenes.back().ranges.push_back({need(r, "name").get<std::string>(), need(r, "low").get<double>(),
                                                    need(r, "high").get<double>(), need(r, "decimals").get<int>()});
        }
        set.seed = need(m, "seed").get<std::uint64_t>();
        const std::string mode = need(m, "mode").get<std::string>();
        set.mode = mode == modeName(symbolic::ParameterMode::Numeric)    ? symbolic::ParameterMode::Numeric
                   : mode == modeName(symbolic::ParameterMode::Textbook) ? symbolic::ParameterMode::Textbook
                                                                         : symbolic::ParameterMode::Parametric;
        set.entries = need(m, "entries").get<std::vector<std::string>>();
        set.dhTable = m.value("dh_table", false);
        for (const nlohmann::json& s : need(m, "students")) {
            ExerciseStudent student;
            student.id = need(s, "id").get<std::string>();
            student.scene = need(s, "scene").get<std::string>();
            student.fingerprint = need(s, "robot").get<std::string>();
            for (const auto& [name, value] : need(s, "values").items()) student.values.emplace_back(name, value.get<double>());
            student.sceneText = sceneText(need(s, "folder").get<std::string>());
            set.students.push_back(std::move(student));
        }
        return set;
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(e.what());
    }
}

nlohmann::ordered_json answerTemplate(const ExerciseSet& set, const ExerciseStudent& student) {
    nlohmann::ordered_json t;
    t["lagrangelab_answers"] = 1;
    t["student"] = student.id;
    t["seed"] = set.seed;
    t["robot"] = student.fingerprint;
    nlohmann::ordered_json answers = nlohmann::ordered_json::object();
    for (const std::string& entry : set.entries) answers[entry] = "";
    t["answers"] = answers;
    return t;
}

}  // namespace ll
