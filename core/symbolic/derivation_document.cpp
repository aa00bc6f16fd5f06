#include "core/symbolic/derivation_document.hpp"

#include <algorithm>
#include <cctype>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <unordered_map>

#include "core/model/actuation.hpp"
#include "core/model/cancellation.hpp"
#include "core/model/exit_memory.hpp"
#include "core/symbolic/angle_sums.hpp"
#include "core/symbolic/display_stream.hpp"
#include "core/symbolic/expression_printer.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/json_writer.hpp"
#include "core/symbolic/latex_formula.hpp"
#include "core/symbolic/latex_text.hpp"
#include "core/symbolic/readable_numbers.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {
namespace {

// Entries with more terms than this are shown as derived (expanded, in display order),
// without the c_i² → s_i² choice, angle sums, common factors and grouping, whose cost
// grows faster than the entry and which no reader follows at that length anyway.
constexpr std::size_t maxShapedTerms = 300;

template <class T>
using ExMap = std::unordered_map<GiNaC::ex, T, std::hash<GiNaC::ex>, GiNaC::ex_is_equal>;

// The common factor of the terms of an expanded sum, velocities left inside (the
// textbook's −m2 a1 ℓc2 s2 (q̇1 + q̇2), not … q̇2 (…)): the symbols every term has, at
// their least power, with the rational content and a common sign. 1 when none.
GiNaC::ex commonFactor(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& velocities) {
    if (!GiNaC::is_a<GiNaC::add>(e)) return 1;
    std::map<GiNaC::ex, int, GiNaC::ex_is_less> common;
    bool first = true, allNegative = true, rational = true;
    GiNaC::numeric gcdNum = 0, lcmDen = 1;
    for (const GiNaC::ex& term : e) {
        std::map<GiNaC::ex, int, GiNaC::ex_is_less> here;
        GiNaC::numeric coef = 1;
        for (const GiNaC::ex& f : GiNaC::is_a<GiNaC::mul>(term) ? term : GiNaC::ex(GiNaC::lst{term})) {
            if (GiNaC::is_a<GiNaC::numeric>(f)) {
                coef = GiNaC::ex_to<GiNaC::numeric>(f);
            } else if (GiNaC::is_a<GiNaC::symbol>(f)) {
                here[f] = 1;
            } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) &&
                       f.op(1).info(GiNaC::info_flags::posint)) {
                here[f.op(0)] = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
            }
        }
        if (!coef.is_rational()) rational = false;
        if (rational) {
            gcdNum = GiNaC::gcd(gcdNum, coef.numer());
            lcmDen = GiNaC::lcm(lcmDen, coef.denom());
        }
        allNegative = allNegative && coef.is_real() && coef.is_negative();
        if (first) {
            common = here;
            first = false;
        } else {
            for (auto it = common.begin(); it != common.end();) {
                const auto h = here.find(it->first);
                if (h == here.end()) {
                    it = common.erase(it);
                } else {
                    it->second = std::min(it->second, h->second);
                    ++it;
                }
            }
        }
        if (common.empty()) return 1;
    }
    GiNaC::ex factor = 1;
    for (const auto& entry : common) {  // not a structured binding: clang 14 (fuzz build) cannot capture one
        const auto& symbol = entry.first;
        if (std::none_of(velocities.begin(), velocities.end(), [&](const GiNaC::symbol& v) { return symbol.is_equal(v); }))
            factor *= GiNaC::pow(symbol, entry.second);
    }
    if (factor.is_equal(1)) return 1;
    GiNaC::numeric content = rational ? gcdNum / lcmDen : GiNaC::numeric(1);
    if (allNegative) content = -content;
    return content * factor;
}

// How an item reads in a textbook: combined angles (c12), grouped by masses, or by
// velocities for the velocity-linear results (C, ω, v_c); each scalar presented once.
class Presenter {
public:
    Presenter(const Derivation& d, bool robot) : d_(d), robot_(robot), combiner_(d.q) {}

