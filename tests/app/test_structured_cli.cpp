// The structured form on the command line: `derive --form`, `--entry`, `--verify`,
// `codegen --lang c|python` (the generated C compiled with cc, the Python run with
// python3, both compared with `eval`), and one-line refusals with exit code 2.
#include "test_registry.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <random>

#include <ginac/ginac.h>

#include "core/io/scene_file.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_structured_cli {

namespace {

struct Run {
    int exitCode;
    QByteArray out, err;
};

Run run(const QString& program, const QStringList& args, const QString& dir = {}) {
    QProcess p;
    if (!dir.isEmpty()) p.setWorkingDirectory(dir);
    p.start(program, args);
    p.waitForFinished(300000);
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

Run cli(const QStringList& args) { return run(LL_CLI, args); }

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

double relative(const QJsonArray& a, const QJsonArray& b) {
    double diff = 0, scale = 1;
    for (int i = 0; i < a.size(); ++i) {
        if (a[i].isArray()) {
            diff = std::max(diff, relative(a[i].toArray(), b[i].toArray()));
            continue;
        }
        diff = std::max(diff, std::abs(a[i].toDouble() - b[i].toDouble()));
        scale = std::max(scale, std::abs(b[i].toDouble()));
    }
    return diff / scale;
}

// A random state (q, q̇ in ±2) for GiNaC's parser: q1…, qd1… and pi in its table, their
// values to substitute, and the same numbers as --q and --qd for eval.
struct ParsedState {
    GiNaC::symtab table;
    GiNaC::lst values;
    QStringList q, qd;
    void bind(const std::string& name, const GiNaC::ex& value) {
        const GiNaC::symbol sym(name);
        table[name] = sym;
        values.append(sym == value);
    }
    double value(const QString& expression) {
        GiNaC::parser reader(table);
        const GiNaC::ex v = reader(expression.toStdString()).subs(values).evalf();
        return GiNaC::is_a<GiNaC::numeric>(v) ? GiNaC::ex_to<GiNaC::numeric>(v).to_double() : std::nan("");
    }
};

ParsedState randomState(std::mt19937& rng, int n) {
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    ParsedState s;
    s.table["pi"] = GiNaC::Pi;
    for (int i = 0; i < n; ++i) {
        s.q << QString::number(u(rng), 'g', 17);
        s.qd << QString::number(u(rng), 'g', 17);
        s.bind("q" + std::to_string(i + 1), GiNaC::numeric(s.q.back().toUtf8().constData()));
        s.bind("qd" + std::to_string(i + 1), GiNaC::numeric(s.qd.back().toUtf8().constData()));
    }
    return s;
}

const char* kQ = "0.3,-0.7,1.1,0.4,-0.2,0.9";
const char* kQd = "0.5,0.2,-0.4,1.0,-0.3,0.6";

}  // namespace

class TestStructuredCli : public QObject {
    Q_OBJECT
private slots:
    // The generated C and Python give eval's B, C, g and, with eval's Q as τ, its q̈.
    void generatedCodeEqualsEval_data() {
        QTest::addColumn<QString>("lang");
        QTest::addColumn<QString>("scene");
        for (const char* lang : {"c", "python"}) {
            QTest::newRow((std::string(lang) + " puma560").c_str()) << lang << "puma560.json";
            QTest::newRow((std::string(lang) + " stanford").c_str()) << lang << "stanford_arm.json";
        }
    }
    void generatedCodeEqualsEval() {
        QFETCH(QString, lang);
        QFETCH(QString, scene);
        const Run e = cli({"eval", example(scene.toUtf8().constData()), "--q", kQ, "--qd", kQd});
        QCOMPARE(e.exitCode, 0);
        const QJsonObject expected = QJsonDocument::fromJson(e.out).object();
        QStringList tau;
        for (const QJsonValue v : expected["Q"].toArray()) tau << QString::number(v.toDouble(), 'g', 17);

        QTemporaryDir dir;
        const QString file = dir.filePath(lang == "c" ? "model.c" : "model.py");
        const Run gen = cli({"codegen", example(scene.toUtf8().constData()), "--lang", lang, "--out", file});
        QVERIFY2(gen.exitCode == 0, gen.err.constData());
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray code = f.readAll();
        QVERIFY(code.contains("DH table"));  // header comment
        QJsonObject got;
        if (lang == "c") {
            QVERIFY(!code.contains("#include <stdio.h>") && code.contains("#include <math.h>"));
            const QString main = dir.filePath("main.c");
            QFile m(main);
            QVERIFY(m.open(QIODevice::WriteOnly));
            m.write(
                QString(
                    "#include <stdio.h>\n"
                    "void ll_mass_matrix(const double*, double*);\n"
                    "void ll_coriolis_matrix(const double*, const double*, double*);\n"
                    "void ll_gravity(const double*, double*);\n"
                    "int ll_forward_dynamics(const double*, const double*, const double*, double*);\n"
                    "int main(void) {\n"
                    "    const double q[6] = {%1}, qd[6] = {%2}, tau[6] = {%3};\n"
                    "    double B[36], C[36], g[6], qdd[6];\n"
                    "    int i, j;\n"
                    "    ll_mass_matrix(q, B); ll_coriolis_matrix(q, qd, C); ll_gravity(q, g);\n"
                    "    if (ll_forward_dynamics(q, qd, tau, qdd) != 0) return 1;\n"
                    "    printf(\"{\\\"B\\\": [\");\n"
                    "    for (i = 0; i < 6; ++i) { printf(\"%s[\", i ? \",\" : \"\"); for (j = 0; j < 6; ++j) printf(\"%s%.17g\", j ? \",\" : \"\", B[i * 6 + j]); printf(\"]\"); }\n"
                    "    printf(\"], \\\"C\\\": [\");\n"
                    "    for (i = 0; i < 6; ++i) { printf(\"%s[\", i ? \",\" : \"\"); for (j = 0; j < 6; ++j) printf(\"%s%.17g\", j ? \",\" : \"\", C[i * 6 + j]); printf(\"]\"); }\n"
                    "    printf(\"], \\\"g\\\": [\");\n"
                    "    for (i = 0; i < 6; ++i) printf(\"%s%.17g\", i ? \",\" : \"\", g[i]);\n"
                    "    printf(\"], \\\"qdd\\\": [\");\n"
                    "    for (i = 0; i < 6; ++i) printf(\"%s%.17g\", i ? \",\" : \"\", qdd[i]);\n"
                    "    printf(\"]}\\n\");\n"
                    "    return 0;\n"
                    "}\n")
                    .arg(kQ, kQd, tau.join(","))
                    .toUtf8());
            m.close();
            const Run cc = run("cc", {"-std=c99", "-pedantic", "-Wall", "-O1", "-o", dir.filePath("model"), file, main, "-lm"});
            QVERIFY2(cc.exitCode == 0, cc.err.constData());
            const Run r = run(dir.filePath("model"), {});
            QCOMPARE(r.exitCode, 0);
            got = QJsonDocument::fromJson(r.out).object();
        } else {
            const Run r = run("python3", {file, "--q", kQ, "--qd", kQd, "--tau", tau.join(",")});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            got = QJsonDocument::fromJson(r.out).object();
        }
        for (const char* key : {"B", "C", "g", "qdd"}) {
            const double err = relative(got[key].toArray(), expected[key].toArray());
            QVERIFY2(err < 1e-10, qPrintable(QString("%1: relative difference %2").arg(key).arg(err)));
        }
    }

