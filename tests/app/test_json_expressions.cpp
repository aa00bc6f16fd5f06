// The `expr` fields of `derive --format json` in one grammar that GiNaC (reading back) and
// SymPy (a student's Python) parse identically (docs/user/derivation.md#expressions-in-json):
// on every example, with parameters and with numbers, every expression evaluated by GiNaC
// here and by SymPy (tests/sympy_reader.py, skipped when python3-sympy is missing) at the
// same values of its identifiers gives the same number; π is written pi.
#include "test_registry.hpp"

#include <QProcess>
#include <QTemporaryDir>

#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include <ginac/ginac.h>
#include <nlohmann/json.hpp>

#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_json_expressions {

namespace {

double valueOf(const std::string& name) {
    long sum = 0;
    for (std::size_t i = 0; i < name.size(); ++i) sum += static_cast<long>(i + 1) * static_cast<unsigned char>(name[i]);
    return 0.2 + static_cast<double>(sum % 1000) / 1000.0;
}

void strings(const nlohmann::json& value, std::vector<std::string>& out) {
    if (value.is_string()) {
        const std::string s = value.get<std::string>();
        const auto at = s.find(" = ");
        if (at == std::string::npos) {
            out.push_back(s);
        } else {
            out.push_back(s.substr(0, at));
            out.push_back(s.substr(at + 3));
        }
    } else if (value.is_array()) {
        for (const auto& v : value) strings(v, out);
    }
}

// Every expr in document order (as sympy_reader.py walks it: keys in file order).
void expressions(const nlohmann::ordered_json& node, std::vector<std::string>& out) {
    if (node.is_object()) {
        for (auto it = node.begin(); it != node.end(); ++it) {
            const std::string& key = it.key();
            if (key == "expr" || key == "B" || key == "C" || key == "g" || key == "Q" || key == "Ekin" || key == "Epot")
                strings(it.value(), out);
            else if (it.value().is_structured()) expressions(it.value(), out);
        }
    } else if (node.is_array()) {
        for (const auto& item : node) expressions(item, out);
    }
}

double ginacValue(const std::string& text) {
    static const std::set<std::string> functions{"sin", "cos", "tan", "tanh", "exp", "log", "sqrt", "pi"};
    GiNaC::symtab table;
    table["pi"] = GiNaC::Pi;
    GiNaC::lst values;
    static const std::regex identifier("[A-Za-z_][A-Za-z_0-9]*");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), identifier); it != std::sregex_iterator(); ++it) {
        const std::string name = it->str();
        if (functions.count(name) || table.count(name)) continue;
        const GiNaC::symbol s(name);
        table[name] = s;
        values.append(s == valueOf(name));
    }
    GiNaC::parser reader(table, true);  // strict: an identifier we did not list is an error
    const GiNaC::ex e = reader(text).subs(values).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(e)) throw std::runtime_error("not a number: " + text);
    return GiNaC::ex_to<GiNaC::numeric>(e).to_double();
}

}  // namespace

// One scene in one mode: its row's name and the JSON document `derive` wrote.
struct Derived {
    QString row;
    int exitCode = -1;
    QByteArray json;
    QString path;  // where it was written for SymPy
};

class TestJsonExpressions : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::vector<Derived> derived_;
    bool sympy_ = false;                         // python3-sympy importable
    std::map<QString, QList<QByteArray>> read_;  // per written file, SymPy's values in document order
    QByteArray sympyError_;

private slots:
    // Every scene derived first; then one Python process reads every document (a process
    // per document spent most of this test's time importing SymPy).
    void initTestCase() {
        QVERIFY(dir_.isValid());
        for (const char* folder : {"", "hard/"})
            for (const auto& entry : std::filesystem::directory_iterator(std::string(LL_EXAMPLES_DIR) + "/" + folder)) {
                if (entry.path().extension() != ".json") continue;
                const std::string name = entry.path().filename().string();
                if (name == "massless_joint.json") continue;  // refused: its B is singular
                for (const char* mode : {"parameters", "numeric"}) {
                    QStringList args{"derive", QString::fromStdString(entry.path().string()), "--format", "json"};
                    if (std::string(mode) == "numeric") args << "--numeric";
                    const auto run = ll::test::runProcess(LL_CLI, args);
                    Derived d{QString::fromStdString(name + " " + mode), run.exitCode, run.out,
                              dir_.filePath(QString("%1.json").arg(derived_.size()))};
                    QFile f(d.path);
                    QVERIFY(f.open(QIODevice::WriteOnly));
                    f.write(d.json);
                    derived_.push_back(std::move(d));
                }
            }
        QVERIFY(derived_.size() > 20);
        sympy_ = ll::test::runProcess("python3", {"-c", "import sympy"}).exitCode == 0;
        if (!sympy_) return;
        QStringList args{QString(LL_SOURCE_DIR) + "/tests/sympy_reader.py"};
        for (const Derived& d : derived_)
            if (d.exitCode == 0) args << d.path;
        const auto read = ll::test::runProcess("python3", args);
        if (read.exitCode != 0) sympyError_ = read.err.isEmpty() ? QByteArray("sympy_reader.py failed") : read.err;
        QList<QByteArray>* values = nullptr;
        for (const QByteArray& line : read.out.split('\n'))
            if (line.startsWith("file ")) values = &read_[QString::fromUtf8(line.mid(5))];
            else if (values && !line.isEmpty()) values->push_back(line);
    }

    void sympyAndGinacAgree_data() {
        QTest::addColumn<int>("index");
        for (std::size_t k = 0; k < derived_.size(); ++k) QTest::newRow(derived_[k].row.toUtf8().constData()) << static_cast<int>(k);
    }
    void sympyAndGinacAgree() {
        QFETCH(int, index);
        const Derived& derived = derived_[static_cast<std::size_t>(index)];
        QCOMPARE(derived.exitCode, 0);
        QVERIFY2(!derived.json.contains("Pi"), "pi is written pi");
        std::vector<std::string> texts;
        expressions(nlohmann::ordered_json::parse(derived.json.toStdString()), texts);
        QVERIFY(!texts.empty());
        std::vector<double> ginac;
        for (const std::string& t : texts) ginac.push_back(ginacValue(t));

        if (!sympy_) QSKIP("python3-sympy is not installed");
        QVERIFY2(sympyError_.isEmpty(), sympyError_.constData());
        const QList<QByteArray>& lines = read_[derived.path];
        QCOMPARE(static_cast<std::size_t>(lines.size()), ginac.size());
        for (std::size_t k = 0; k < ginac.size(); ++k) {
            const double s = lines[static_cast<qsizetype>(k)].toDouble();
            QVERIFY2(std::abs(s - ginac[k]) <= 1e-9 * std::max(1.0, std::abs(ginac[k])),
                     qPrintable(QString("%1: GiNaC %2, SymPy %3").arg(QString::fromStdString(texts[k])).arg(ginac[k]).arg(s)));
        }
    }
};

LL_TEST_GUILESS_MAIN(TestJsonExpressions)

}  // namespace test_json_expressions
#include "test_json_expressions.moc"