    GiNaC::ex present(const std::string& name, const GiNaC::ex& value) {
        if (GiNaC::is_a<GiNaC::matrix>(value)) {
            GiNaC::matrix m = GiNaC::ex_to<GiNaC::matrix>(value);
            for (unsigned r = 0; r < m.rows(); ++r)
                for (unsigned c = 0; c < m.cols(); ++c) m(r, c) = present(name, m(r, c));
            return m;
        }
        const bool byVelocity =
            name == "C" || name == "E_kin" || name.rfind("w_", 0) == 0 || name.rfind("v_c", 0) == 0;
        ExMap<GiNaC::ex>& cache = cache_[byVelocity ? 1 : 0];
        if (auto it = cache.find(value); it != cache.end()) return it->second;
        // Shaping (sines for cosines, angle sums) costs more than linear time and only
        // pays off on entries a reader can follow: larger ones stay as derived.
        GiNaC::ex e = value.expand();
        if (termCount(e) > maxShapedTerms) return cache.emplace(value, readableNumbers(e)).first->second;
        if (robot_) e = combiner_.combine(shorterInSines(e));
        // Robots group by masses (m2 (a1² + ...)); a hand-typed Lagrangian by its
        // parameters, so the notes' spring term reads K2 (θ1 − θ2).
        const GiNaC::ex common = robot_ ? commonFactor(e, d_.qd) : GiNaC::ex(1);
        if (!common.is_equal(1)) e = (e / common).expand();
        std::vector<GiNaC::symbol> groupBy = byVelocity ? d_.qd : robot_ ? massSymbols(e) : parameters();
        const GiNaC::ex shown = common * readableNumbers(collectForDisplay(e, groupBy));
        return cache.emplace(value, shown).first->second;
    }

    // Row i of B q̈ + C q̇ + g = Q in that order: b_i1 q̈1 + … + (C q̇)_i + g_i, the
    // velocity part as one sum over the velocity products with its common factor out
    // (the 2R's −m2 a1 ℓc2 s2 (2 q̇1 q̇2 + q̇2²)).
    std::vector<GiNaC::ex> equationParts(int i) {
        std::vector<GiNaC::ex> parts;
        for (size_t j = 0; j < d_.q.size(); ++j) parts.push_back(present("B", d_.B(i, j)) * d_.qdd[j]);
        GiNaC::ex velocity = 0;
        size_t terms = 0;  // counted on the entries: expanding a long row first costs more than all the rest
        for (size_t j = 0; j < d_.q.size(); ++j) {
            velocity += d_.C(i, j) * d_.qd[j];
            terms += termCount(d_.C(i, j));
        }
        if (terms <= maxShapedTerms) {
            parts.push_back(present("C", velocity));
        } else {  // too long to factor: entry by entry, each already presented for C
            for (size_t j = 0; j < d_.q.size(); ++j) parts.push_back(present("C", d_.C(i, j)) * d_.qd[j]);
        }
        parts.push_back(present("g", d_.g(i, 0)));
        return parts;
    }

private:
    static size_t termCount(const GiNaC::ex& e) { return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1; }

    // The derivation keeps powers of c_i and reduces s_i² = 1 − c_i² (a canonical form);
    // a textbook writes I1 s1², not I1 − I1 c1². For display, eliminate c_i² instead
    // wherever that gives fewer terms.
    GiNaC::ex shorterInSines(const GiNaC::ex& value) const {
        using namespace GiNaC;  // is_ex_the_function is a macro naming GiNaC's function classes
        ex e = value.expand();
        const GiNaC::lst& trig = d_.trigToFunctions;  // c_i == cos(q_i), s_i == sin(q_i), in pairs
        for (size_t k = 0; k + 1 < trig.nops(); k += 2) {
            const GiNaC::ex c = trig.op(k).lhs(), s = trig.op(k + 1).lhs();
            if (!is_ex_the_function(trig.op(k).rhs(), cos) || e.degree(c) < 2) continue;
            const GiNaC::ex alternative = reducePythagorean(e, c, s);
            if (termCount(alternative) < termCount(e)) e = alternative;
        }
        return e;
    }

    std::vector<GiNaC::symbol> parameters() const {
        std::vector<GiNaC::symbol> symbols;
        for (const GiNaC::ex& rel : d_.parameterValues)
            if (GiNaC::is_a<GiNaC::symbol>(rel.lhs())) symbols.push_back(GiNaC::ex_to<GiNaC::symbol>(rel.lhs()));
        return symbols;
    }