    // auto: small robots expanded, a 7-joint arm structured, and the output says why;
    // the structured JSON's definitions re-parse, and B evaluates to eval's B.
    void formAutoAndStructuredJson() {
        const Run small = cli({"derive", example("planar_2r.json"), "--format", "json"});
        QCOMPARE(small.exitCode, 0);
        const QJsonObject s = QJsonDocument::fromJson(small.out).object();
        QCOMPARE(s["form"].toString(), QString("expanded"));
        QVERIFY(!s["form_reason"].toString().isEmpty());

        const Run panda = cli({"derive", example("panda.json"), "--format", "json"});
        QCOMPARE(panda.exitCode, 0);
        const QJsonObject p = QJsonDocument::fromJson(panda.out).object();
        QCOMPARE(p["form"].toString(), QString("structured"));
        QVERIFY(p["form_reason"].toString().contains("7 joints"));
        const QJsonArray defs = p["definitions"].toArray();
        QVERIFY(defs.size() > 50);

        // Evaluate the names in order with GiNaC's parser, then B, and compare with eval.
        const char* q = "0.3,-0.7,1.1,0.4,-0.2,0.9,0.5";
        const Run e = cli({"eval", example("panda.json"), "--q", q, "--qd", "0,0,0,0,0,0,0"});
        QCOMPARE(e.exitCode, 0);
        const QJsonArray Bexpected = QJsonDocument::fromJson(e.out).object()["B"].toArray();
        GiNaC::symtab table;
        GiNaC::lst values;
        const QStringList qs = QString(q).split(',');
        for (int i = 0; i < 7; ++i) {
            const GiNaC::symbol qi("q" + std::to_string(i + 1));
            table["q" + std::to_string(i + 1)] = qi;
            values.append(qi == GiNaC::numeric(qs[i].toUtf8().constData()));
        }
        for (const QJsonValue v : p["parameters"].toArray()) Q_UNUSED(v);
        // parameters of the scene (kept as symbols by default) come from its file
        QFile f(example("panda.json"));
        f.open(QIODevice::ReadOnly);
        const QJsonObject params = QJsonDocument::fromJson(f.readAll()).object()["parameters"].toObject();
        for (auto it = params.begin(); it != params.end(); ++it) {
            const GiNaC::symbol sym(it.key().toStdString());
            table[it.key().toStdString()] = sym;
            values.append(sym == GiNaC::numeric(QString::number(it.value().toDouble(), 'g', 17).toUtf8().constData()));
        }
        for (const QJsonValue d : defs) {
            const QJsonObject def = d.toObject();
            QVERIFY(def.contains("latex") && def.contains("meaning") && def.contains("step"));
            GiNaC::parser reader(table);
            const GiNaC::ex value = reader(def["expr"].toString().toStdString()).subs(values).evalf();
            const GiNaC::symbol name(def["name"].toString().toStdString());
            table[def["name"].toString().toStdString()] = name;
            values.append(name == value);
        }
        const QJsonArray B = p["B"].toArray();
        double err = 0;
        for (int i = 0; i < 7; ++i)
            for (int j = 0; j < 7; ++j) {
                GiNaC::parser reader(table);
                const GiNaC::ex v = reader(B[i].toArray()[j].toString().toStdString()).subs(values).evalf();
                err = std::max(err, std::abs(GiNaC::ex_to<GiNaC::numeric>(v).to_double() - Bexpected[i].toArray()[j].toDouble()));
            }
        QVERIFY2(err < 1e-10, qPrintable(QString::number(err)));
    }

