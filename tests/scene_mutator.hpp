#pragma once
// A new user's mistakes in a scene file, as seeded mutations of its JSON tree: wrong
// types, NaN/inf/subnormal/huge numbers, deletions, typos of keys, broken expressions,
// duplicated entries and broken JSON text. Used by tests/test_mutation_fuzz.cpp; the
// same seed gives the same scenes, so a failure names its case and reproduces.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ll::test {

class SceneMutator {
public:
    using Json = nlohmann::ordered_json;

    explicit SceneMutator(std::uint32_t seed) : rng_(seed) {}

    std::mt19937& rng() { return rng_; }

    // `text` (a valid scene) with 1 to 3 mutations; `what` says which, for the report.
    std::string mutate(const std::string& text, std::string& what) {
        Json root = Json::parse(text);
        what.clear();
        const int count = 1 + static_cast<int>(rng_() % 3);
        for (int i = 0; i < count; ++i) what += (what.empty() ? "" : "; ") + mutateTree(root);
        std::string out = root.dump(1);
        if (rng_() % 25 == 0) {  // broken JSON text: a character dropped or inserted
            static const char kPunctuation[] = "{}[],:\"0e-";
            const std::size_t at = rng_() % out.size();
            if (rng_() % 2) out.erase(at, 1);
            else out.insert(at, 1, kPunctuation[rng_() % (sizeof kPunctuation - 1)]);
            what += "; JSON text broken at byte " + std::to_string(at);
        }
        return out;
    }

private:
    struct Slot {
        Json* parent;     // object or array holding the value
        std::string key;  // in an object
        std::size_t index = 0;
        Json& value() const { return parent->is_object() ? (*parent)[key] : (*parent)[index]; }
    };

    void collect(Json& node, std::vector<Slot>& places) {
        if (node.is_object()) {
            for (auto& [key, value] : node.items()) {
                places.push_back({&node, key, 0});
                collect(value, places);
            }
        } else if (node.is_array()) {
            for (std::size_t i = 0; i < node.size(); ++i) {
                places.push_back({&node, "", i});
                collect(node[i], places);
            }
        }
    }

    template <class T>
    const T& pick(const std::vector<T>& options) {
        return options[rng_() % options.size()];
    }

    std::string mutateTree(Json& root) {
        std::vector<Slot> places;
        collect(root, places);
        if (places.empty()) return "nothing to mutate";
        // Numbers and expressions are where most mistakes land.
        std::vector<Slot> leaves;
        for (const Slot& s : places)
            if (s.value().is_number() || s.value().is_string()) leaves.push_back(s);
        const Slot slot = !leaves.empty() && rng_() % 3 ? pick(leaves) : pick(places);
        Json& value = slot.value();
        const std::string where = slot.parent->is_object() ? slot.key : "[" + std::to_string(slot.index) + "]";
        switch (rng_() % 8) {
            case 0: {  // a wrong type
                static const std::vector<Json> kWrong = {Json("abc"),    Json(true),          Json(nullptr), Json::array(),
                                                         Json::object(), Json::array({1, 2}), Json(""),      Json(42)};
                value = pick(kWrong);
                return where + " := " + value.dump();
            }
            case 1:
            case 2: {  // a number at the ends of double precision, or NaN/inf as text
                static const std::vector<Json> kNumbers = {Json(1e-310),
                                                           Json(-4e-320),
                                                           Json(1e308),
                                                           Json(-1e308),
                                                           Json(1e300),
                                                           Json(1e150),
                                                           Json(1e-300),
                                                           Json(0),
                                                           Json(-1),
                                                           Json(-0.0),
                                                           Json(1e20),
                                                           Json(123456789),
                                                           Json(2.2250738585072014e-308),
                                                           Json("nan"),
                                                           Json("inf"),
                                                           Json("-inf"),
                                                           Json("1e400"),
                                                           Json("1e-400"),
                                                           Json("1e-310"),
                                                           Json("NaN"),
                                                           Json("1/0"),
                                                           Json("0/0"),
                                                           Json("1e308*10"),
                                                           Json("1e200*1e200"),
                                                           Json("10^400")};
                value = pick(kNumbers);
                return where + " := " + value.dump();
            }
            case 3: {  // a deletion
                if (slot.parent->is_object()) slot.parent->erase(slot.key);
                else if (slot.index < slot.parent->size()) slot.parent->erase(slot.index);
                return "deleted " + where;
            }
            case 4: {  // a typo in a key
                if (!slot.parent->is_object() || slot.key.empty()) return "no key at " + where;
                std::string key = slot.key;
                const std::size_t at = rng_() % key.size();
                switch (rng_() % 4) {
                    case 0:
                        if (at + 1 < key.size()) std::swap(key[at], key[at + 1]);
                        break;
                    case 1: key.erase(at, 1); break;
                    case 2: key.insert(at, 1, key[at]); break;
                    default: key[at] = static_cast<char>(std::toupper(static_cast<unsigned char>(key[at]))); break;
                }
                if (key == slot.key || slot.parent->contains(key)) key += "s";
                Json moved = value;
                slot.parent->erase(slot.key);
                (*slot.parent)[key] = moved;
                return "key " + slot.key + " -> " + key;
            }
            case 5: {  // a broken or extreme expression
                static const std::vector<std::string> kExpressions = {"*",         "(",          "sin(",     "a1*",     "q1",
                                                                      "t",         "x^",         "pi/",      "2 deg",   "90\xC2\xB0",
                                                                      "1e-310*1",  "m1/(a1-a1)", "sqrt(-1)", "log(0)",  "exp(1000)",
                                                                      "cosh(800)", "0.5*",       "1/(1-1)",  "((1)",    "1e308*1e308",
                                                                      "-",         "0.5*m1",     "2^0.5",    "abs(-3)", "1e-200*1e-200"};
                const std::string expression = pick(kExpressions);
                if (value.is_string() && rng_() % 2 && expression.size() <= 2) value = value.get<std::string>() + expression;
                else value = expression;
                return where + " := " + value.dump();
            }
            case 6: {  // a number scaled by a large power of ten
                if (!value.is_number()) return "no number at " + where;
                const int exponent = static_cast<int>(rng_() % 601) - 300;
                value = value.get<double>() * std::pow(10.0, exponent);
                return where + " *= 1e" + std::to_string(exponent);
            }
            default: {  // an entry of an array written twice (an extra joint, spring, ...)
                if (!slot.parent->is_array() || slot.index >= slot.parent->size()) return "no entry at " + where;
                const Json copy = value;  // value lives in the array that grows
                slot.parent->insert(slot.parent->begin() + static_cast<std::ptrdiff_t>(slot.index), copy);
                return "duplicated " + where;
            }
        }
    }

    std::mt19937 rng_;
};

}  // namespace ll::test