    const Derivation& d_;
    bool robot_;
    AngleSumCombiner combiner_;
    ExMap<GiNaC::ex> cache_[2];  // by velocity grouping
};

// B, C, g, Q, E_kin, E_pot as displayed (JSON's top level), whatever steps are shown.
struct DisplayResults {
    DisplayPtr B, C, g, Q, Ekin, Epot;
};

DisplayItem displayItem(const DerivationItem& item, Presenter& presenter, DisplayBuilder& build,
                        const DisplayOptions& options) {
    DisplayItem out{item.name, item.latexName, nullptr, nullptr, {}};
    if (item.name.rfind("equation_", 0) == 0) {
        const int row = std::stoi(item.name.substr(9)) - 1;
        std::vector<DisplayPtr> parts;
        for (const GiNaC::ex& part : presenter.equationParts(row))
            if (!part.is_zero()) parts.push_back(build(part));
        out.value = build(presenter.present("Q", item.value.rhs()));
        out.equation = displayEquation(displaySumOf(parts), out.value);
        return out;
    }
    out.value = build(presenter.present(item.name, item.value));
    out.equation = displayEquation(displayLabel(item.name, item.latexName, options), out.value);
    return out;
}

// The name of entry (r, c) of a matrix item: b11 for B, g2 for g, T_2^0[1,4] otherwise.
std::string entryName(const std::string& name, std::size_t r, std::size_t c, bool column) {
    const std::string rc = column ? std::to_string(r + 1) : std::to_string(r + 1) + std::to_string(c + 1);
    if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0])))
        return std::string(1, static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])))) + rc;
    return name + "[" + (column ? std::to_string(r + 1) : std::to_string(r + 1) + "," + std::to_string(c + 1)) + "]";
}

// Text columns of the longest line.
std::size_t widestLine(const std::string& s) {
    std::size_t widest = 0, n = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        if (b == '\n') {
            widest = std::max(widest, n);
            n = 0;
        } else if ((b & 0xC0) != 0x80 && !(b == 0xCC || (b == 0xCD && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) < 0xB0))) {
            ++n;
        }
    }
    return std::max(widest, n);
}

// The item renderings a document is made of, by format: JSON writes LaTeX, Text and
// Plain of every item, the text and LaTeX documents one each.
enum class Part { Latex, Text, Plain };

std::vector<Part> partsOf(DocumentFormat format) {
    if (format == DocumentFormat::Json) return {Part::Latex, Part::Text, Part::Plain};
    if (format == DocumentFormat::Latex) return {Part::Latex};
    return {Part::Text};
}

std::string itemLatex(const DisplayItem& item) { return renderDisplay(*item.equation, DisplayStyle::Latex); }

// Part of an item as strings: one, or for the Plain of a matrix its entries row by row
// (JSON writes it as rows of entries, a column as a list). Plain comes from the
// displayed tree, which has the same value as the derived one (grouping and angle sums
// keep it; decimals print with 17 digits), so it stays re-parsable.
std::vector<std::string> renderPart(const DisplayItem& item, Part part) {
    if (part == Part::Latex) return {itemLatex(item)};
    if (part == Part::Text) return {itemText(item)};
    if (item.name.rfind("equation_", 0) == 0) return {renderDisplay(*item.equation, DisplayStyle::Plain)};
    if (item.value->kind != DisplayKind::Matrix) return {renderDisplay(*item.value, DisplayStyle::Plain)};
    std::vector<std::string> entries;
    for (const auto& row : item.value->rows)
        for (const DisplayPtr& cell : row) entries.push_back(renderDisplay(*cell, DisplayStyle::Plain));
    return entries;
}

// Plain renderings of the nodes JSON writes twice: B, C, g, Q and the energies are
// items of their steps and the document's results too (their sums are the same nodes:
// the builder caches them; a matrix node itself is made anew). The renderings of those
// items' values and entries are kept as they are written, for the second time. (The
// results come after the steps: what is kept is chosen by the items' names.)
class PlainTexts {
public:
    static bool isResult(const std::string& itemName) {
        for (const char* name : {"B", "C", "g", "Q", "E_kin", "E_pot"})
            if (itemName == name) return true;
        return false;
    }
    // Writes `quoted`, the Plain of n as a JSON string, and keeps it when asked.
    void write(JsonWriter& json, const DisplayNode& n, std::string&& quoted, bool keep) {
        json.quotedValue(quoted);
        if (keep) kept_.emplace(&n, std::move(quoted));
    }
    // The Plain of n, kept or rendered now.
    void write(JsonWriter& json, const DisplayNode& n) {
        if (auto it = kept_.find(&n); it != kept_.end()) return json.quotedValue(it->second);
        json.value(renderDisplay(n, DisplayStyle::Plain));
    }

private:
    std::unordered_map<const DisplayNode*, std::string> kept_;
};