    // The structured JSON's Ekin and Epot, read with GiNaC's parser over its definitions,
    // equal eval's at random states: the Panda (a base frame at the origin, parameters by
    // name) and a seeded 10-joint chain (a rotated, offset base, prismatic joints, two
    // springs, gravity off the vertical).
    void structuredJsonEnergiesEqualEval_data() {
        QTest::addColumn<QString>("scene");
        QTest::newRow("panda") << "panda.json";
        QTest::newRow("10-joint chain") << "";
    }
    void structuredJsonEnergiesEqualEval() {
        QFETCH(QString, scene);
        QTemporaryDir dir;
        QString file = scene.isEmpty() ? dir.filePath("chain10.json") : example(scene.toUtf8().constData());
        if (scene.isEmpty()) {
            std::mt19937 rng(1010);
            ll::Scene chain;
            chain.name = "chain 10";
            chain.robot = ll::test::randomRobot(rng, 10, ll::DhConvention::Standard, true);
            chain.effects.gravity = Eigen::Vector3d(0.3, -0.2, -9.81);
            chain.effects.springs = {{1, 12.0, 0.4}, {5, 30.0, -0.2}};
            ll::saveScene(chain, file.toStdString());
        }
        const Run derived = cli({"derive", file, "--form", "structured", "--format", "json"});
        QVERIFY2(derived.exitCode == 0, derived.err.constData());
        const QJsonObject doc = QJsonDocument::fromJson(derived.out).object();
        QVERIFY2(doc.contains("Ekin") && doc.contains("Epot"), "the structured JSON has the energies");
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject params = QJsonDocument::fromJson(f.readAll()).object()["parameters"].toObject();
        const int n = doc["coordinates"].toArray().size();
        std::mt19937 rng(99);
        for (int state = 0; state < 3; ++state) {
            ParsedState x = randomState(rng, n);
            for (auto it = params.begin(); it != params.end(); ++it)
                x.bind(it.key().toStdString(), GiNaC::numeric(QString::number(it.value().toDouble(), 'g', 17).toUtf8().constData()));
            for (const QJsonValue d : doc["definitions"].toArray()) {
                GiNaC::parser reader(x.table);
                const GiNaC::ex value = reader(d.toObject()["expr"].toString().toStdString()).subs(x.values).evalf();
                x.bind(d.toObject()["name"].toString().toStdString(), value);
            }
            const Run e = cli({"eval", file, "--q", x.q.join(','), "--qd", x.qd.join(',')});
            QVERIFY2(e.exitCode == 0, e.err.constData());
            const QJsonObject expected = QJsonDocument::fromJson(e.out).object();
            for (const char* energy : {"Ekin", "Epot"}) {
                const double got = x.value(doc[energy].toString()), want = expected[energy].toDouble();
                QVERIFY2(std::abs(got - want) <= 1e-9 * std::max(1.0, std::abs(want)),
                         qPrintable(QString("%1: %2, eval %3").arg(energy).arg(got, 0, 'g', 17).arg(want, 0, 'g', 17)));
            }
        }
    }