// A value's Plain in JSON: a matrix as rows of entries (a column as a list), from its
// entries' renderings (`entries`, row by row, quoted) or, with none given, rendered or
// kept ones.
void writePlain(JsonWriter& json, const DisplayNode& value, PlainTexts& plain, std::vector<std::string>* entries = nullptr,
                bool keep = false) {
    std::size_t next = 0;
    auto cell = [&](const DisplayNode& n) {
        if (entries) return plain.write(json, n, std::move((*entries)[next++]), keep);
        plain.write(json, n);
    };
    if (value.kind != DisplayKind::Matrix) return cell(value);
    json.beginArray();
    for (const auto& r : value.rows) {
        if (r.size() == 1) {
            cell(*r[0]);
            continue;
        }
        json.beginArray();
        for (const DisplayPtr& c : r) cell(*c);
        json.endArray();
    }
    json.endArray();
}

// The documents in parts (head, each step's start, each item, tail): an item is written
// as soon as it is shaped and rendered (derivationDocument).

void writeTextHead(const std::string& systemName, std::ostream& out) {
    out << systemName << "\n" << std::string(systemName.size(), '=') << "\n";
}

void writeTextStep(const DisplayStep& step, std::ostream& out) {
    out << "\nStep " << step.number << ". " << step.title << "\n    " << step.formulaText << "\n\n";
}

void writeTextItem(const std::string& text, std::ostream& out) { out << text << "\n\n"; }

void writeTextTail(const std::string& actuation, std::ostream& out) { out << "Actuation: " << actuation << "\n"; }

void writeLatexHead(const std::string& systemName, std::ostream& out) {
    out << "\\documentclass[a4paper,10pt]{article}\n"
           "\\usepackage[margin=1.5cm,landscape]{geometry}\n"
           "\\usepackage{amsmath,amssymb}\n"
           "\\allowdisplaybreaks\n"
           "\\setcounter{MaxMatrixCols}{20}\n"
           "\\title{Euler--Lagrange model: " << latexText(systemName) << "}\n"
           "\\author{LagrangeLab}\n\\date{}\n"
           "\\begin{document}\n\\maketitle\n"
           "Shorthand: $c_{i} = \\cos q_i$, $s_{i} = \\sin q_i$, $c_{12} = \\cos(q_1 + q_2)$, $\\dot{q}_i$ the joint velocities.\n";
}

void writeLatexStep(const DisplayStep& step, std::ostream& out) {
    out << "\\section*{Step " << step.number << ": " << latexText(step.title) << "}\n\\[ " << step.formulaLatex << " \\]\n";
}

void writeLatexItem(const std::string& latex, std::ostream& out) { out << "\\[ " << latex << " \\]\n"; }

void writeLatexTail(const std::string& actuation, std::ostream& out) {
    out << "\\paragraph{Actuation} " << latexText(actuation) << ".\n"
        << "\\end{document}\n";
}

// The text and LaTeX documents' parts, by format. An item comes as its one rendering.
struct StreamWriters {
    void (*head)(const std::string& systemName, std::ostream& out);
    void (*step)(const DisplayStep& step, std::ostream& out);  // the step's start: its items follow
    void (*item)(const std::string& rendering, std::ostream& out);
    void (*tail)(const std::string& actuation, std::ostream& out);
};

StreamWriters streamWriters(DocumentFormat format) {
    if (format == DocumentFormat::Latex) return {writeLatexHead, writeLatexStep, writeLatexItem, writeLatexTail};
    return {writeTextHead, writeTextStep, writeTextItem, writeTextTail};
}

void writeJsonHead(const Derivation& d, const std::string& mode, JsonWriter& json) {
    json.beginObject();
    json.member("system", d.systemName);
    json.member("mode", mode);
    json.member("coordinates", d.coordinateNames);
    json.key("steps");
    json.beginArray();
}

// A step's start: its number, title, formula and time; its items follow.
void writeJsonStep(const DisplayStep& step, JsonWriter& json) {
    json.beginObject();
    json.member("number", step.number);
    json.member("title", step.title);
    json.key("formula");
    json.beginObject();
    json.member("text", step.formulaText);
    json.member("latex", step.formulaLatex);
    json.endObject();
    json.member("seconds", step.seconds);
    json.key("items");
    json.beginArray();
}

void endJsonStep(JsonWriter& json) {
    json.endArray();
    json.endObject();
}

// An item from its renderings in partsOf(Json) order, quoted (moved from).
void writeJsonItem(const DisplayItem& item, std::vector<std::string>* parts[3], PlainTexts& plain, JsonWriter& json) {
    json.beginObject();
    json.member("name", item.name);
    json.key("latex");
    json.quotedValue(parts[0]->front());
    json.key("text");
    json.quotedValue(parts[1]->front());
    json.key("expr");
    if (item.name.rfind("equation_", 0) == 0)
        json.quotedValue(parts[2]->front());
    else
        writePlain(json, *item.value, plain, parts[2], PlainTexts::isResult(item.name));
    json.endObject();
}

void writeJsonTail(const Derivation& d, const DisplayResults& results, PlainTexts& plain, JsonWriter& json) {
    json.endArray();
    for (const auto& [name, value] : {std::pair{"B", &results.B}, {"C", &results.C}, {"g", &results.g}, {"Q", &results.Q},
                                      {"Ekin", &results.Ekin}, {"Epot", &results.Epot}}) {
        json.key(name);
        writePlain(json, **value, plain);
    }
    std::vector<std::string> actuated;
    for (int a : d.actuated) actuated.push_back(d.coordinateNames[a]);
    json.member("actuated", actuated);
    json.member("underactuated", d.underactuated);
    json.member("warnings", d.warnings);
    json.endObject();
}

const char* const massMatrixFormula =
    R"(,\quad B(q) = \sum_i \left(m_i\, J_{P,i}^T J_{P,i} + J_{O,i}^T R_i\, I_{li}\, R_i^T J_{O,i}\right))";

// A step as displayed, without its items yet.
DisplayStep stepHead(const Derivation& d, const DerivationStep& step) {
    DisplayStep s{step.number, step.title, step.formulaText, step.formulaLatex, {}, step.seconds, {}};
    // The notes' general formula typeset; a robot's step 7 also gives B as the notes sum it.
    const bool robot = d.trigToFunctions.nops() > 0;
    s.formula = formulaFromLatex(step.formulaLatex + (robot && step.number == 7 ? massMatrixFormula : ""), step.formulaText);
    return s;
}

// The display document, item by item; each step and item also handed to `stream` as it
// is shaped when there is one.
std::shared_ptr<const DisplayDocument> shapeDocument(const Derivation& d, Presenter& presenter, DisplayBuilder& build,
                                                     const DisplayOptions& options, const std::atomic<bool>* cancel,
                                                     DisplayStream* stream) {
    auto doc = std::make_shared<DisplayDocument>();
    doc->systemName = d.systemName;
    doc->coordinateNames = d.coordinateNames;
    doc->actuation = actuationText(d.actuated, d.coordinateNames);
    if (stream) stream->open(*doc);
    for (const DerivationStep& step : d.steps) {
        DisplayStep& shown = doc->steps.emplace_back(stepHead(d, step));
        if (stream) stream->putStep(shown);
        for (const DerivationItem& item : step.items) {
            throwIfCancelled(cancel);  // a newer edit need not wait for this document under the GiNaC lock
            const DisplayItem& made = shown.items.emplace_back(displayItem(item, presenter, build, options));
            if (stream) stream->putItem(made);
        }
    }
    if (stream) stream->close(doc->actuation);
    return doc;
}