    // An entry expanded on demand of a chain with constant angles that are not special
    // (docs/bench/chain8_general.json: twists 0.3 rad, a prismatic joint at θ = 0.624 rad),
    // their sines and cosines folded to numbers, equals eval's at random states.
    void expandedEntryWithGeneralAnglesEqualsEval() {
        const QString file = QString(LL_SOURCE_DIR) + "/docs/bench/chain8_general.json";
        const Run r = cli({"derive", file, "--form", "expanded", "--entry", "B11,B24,C11,C23,g4", "--format", "json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject entries = QJsonDocument::fromJson(r.out).object()["entries"].toObject();
        QCOMPARE(entries.size(), 5);
        std::mt19937 rng(8);
        for (int state = 0; state < 2; ++state) {
            ParsedState x = randomState(rng, 8);
            const Run e = cli({"eval", file, "--q", x.q.join(','), "--qd", x.qd.join(',')});
            QVERIFY2(e.exitCode == 0, e.err.constData());
            const QJsonObject expected = QJsonDocument::fromJson(e.out).object();
            for (const QString& key : entries.keys()) {
                const int row = key.mid(1, 1).toInt() - 1, col = key.size() > 2 ? key.mid(2, 1).toInt() - 1 : -1;
                const QJsonValue m = expected[key.left(1)];
                const double want = col < 0 ? m.toArray()[row].toDouble() : m.toArray()[row].toArray()[col].toDouble();
                const double got = x.value(entries[key].toObject()["expr"].toString());
                QVERIFY2(std::abs(got - want) <= 1e-9 * std::max(1.0, std::abs(want)),
                         qPrintable(QString("%1: %2, eval %3").arg(key).arg(got, 0, 'g', 17).arg(want, 0, 'g', 17)));
            }
        }
    }

    // --entry with the expanded form expands only those entries, with term counts;
    // C from the expanded rows of B equals the structured C at a state (--verify
    // prints its own comparison).
    void entriesExpandedOnDemand() {
        const Run r = cli({"derive", example("panda.json"), "--form", "expanded", "--entry", "B11,C23,g4", "--format", "json", "--verify"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(o["form"].toString(), QString("expanded"));  // what was asked for, not "structured"
        const QJsonObject entries = o["entries"].toObject();
        QCOMPARE(entries.keys(), (QStringList{"B11", "C23", "g4"}));
        for (const QString& k : entries.keys()) {
            QVERIFY(entries[k].toObject()["terms"].toInt() > 0);
            QVERIFY(!entries[k].toObject()["expr"].toString().isEmpty());
        }
        QVERIFY2(r.err.contains("structured vs numeric core"), r.err.constData());
        // the largest difference it reports is small
        const QString err = QString::fromUtf8(r.err);
        const int at = err.indexOf("difference ") + 11;
        QVERIFY2(err.mid(at, err.indexOf(' ', at) - at).toDouble() < 1e-10, r.err.constData());
    }

    // The form each document says it is, in text too, and --steps honoured by the
    // structured form (text and JSON).
    void formLabelAndSteps() {
        const Run text = cli({"derive", example("panda.json"), "--form", "expanded", "--entry", "B77"});
        QVERIFY2(text.exitCode == 0, text.err.constData());
        QVERIFY2(text.out.contains("Form: expanded (asked for with --form"), text.out.left(400).constData());
        const Run structured = cli({"derive", example("panda.json"), "--form", "structured", "--steps", "6-6"});
        QVERIFY2(structured.exitCode == 0, structured.err.constData());
        QVERIFY(structured.out.contains("Form: structured"));
        QVERIFY(structured.out.contains("Step 6.") && structured.out.contains("gamma1_3 ="));
        QVERIFY(!structured.out.contains("Step 1.") && !structured.out.contains("Step 7.") && !structured.out.contains("beta"));
        const Run json = cli({"derive", example("panda.json"), "--form", "structured", "--steps", "7-8", "--format", "json"});
        QVERIFY2(json.exitCode == 0, json.err.constData());
        const QJsonObject o = QJsonDocument::fromJson(json.out).object();
        for (const QJsonValue d : o["definitions"].toArray()) QVERIFY(d.toObject()["step"].toInt() >= 7);
        QVERIFY(o.contains("B") && o.contains("C") && o.contains("g"));
    }

    // A parameter named like a generated name (here the first name the 2R's structured
    // form makes) is refused: one line naming it, exit 2, for derive and codegen.
    void generatedNameClashIsOneLine() {
        const Run names = cli({"derive", example("planar_2r.json"), "--form", "structured", "--format", "json"});
        QCOMPARE(names.exitCode, 0);
        const QString generated = QJsonDocument::fromJson(names.out).object()["definitions"].toArray()[0].toObject()["name"].toString();
        QVERIFY(!generated.isEmpty());
        QFile f(example("planar_2r.json"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonObject scene = QJsonDocument::fromJson(f.readAll()).object();
        QJsonObject parameters = scene["parameters"].toObject();
        parameters[generated] = 0.25;
        scene["parameters"] = parameters;
        QTemporaryDir dir;
        const QString path = dir.filePath("clash.json");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(scene).toJson());
        out.close();
        for (const QStringList& args : {QStringList{"derive", path, "--form", "structured"}, QStringList{"codegen", path, "--lang", "c"}}) {
            const Run r = cli(args);
            QCOMPARE(r.exitCode, 2);
            QCOMPARE(r.err.count('\n'), 1);
            QVERIFY2(r.err.contains(("parameters." + generated).toUtf8()) && r.err.startsWith("error: "), r.err.constData());
        }
    }

    void badFormAndEntryAreOneLine_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("names");
        QTest::newRow("form") << QStringList{"--form", "short"} << "--form";
        QTest::newRow("entry letter") << QStringList{"--entry", "X11"} << "--entry";
        QTest::newRow("entry range") << QStringList{"--entry", "B13"} << "--entry";
        QTest::newRow("entry g") << QStringList{"--entry", "g0"} << "--entry";
        QTest::newRow("entry empty") << QStringList{"--entry", ""} << "--entry";
    }
    void badFormAndEntryAreOneLine() {
        QFETCH(QStringList, args);
        QFETCH(QString, names);
        const Run r = cli(QStringList{"derive", example("planar_2r.json")} + args);
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY2(r.err.contains(names.toUtf8()) && r.err.startsWith("error: "), r.err.constData());
        const Run c = cli({"codegen", example("planar_2r.json"), "--lang", "fortran"});
        QCOMPARE(c.exitCode, 2);
        QVERIFY2(c.err.contains("--lang") && c.err.count('\n') == 1, c.err.constData());
    }
};

LL_TEST_GUILESS_MAIN(TestStructuredCli)

}  // namespace test_structured_cli
#include "test_structured_cli.moc"