// What derivationDocument hands from the thread that shapes (GiNaC, under its lock) to
// the one that writes (display trees only, no GiNaC), in document order: each step's
// start, then its items as they are shaped. An item is written while the next is shaped,
// on the second core. Its renderings are made by whichever thread claims them first: the
// writer going forward, and, once everything is shaped, the shaping thread going back
// from the last (the long tail of C and the equations, rendered by both threads).
class Handover {
public:
    struct Rendering {
        Part part;
        std::atomic<int> state{0};  // open, claimed, done
        std::vector<std::string> strings;
    };
    struct Entry {
        std::optional<DisplayStep> step;  // a step starts (without its items)
        std::optional<DisplayItem> item;
        std::deque<Rendering> renderings;  // one per part (atomics do not move: a deque)
    };

    Handover(DocumentFormat format, DocumentWriting* writing)
        : parts_(partsOf(format)), json_(format == DocumentFormat::Json), writing_(writing) {}

    void putStep(DisplayStep head) {
        {
            const std::lock_guard lock(mutex_);
            entries_.emplace_back().step = std::move(head);
        }
        changed_.notify_all();
    }
    void putItem(DisplayItem item) {
        {
            const std::lock_guard lock(mutex_);
            Entry& e = entries_.emplace_back();
            e.item = std::move(item);
            for (const Part part : parts_) e.renderings.emplace_back().part = part;
        }
        changed_.notify_all();
    }
    // No more entries; `results` for JSON. Not finished normally: the writer stops.
    // (Said again after a failure while helping: the results stay as they were given.)
    void finish(std::optional<DisplayResults> results, bool failed = false) {
        {
            const std::lock_guard lock(mutex_);
            if (!finished_) results_ = std::move(results);
            finished_ = true;
            failed_ = failed_ || failed;
        }
        changed_.notify_all();
    }

    // The writer's side. The next entry (kept here, in place, until the handover ends),
    // or null after the last one or once the handover failed.
    Entry* next() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return failed_ || ((taken_ < entries_.size() || finished_) && (!holdWriter() || helperStarted_)); });
        if (failed_) return nullptr;
        return taken_ < entries_.size() ? &entries_[taken_++] : nullptr;
    }
    // An item's rendering, made now or, when the shaping thread claimed it, waited for.
    // Null once the handover failed.
    std::vector<std::string>* rendered(Entry& e, std::size_t k) {
        Rendering& r = e.renderings[k];
        if (claim(r)) {
            r.strings = render(*e.item, r.part);
            ++renderedByWriter_;
            return &r.strings;
        }
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return failed_ || r.state.load() == 2; });
        return failed_ ? nullptr : &r.strings;
    }
    // The writer failed: the shaping thread stops handing over and does not help.
    void fail() {
        {
            const std::lock_guard lock(mutex_);
            failed_ = true;
        }
        changed_.notify_all();
    }
    // After next() gave null: whether the entries ended normally, and the results.
    bool failed() {
        const std::lock_guard lock(mutex_);
        return failed_;
    }
    const std::optional<DisplayResults>& results() {
        const std::lock_guard lock(mutex_);
        return results_;
    }
    void writerDone() {
        if (writing_) writing_->parts = renderedByWriter_ + renderedByShaper_.load();
    }

    // The shaping thread's side, after finish(): renders from the last item back until
    // it meets what the writer has claimed. A rendering that throws fails the handover.
    void help() {
        if (failed()) return;
        try {
            renderFromTheEnd();
            started();
        } catch (...) {
            {
                const std::lock_guard lock(mutex_);
                failed_ = true;
            }
            changed_.notify_all();
            throw;
        }
        if (writing_) writing_->renderedByShaper = renderedByShaper_.load();
    }

private:
    void renderFromTheEnd() {
        for (std::size_t i = entries_.size(); i-- > 0;) {  // no more entries come: no lock needed to walk them
            Entry& e = entries_[i];
            for (std::size_t k = e.renderings.size(); k-- > 0;) {
                Rendering& r = e.renderings[k];
                if (failed() || !claim(r)) return;
                started();
                r.strings = render(*e.item, r.part);
                ++renderedByShaper_;
                {
                    const std::lock_guard lock(mutex_);
                    r.state = 2;
                }
                changed_.notify_all();
            }
        }
    }
    // A part as the document writes it: for JSON quoted (by either thread, not the
    // writer's JsonWriter alone: tens of megabytes).
    std::vector<std::string> render(const DisplayItem& item, Part part) const {
        std::vector<std::string> strings = renderPart(item, part);
        if (json_)
            for (std::string& s : strings) {
                std::string quoted;
                quoted.reserve(s.size() + s.size() / 8 + 2);
                JsonWriter::quote(s, quoted);
                s = std::move(quoted);
            }
        return strings;
    }
    static bool claim(Rendering& r) {
        int open = 0;
        return r.state.compare_exchange_strong(open, 1);
    }
    bool holdWriter() const { return writing_ && writing_->writerWaitsForHelper; }
    // The shaping thread has claimed its first rendering, or found none to claim.
    void started() {
        if (helperStarted_) return;
        {
            const std::lock_guard lock(mutex_);
            helperStarted_ = true;
        }
        changed_.notify_all();
    }

    const std::vector<Part> parts_;
    const bool json_;
    DocumentWriting* writing_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Entry> entries_;  // a deque: emplace_back leaves the given entries in place
    std::size_t taken_ = 0;
    bool finished_ = false, failed_ = false, helperStarted_ = false;
    std::optional<DisplayResults> results_;
    std::size_t renderedByWriter_ = 0;
    std::atomic<std::size_t> renderedByShaper_{0};
};

// The writer's side: the document in `format` from the handed-over entries. A rendering
// is freed once written.
void writeHandedOver(const Derivation& d, DocumentFormat format, const std::string& modeName, Handover& handover,
                     std::string& out) {
    if (format == DocumentFormat::Json) {
        PlainTexts plain;
        JsonWriter json(out);
        writeJsonHead(d, modeName, json);
        bool inStep = false;
        while (Handover::Entry* e = handover.next()) {
            if (e->step) {
                if (inStep) endJsonStep(json);
                writeJsonStep(*e->step, json);
                inStep = true;
                continue;
            }
            std::vector<std::string>* parts[3];
            for (std::size_t k = 0; k < 3; ++k)
                if (!(parts[k] = handover.rendered(*e, k))) return;
            writeJsonItem(*e->item, parts, plain, json);
            for (std::vector<std::string>* p : parts) std::vector<std::string>().swap(*p);
        }
        if (handover.failed()) return;
        if (inStep) endJsonStep(json);
        writeJsonTail(d, *handover.results(), plain, json);
        handover.writerDone();
        out += '\n';
        return;
    }
    std::ostringstream text;
    const StreamWriters write = streamWriters(format);
    write.head(d.systemName, text);
    while (Handover::Entry* e = handover.next()) {
        if (e->step) {
            write.step(*e->step, text);
            continue;
        }
        std::vector<std::string>* rendering = handover.rendered(*e, 0);
        if (!rendering) return;
        write.item(rendering->front(), text);
        std::vector<std::string>().swap(*rendering);
    }
    if (handover.failed()) return;
    write.tail(actuationText(d.actuated, d.coordinateNames), text);
    handover.writerDone();
    out = std::move(text).str();
}
}  // namespace

namespace {

// A lower bound of the columns a node takes in Text, counted no further than `limit`:
// every symbol or number at least one column, " + " between terms, a space between
// factors, parentheses around a fence.
std::size_t textColumnsAtLeast(const DisplayNode& n, std::size_t limit) {
    std::size_t count = 0;
    auto add = [&](std::size_t k) { count = std::min(limit, count + k); };
    switch (n.kind) {
    case DisplayKind::Sum:
    case DisplayKind::Product:
        for (std::size_t i = 0; i < n.children.size() && count < limit; ++i)
            add(textColumnsAtLeast(*n.children[i], limit - count) + (i ? (n.kind == DisplayKind::Sum ? 3 : 1) : 0));
        return count;
    case DisplayKind::Fence: return std::min(limit, textColumnsAtLeast(*n.children[0], limit) + 2);
    default: return 1;
    }
}

}  // namespace

std::string itemText(const DisplayItem& item) {
    // A block whose entry alone is wider than a row may be is listed entry by entry
    // without being written as a block first (the expanded Panda's C: megabytes).
    bool tooWide = false;
    if (item.value->kind == DisplayKind::Matrix)
        for (const auto& row : item.value->rows)
            for (const DisplayPtr& cell : row)
                tooWide = tooWide || textColumnsAtLeast(*cell, maxTextMatrixRow + 1) > maxTextMatrixRow;
    if (!tooWide) {
        std::string whole = renderDisplay(*item.equation, DisplayStyle::Text);
        if (item.value->kind != DisplayKind::Matrix || widestLine(whole) <= maxTextMatrixRow) return whole;
    }
    // Too wide to read as a block: the entries one by one, under the matrix's name.
    const auto& rows = item.value->rows;
    const bool column = !rows.empty() && rows[0].size() == 1;
    const bool zeros = hasZeroEntry(*item.value);  // left out, and said so
    std::string out = item.name + " (" + std::to_string(rows.size()) + "×" +
                      std::to_string(rows.empty() ? 0 : rows[0].size()) + "), entry by entry" + (zeros ? ", the zeros left out:" : ":");
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            if (!isZeroNumber(*rows[r][c]))
                out += "\n  " + entryName(item.name, r, c, column) + " = " + renderDisplay(*rows[r][c], DisplayStyle::Text);
    return out;
}

std::shared_ptr<const DisplayDocument> displayDocument(const Derivation& d, const std::atomic<bool>* cancel, DisplayStream* stream,
                                                       bool forPages) {
    const auto lock = lockGinac();
    DisplayOptions options = displayOptions(printOptionsFor(d, Style::Text));
    options.cutLongSums = forPages;
    // Their caches: freed at the end, or left to a command's exit.
    const Disposing<DisplayBuilder> build(options);
    const Disposing<Presenter> presenter(d, d.trigToFunctions.nops() > 0);
    return shapeDocument(d, *presenter, *build, options, cancel, stream);
}

std::string renderDocument(const DisplayDocument& document, DocumentFormat format) {
    if (format != DocumentFormat::Text && format != DocumentFormat::Latex) return {};
    std::ostringstream out;
    const StreamWriters write = streamWriters(format);
    write.head(document.systemName, out);
    const Part part = partsOf(format).front();
    for (const DisplayStep& step : document.steps) {
        write.step(step, out);
        for (const DisplayItem& item : step.items) write.item(renderPart(item, part).front(), out);
    }
    write.tail(document.actuation, out);
    return out.str();
}

std::string derivationDocument(const Derivation& d, DocumentFormat format, const std::string& modeName,
                               DocumentWriting* writing) {
    if (format == DocumentFormat::Display) return {};
    const auto lock = lockGinac();
    const DisplayOptions options = displayOptions(printOptionsFor(d, Style::Text));
    Disposing<DisplayBuilder> build(options);
    Disposing<Presenter> presenter(d, d.trigToFunctions.nops() > 0);
    const Disposing<Handover> handoverOwner(format, writing);  // the trees it holds: freed at the end, or left to a command's exit
    Handover& handover = *handoverOwner;
    std::string out;
    std::exception_ptr writeFailed;
    std::thread writer([&] {
        try {
            writeHandedOver(d, format, modeName, handover, out);
        } catch (...) {
            writeFailed = std::current_exception();
            handover.fail();  // shaping and helping stop: nothing more will be written
        }
    });
    try {
        for (const DerivationStep& step : d.steps) {
            if (handover.failed()) break;
            handover.putStep(stepHead(d, step));
            for (const DerivationItem& item : step.items) handover.putItem(displayItem(item, *presenter, *build, options));
        }
        std::optional<DisplayResults> results;
        if (format == DocumentFormat::Json) {
            auto shown = [&](const char* name, const GiNaC::ex& value) { return (*build)(presenter->present(name, value)); };
            results = DisplayResults{shown("B", d.B), shown("C", d.C), shown("g", d.g),
                                     shown("Q", d.Q), shown("E_kin", d.Ekin), shown("E_pot", d.Epot)};
        }
        handover.finish(std::move(results));
        // Their caches are freed while the writer goes on (the trees it reads are the
        // items'), or left to a command's exit; then this thread renders the last items'
        // parts beside it.
        presenter.disposeNow();
        build.disposeNow();
        handover.help();
    } catch (...) {
        handover.finish(std::nullopt, true);
        writer.join();
        // The writer's error first: it met its string earlier in the document.
        if (writeFailed) std::rethrow_exception(writeFailed);
        throw;
    }
    writer.join();
    if (writeFailed) std::rethrow_exception(writeFailed);
    return out;
}

}  // namespace ll::symbolic
