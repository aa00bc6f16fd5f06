// The command line, run as a user runs it: JSON from eval with the textbook values,
// trajectories from simulate, one-line errors with exit code 2 for bad input.
#include "test_registry.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <ginac/ginac.h>

#include "core/model/utf8_text.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_cli {

class TestCli : public QObject {
    Q_OBJECT

    struct Run {
        int exitCode;
        QProcess::ExitStatus status;
        QByteArray out, err;
    };
    // Every refusal (exit code 2) is checked for valid UTF-8 on stderr.
    // `display` false: with DISPLAY and WAYLAND_DISPLAY unset (a bare `lagrangelab` then
    // cannot open its window and prints the usage instead).
    static Run run(const QStringList& args, bool display = true) {
        QProcess p;
        if (!display) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove("DISPLAY");
            env.remove("WAYLAND_DISPLAY");
            p.setProcessEnvironment(env);
        }
        p.start(LL_CLI, args);
        p.waitForFinished(120000);
        const Run r{p.exitCode(), p.exitStatus(), p.readAllStandardOutput(), p.readAllStandardError()};
        if (r.exitCode == 2)
            QTest::qVerify(ll::isValidUtf8(r.err.toStdString()), "stderr is UTF-8", r.err.toHex(' ').constData(), __FILE__, __LINE__);
        return r;
    }
    // `bytes` as dir/bad.json.
    static QString writeScene(const QTemporaryDir& dir, const QByteArray& bytes) {
        const QString path = dir.filePath("bad.json");
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size()) qFatal("cannot write %s", qPrintable(path));
        return path;
    }
    // A copy of an example with its JSON edited, in `dir`.
    template <class Edit>
    static QString editedExample(const QTemporaryDir& dir, const char* name, Edit edit) {
        QFile in(example(name));
        in.open(QIODevice::ReadOnly);
        QJsonObject root = QJsonDocument::fromJson(in.readAll()).object();
        edit(root);
        const QString path = dir.filePath(name);
        QFile out(path);
        out.open(QIODevice::WriteOnly);
        out.write(QJsonDocument(root).toJson());
        return path;
    }
    static QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }
    // A parameter's value as the scene file gives it (numbers only in these examples).
    static double parameterValue(const QString& scene, const std::string& name) {
        QFile f(example(scene.toUtf8().constData()));
        f.open(QIODevice::ReadOnly);
        const QJsonValue v = QJsonDocument::fromJson(f.readAll()).object()["parameters"].toObject()[QString::fromStdString(name)];
        if (!v.isDouble()) qFatal("parameter %s is not a number in %s", name.c_str(), qPrintable(scene));
        return v.toDouble();
    }

private slots:
    // Field paths count as JSON does (the first joint is robot.joints[0]) with the joint in
    // words as the table names it, and every magnitude outside any physical range is named
    // as such, on its own first line, before B could be blamed: exit 2.
    void fieldPathsAndAbsurdMagnitudes_data() {
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("negative mass of the first joint") << "mass"
                                                          << "-2"
                                                          << "robot.joints[0].mass (joint 1): mass is negative";
        QTest::newRow("a 1e300 length") << "d"
                                        << "1e300"
                                        << "robot.joints[0].d (joint 1): absurdly large length 1e+300 m";
        QTest::newRow("a 1e5 m length") << "a"
                                        << "1e5"
                                        << "robot.joints[0].a (joint 1): absurdly large length 100000 m";
        QTest::newRow("a 1e-12 m length") << "a"
                                          << "1e-12"
                                          << "robot.joints[0].a (joint 1): absurdly small length 1e-12 m";
        QTest::newRow("a 1e10 kg mass") << "mass"
                                        << "1e10"
                                        << "robot.joints[0].mass (joint 1): absurdly large mass 1e+10 kg";
        QTest::newRow("a 1e-12 kg mass") << "mass"
                                         << "1e-12"
                                         << "robot.joints[0].mass (joint 1): absurdly small mass 1e-12 kg";
        QTest::newRow("a 1e10 inertia") << "inertia.zz"
                                        << "1e10"
                                        << "robot.joints[0].inertia.zz (joint 1): absurdly large inertia 1e+10 kg m²";
        QTest::newRow("a 1e-20 inertia") << "inertia.zz"
                                         << "1e-20"
                                         << "robot.joints[0].inertia.zz (joint 1): absurdly small inertia 1e-20 kg m²";
        QTest::newRow("a 1e4 m/s² gravity") << "gravity"
                                            << "-1e4"
                                            << "effects.gravity: absurdly large gravity 10000 m/s²";
        QTest::newRow("a 1e-9 m/s² gravity") << "gravity"
                                             << "-1e-9"
                                             << "effects.gravity: absurdly small gravity 1e-09 m/s²";
    }
    void fieldPathsAndAbsurdMagnitudes() {
        QFETCH(QString, field);
        QFETCH(QString, value);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = editedExample(dir, "planar_2r.json", [&](QJsonObject& root) {
            const double v = value.toDouble();
            if (field == "gravity") {
                QJsonObject effects = root["effects"].toObject();
                effects["gravity"] = QJsonArray{0, v, 0};
                root["effects"] = effects;
                return;
            }
            QJsonObject robot = root["robot"].toObject();
            QJsonArray joints = robot["joints"].toArray();
            QJsonObject joint = joints[0].toObject();
            if (field.startsWith("inertia.")) {
                QJsonObject inertia = joint["inertia"].toObject();
                inertia[field.mid(8)] = v;
                joint["inertia"] = inertia;
            } else {
                joint[field] = v;
            }
            joints[0] = joint;
            robot["joints"] = joints;
            root["robot"] = robot;
        });
        const Run r = run({"eval", path, "--q", "0,0", "--qd", "0,0"});
        QCOMPARE(r.exitCode, 2);
        const QStringList errors = QString::fromUtf8(r.err).split('\n').filter(QRegularExpression("^error: "));
        QVERIFY2(!errors.isEmpty() && errors[0].contains(expected), r.err.constData());
        QVERIFY2(!r.err.contains("B(q)"), r.err.constData());  // never blamed on the mass matrix
        for (const QString& line : errors) QVERIFY2(line.toUtf8().size() - path.toUtf8().size() <= 200, qPrintable(line));
    }

    // Reference (platform notes, Corke's parameters): g(0) = [0, 37.4837, 0.2489, 0, 0, 0];
    // the rigid-body B with the motors switched off.
    void evalPuma560AtZero() {
        QTemporaryDir dir;
        const QString rigid = editedExample(dir, "puma560.json", [](QJsonObject& root) {
            QJsonObject robot = root["robot"].toObject();
            QJsonArray joints = robot["joints"].toArray();
            for (QJsonValueRef joint : joints) {
                QJsonObject j = joint.toObject();
                j.remove("motor");
                joint = j;
            }
            robot["joints"] = joints;
            root["robot"] = robot;
        });
        const Run r = run({"eval", rigid, "--q", "0,0,0,0,0,0", "--qd", "0,0,0,0,0,0"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out).object();
        for (const char* key : {"B", "C", "g", "Q", "qdd", "Ekin", "Epot"}) QVERIFY2(o.contains(key), key);
        const QJsonArray g = o["g"].toArray();
        QCOMPARE(g.size(), 6);
        QVERIFY(std::abs(g[1].toDouble() - 37.4837) < 1e-4);
        QVERIFY(std::abs(g[2].toDouble() - 0.2489) < 1e-4);
        const double diag[] = {3.1771, 2.1318, 0.3618, 0.00164, 0.00064, 0.00004};
        for (int i = 0; i < 6; ++i) QVERIFY(std::abs(o["B"].toArray()[i].toArray()[i].toDouble() - diag[i]) < 1e-4);
        QCOMPARE(o["Ekin"].toDouble(), 0.0);
        QVERIFY(r.err.contains("triangle"));  // Corke's link 1 is warned about, not refused
    }

    // With its motors, examples/puma560.json gives the Robotics Toolbox's inertia at
    // qn = (0, π/4, π, 0, π/4, 0).
    void evalPuma560WithMotorsAtNominal() {
        const Run r = run({"eval", example("puma560.json"), "--q", "0,0.7853981633974483,3.141592653589793,0,0.7853981633974483,0", "--qd",
                           "0,0,0,0,0,0"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray B = QJsonDocument::fromJson(r.out).object()["B"].toArray();
        const double toolbox[] = {3.6594, 4.4137, 0.9378, 0.1925, 0.1713, 0.1941};
        for (int i = 0; i < 6; ++i) QVERIFY(std::abs(B[i].toArray()[i].toDouble() - toolbox[i]) < 5e-5);
    }

    // Refusals of text that is not plain ASCII: one line, the field, the character by
    // its code point, exit code 2, valid UTF-8 (checked in run()).
    void nonAsciiInputIsRefusedInOneLine_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expected");
        const QByteArray head = R"({"format":"lagrangelab-scene/1","name":"x","robot":{"convention":"standard","joints":[)";
        QTest::newRow("degree sign in a length") << head + R"({"type":"revolute","a":"1°","mass":2}]}})"
                                                 << QString::fromUtf8("robot.joints[0].a (joint 1): '°' (U+00B0) at position 2");
        QTest::newRow("minus sign in alpha") << head + R"({"type":"revolute","a":1,"alpha":"−pi/2","mass":2}]}})"
                                             << QString::fromUtf8(
                                                    "robot.joints[0].alpha (joint 1): unexpected character '−' (U+2212) at position 1");
        QTest::newRow("ordinal for degree") << head + R"({"type":"revolute","a":1,"alpha":"90º","mass":2}]}})"
                                            << QString::fromUtf8("'º' (U+00BA) at position 3");
        QTest::newRow("cut character") << head + QByteArray("{\"type\":\"revolute\",\"a\":1,\"alpha\":\"90\xC2\",\"mass\":2}]}}")
                                       << QString("the file is not UTF-8: byte 0xC2 at line 1, column");
    }
    void nonAsciiInputIsRefusedInOneLine() {
        QFETCH(QByteArray, json);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = writeScene(dir, json);
        const Run r = run({"eval", path, "--q", "0", "--qd", "0"});
        QCOMPARE(r.exitCode, 2);
        // one error line, then at most one hint line
        const QStringList lines = QString::fromUtf8(r.err).split('\n', Qt::SkipEmptyParts);
        QVERIFY2(lines.size() == 1 || (lines.size() == 2 && lines[1].startsWith("hint: ")), r.err.constData());
        QVERIFY2(lines[0].contains(expected), r.err.constData());
    }

    // A bare 90 in alpha is loaded as 90 rad, with a warning that names the field.
    void bareDegreesWarn() {
        QTemporaryDir dir;
        const QString path = editedExample(dir, "planar_2r.json", [](QJsonObject& root) {
            QJsonObject robot = root["robot"].toObject();
            QJsonArray joints = robot["joints"].toArray();
            QJsonObject first = joints[0].toObject();
            first["alpha"] = 90;
            joints[0] = first;
            robot["joints"] = joints;
            root["robot"] = robot;
        });
        const Run r = run({"eval", path, "--q", "0,0", "--qd", "0,0"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(QString::fromUtf8(r.err).contains(
                     QString::fromUtf8("robot.joints[0].alpha (joint 1): alpha 90 rad — did you mean 90°? write 90° or pi/2")),
                 r.err.constData());
    }

    void evalTauReplacesSceneTorques() {
        const Run a = run({"eval", example("mass_spring_pair.json"), "--q", "0.1,0", "--qd", "0,0", "--tau", "0,2"});
        QCOMPARE(a.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(a.out).object();
        QCOMPARE(o["Q"].toArray()[1].toDouble(), 2.0);
        // B = [[I1+I2, I2], [I2, I2]] with I1 = 0.5, I2 = 0.2
        QVERIFY(std::abs(o["B"].toArray()[0].toArray()[0].toDouble() - 0.7) < 1e-12);
        QVERIFY(std::abs(o["B"].toArray()[0].toArray()[1].toDouble() - 0.2) < 1e-12);
    }

    void simulateWritesTrajectoryAndSummary() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("out.csv");
        const Run r = run({"simulate", example("double_pendulum.json"), "--duration", "1", "--out", csv});
        QCOMPARE(r.exitCode, 0);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        // the trajectory, then where the torque goes (test_check_cli reads those columns)
        QVERIFY(lines[0].startsWith("t,q1,q2,qd1,qd2,Ekin,Epot,E,W,tau_inertial_1 [N·m],tau_inertial_2 [N·m],"));
        QVERIFY(lines.size() > 50);
        QVERIFY(r.err.contains("right-hand-side evaluations"));
        QVERIFY(r.err.contains("max |dE|/E"));
    }

    void lagrangianTrajectoryUsesTheUsersNames() {
        QTemporaryDir dir;
        const QString csv = dir.filePath("pair.csv");
        const Run r = run({"simulate", example("mass_spring_pair_lagrangian.json"), "--duration", "0.5", "--out", csv});
        QCOMPARE(r.exitCode, 0);
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        // a typed Lagrangian's torque columns have no unit: its parameters carry none
        QVERIFY(f.readLine().trimmed().startsWith("t,theta1,theta2,theta1_dot,theta2_dot,Ekin,Epot,E,W,tau_inertial_1,"));
    }

    void underactuatedIsReported() {
        const Run r = run({"simulate", example("acrobot.json"), "--duration", "0.1", "--out", QDir::temp().filePath("acrobot.json")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("underactuated"), r.err.constData());
    }

    void badInputGivesOneLineAndExitCode2_data() {
        QTest::addColumn<QString>("json");
        QTest::addColumn<QString>("expected");
        const QString head = R"({"format":"lagrangelab-scene/1","name":"x","robot":{"convention":"standard","joints":[)";
        QTest::newRow("negative mass") << head + R"({"type":"revolute","a":1,"mass":-2,"inertia":{"zz":1}}]}})"
                                       << "robot.joints[0].mass";
        QTest::newRow("non-PSD inertia") << head + R"({"type":"revolute","a":1,"mass":2,"inertia":{"xx":1,"yy":1,"zz":1,"xy":5}}]}})"
                                         << "robot.joints[0].inertia";
        QTest::newRow("massless joint") << head + R"({"type":"revolute","a":1,"mass":0}]}})"
                                        << "robot.joints[0]";
        QTest::newRow("malformed JSON") << head + R"({"type":"revolute",,]}})"
                                        << "JSON syntax error";
        QTest::newRow("unknown integrator") << head + R"({"type":"revolute","a":1,"mass":2}]},"simulation":{"integrator":"rk45"}})"
                                            << "simulation.integrator";
    }
    void badInputGivesOneLineAndExitCode2() {
        QFETCH(QString, json);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = writeScene(dir, json.toUtf8());
        for (const QStringList& args : {QStringList{"eval", path, "--q", "0", "--qd", "0"}, QStringList{"simulate", path}}) {
            const Run r = run(args);
            QCOMPARE(r.status, QProcess::NormalExit);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(expected.toUtf8()), r.err.constData());
            QVERIFY2(r.err.contains(path.toUtf8()), r.err.constData());
        }
    }

    // derive's plain expressions, parsed back with GiNaC and evaluated, equal eval's
    // numbers: the symbolic and the numeric route agree through the user interface.
    void deriveJsonAgreesWithEval_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("mode");
        QTest::newRow("planar 2R, parameters") << "planar_2r.json"
                                               << "";
        QTest::newRow("SCARA, numeric") << "scara.json"
                                        << "--numeric";
        QTest::newRow("cart-pole, symbolic") << "cart_pole.json"
                                             << "--symbolic";
        QTest::newRow("Stanford, parameters") << "stanford_arm.json"
                                              << "";
    }
    void deriveJsonAgreesWithEval() {
        QFETCH(QString, scene);
        QFETCH(QString, mode);
        QStringList args{"derive", example(scene.toUtf8().constData()), "--format", "json"};
        if (!mode.isEmpty()) args << mode;
        const Run derived = run(args);
        QCOMPARE(derived.exitCode, 0);
        const QJsonObject d = QJsonDocument::fromJson(derived.out).object();
        for (const char* key : {"B", "C", "g", "Q", "steps"}) QVERIFY2(d.contains(key), key);
        const int n = d["B"].toArray().size();
        QStringList q, qd;
        for (int i = 0; i < n; ++i) {
            q << QString::number(0.3 + 0.4 * i);
            qd << QString::number(0.7 - 0.5 * i);
        }
        const Run numeric = run({"eval", example(scene.toUtf8().constData()), "--q", q.join(','), "--qd", qd.join(',')});
        QCOMPARE(numeric.exitCode, 0);
        const QJsonObject e = QJsonDocument::fromJson(numeric.out).object();

        // every symbol the expressions may use: state, time, the scene's parameters (and
        // in --symbolic mode the textbook symbols, whose values derive reports per step
        // 0 only as names: so compare that mode's structure, not its numbers)
        GiNaC::symtab table;
        GiNaC::lst state;
        for (int i = 0; i < n; ++i) {
            const GiNaC::symbol qi("q" + std::to_string(i + 1)), qdi("qd" + std::to_string(i + 1));
            table[qi.get_name()] = qi;
            table[qdi.get_name()] = qdi;
            state.append(qi == q[i].toDouble());
            state.append(qdi == qd[i].toDouble());
        }
        GiNaC::parser reader(table);
        const auto value = [&](const QJsonValue& expr) {
            const GiNaC::ex parsed = reader(expr.toString().toStdString());
            GiNaC::ex v = parsed.subs(state);
            for (const auto& [name, symbol] : reader.get_syms())
                if (!table.count(name)) v = v.subs(symbol == parameterValue(scene, name));
            return GiNaC::ex_to<GiNaC::numeric>(v.evalf()).to_double();
        };
        if (mode == "--symbolic") {
            QVERIFY(d["B"].toArray()[0].toArray()[0].toString().contains("m1"));
            return;
        }
        for (int i = 0; i < n; ++i) {
            const double g = value(d["g"].toArray()[i]);
            QVERIFY2(std::abs(g - e["g"].toArray()[i].toDouble()) < 1e-9 * std::max(1.0, std::abs(g)),
                     qPrintable(QString("g%1").arg(i + 1)));
            for (int j = 0; j < n; ++j) {
                const double b = value(d["B"].toArray()[i].toArray()[j]), c = value(d["C"].toArray()[i].toArray()[j]);
                QVERIFY(std::abs(b - e["B"].toArray()[i].toArray()[j].toDouble()) < 1e-9 * std::max(1.0, std::abs(b)));
                QVERIFY(std::abs(c - e["C"].toArray()[i].toArray()[j].toDouble()) < 1e-9 * std::max(1.0, std::abs(c)));
            }
        }
    }

    // --out writes every format, the same bytes stdout gets; an unwritable path is refused
    // before the work, naming it.
    void deriveOutWritesEveryFormat_data() {
        QTest::addColumn<QString>("format");
        for (const char* f : {"text", "latex", "json"}) QTest::newRow(f) << QString(f);
    }
    void deriveOutWritesEveryFormat() {
        QFETCH(QString, format);
        QTemporaryDir dir;
        const QString path = dir.filePath("2r." + format);
        const Run toFile = run({"derive", example("planar_2r.json"), "--format", format, "--out", path});
        QCOMPARE(toFile.exitCode, 0);
        QVERIFY(toFile.out.isEmpty());
        const Run toStdout = run({"derive", example("planar_2r.json"), "--format", format});
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray written = f.readAll(), shown = toStdout.out;
        if (format == "json") {  // the derivation's own timings differ from run to run
            static const QRegularExpression seconds("\"[a-z_]*seconds\": *[0-9.e-]+");
            written = QString::fromUtf8(written).replace(seconds, "").toUtf8();
            shown = QString::fromUtf8(shown).replace(seconds, "").toUtf8();
        }
        QCOMPARE(written, shown);
        const Run refused = run({"derive", example("planar_2r.json"), "--format", format, "--out", "/nonexistent/x." + format});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY(refused.err.contains("/nonexistent/x." + format.toUtf8()));
    }

    void deriveTextIsTheTextbookForm() {
        const Run r = run({"derive", example("planar_2r.json"), "--steps", "7-8"});
        QCOMPARE(r.exitCode, 0);
        const QString out = QString::fromUtf8(r.out);
        QVERIFY2(out.contains(QString::fromUtf8("I1 + m1 ℓc1² + I2 + m2 (a1² + ℓc2² + 2 a1 ℓc2 c2)")), qPrintable(out));
        QVERIFY(out.contains(QString::fromUtf8("I2 + m2 (ℓc2² + a1 ℓc2 c2)")));
        QVERIFY(out.contains(QString::fromUtf8("−m2 a1 ℓc2 s2 q̇2")));
        QVERIFY(!out.contains("Step 6"));  // --steps 7-8 shows only those
        const Run again = run({"derive", example("planar_2r.json"), "--steps", "7-8"});
        QCOMPARE(again.out, r.out);  // deterministic from run to run
    }

    // The course notes' rotational mass–spring pair typed as a Lagrangian: the
    // equations come out in the notes' own form, the JSON in the user's names.
    void deriveLagrangianMassSpringPair() {
        const Run text = run({"derive", example("mass_spring_pair_lagrangian.json")});
        QCOMPARE(text.exitCode, 0);
        const QString out = QString::fromUtf8(text.out);
        QVERIFY2(out.contains(QString::fromUtf8("I1 θ̈1 + K1 θ1 + K2 (θ1 − θ2) = 0")), qPrintable(out));
        QVERIFY(out.contains(QString::fromUtf8("I2 θ̈2 − K2 (θ1 − θ2) = τ")));
        const Run json = run({"derive", example("mass_spring_pair_lagrangian.json"), "--format", "json"});
        QCOMPARE(json.exitCode, 0);
        const QJsonObject d = QJsonDocument::fromJson(json.out).object();
        QCOMPARE(d["coordinates"].toArray()[1].toString(), QString("theta2"));
        QCOMPARE(d["B"].toArray()[0].toArray()[0].toString(), QString("I1"));
        QCOMPARE(d["B"].toArray()[0].toArray()[1].toString(), QString("0"));
        QCOMPARE(d["Q"].toArray()[1].toString(), QString("tau"));
        // g = ∂E_pot/∂θ in plain syntax, checked by value: K1 θ1 + K2 (θ1 − θ2) at θ = (0.3, −0.2)
        GiNaC::symtab table;
        for (const char* name : {"theta1", "theta2", "K1", "K2"}) table[name] = GiNaC::symbol(name);
        GiNaC::parser reader(table);
        const GiNaC::ex g1 = reader(d["g"].toArray()[0].toString().toStdString());
        const GiNaC::lst values{table["theta1"] == 0.3, table["theta2"] == -0.2, table["K1"] == 10, table["K2"] == 4};
        QVERIFY(std::abs(GiNaC::ex_to<GiNaC::numeric>(g1.subs(values).evalf()).to_double() - (10 * 0.3 + 4 * 0.5)) < 1e-12);
    }

    void deriveLatexIsACompleteDocument() {
        const Run r = run({"derive", example("scara.json"), "--format", "latex"});
        QCOMPARE(r.exitCode, 0);
        const QByteArray& tex = r.out;
        QVERIFY(tex.startsWith("\\documentclass"));
        QVERIFY(tex.trimmed().endsWith("\\end{document}"));
        QCOMPARE(tex.count('{'), tex.count('}'));
        QCOMPARE(tex.count("\\["), tex.count("\\]"));
        for (int step = 0; step <= 8; ++step) QVERIFY(tex.contains(QString("Step %1:").arg(step).toUtf8()));
    }

    void badCommandLineGivesExitCode2() {
        QCOMPARE(run({"eval", example("puma560.json"), "--q", "0,0"}).exitCode, 2);
        QCOMPARE(run({"simulate", example("puma560.json"), "--integrator", "nope"}).exitCode, 2);
        QCOMPARE(run({"simulate", example("puma560.json"), "--duration", "abc"}).exitCode, 2);
        QCOMPARE(run({"frobnicate"}).exitCode, 2);
        // The benchmarks are lagrangelab-bench's (tests/test_bench), not a user command.
        const Run bench = run({"bench", "--rhs"});
        QCOMPARE(bench.exitCode, 2);
        QVERIFY2(bench.err.startsWith("error: unknown command 'bench'"), bench.err.constData());
    }

    // A scene whose parameters are named like the derivation's shorthand (c1 = cos q1,
    // s12 = sin(q1 + q2)) is refused in every format with one line naming the clash:
    // it used to print m1 c1² as m1*cos(q1)^2 and s12 sin(q1 + q2) as s12².
    void deriveRefusesShorthandParameterNames_data() {
        QTest::addColumn<QString>("format");
        QTest::newRow("text") << "text";
        QTest::newRow("latex") << "latex";
        QTest::newRow("json") << "json";
    }
    void deriveRefusesShorthandParameterNames() {
        QFETCH(QString, format);
        QTemporaryDir dir;
        const QString path = dir.filePath("planar_2r_c1_s12.json");
        QFile original(example("planar_2r.json"));
        QVERIFY(original.open(QIODevice::ReadOnly));
        QFile renamed(path);
        QVERIFY(renamed.open(QIODevice::WriteOnly));
        renamed.write(original.readAll().replace("lc1", "c1").replace("lc2", "s12"));
        renamed.close();
        const Run r = run({"derive", path, "--format", format});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY2(r.err.startsWith(("error: " + path + ": parameters.c1: ").toUtf8()), r.err.constData());
        QVERIFY2(r.err.contains("cos q1"), r.err.constData());
        // The numbers alone do not clash: the numeric model derives.
        QCOMPARE(run({"derive", path, "--format", format, "--numeric"}).exitCode, 0);
    }

    void versionIsTheProjectVersion() {
        for (const char* spelling : {"--version", "version"}) {
            const Run r = run({spelling});
            QCOMPARE(r.exitCode, 0);
            QCOMPARE(r.out, QByteArray("lagrangelab " LL_VERSION "\n"));
        }
    }

    // `help` and `--help` list every command; each is also in the usage error of a bare
    // `lagrangelab` where there is no display for its window.
    void helpListsEveryCommand() {
        Run bare = run({}, false);
        QCOMPARE(bare.exitCode, 2);
        QVERIFY2(bare.err.contains("no display"), bare.err.constData());
        bare.err = bare.err.left(bare.err.indexOf("error: no display"));
        for (const char* spelling : {"help", "--help"}) {
            const Run r = run({spelling});
            QCOMPARE(r.exitCode, 0);
            QVERIFY(r.out.startsWith("usage: lagrangelab <command>"));
            QCOMPARE(r.out, bare.err);
            for (const char* command : {"eval SCENE", "simulate SCENE", "derive SCENE", "integrators", "accuracy SCENE", "render SCENE",
                                        "codegen SCENE", "help [COMMAND]", "version"})
                QVERIFY2(r.out.contains(QByteArray("\n  ") + command), command);
        }
    }

    // `lagrangelab COMMAND --help` (anywhere among its arguments) and `help COMMAND`
    // print that command's usage, exit 0; a usage error prints the same synopsis.
    void commandHelpPrintsItsUsage_data() {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("synopsis");
        QTest::newRow("eval") << "eval"
                              << "SCENE --q v1,... --qd v1,... [--t T] [--tau v1,...]";
        QTest::newRow("simulate") << "simulate"
                                  << "SCENE [--duration T] [--integrator NAME]";
        QTest::newRow("derive") << "derive"
                                << "SCENE [--format text|latex|json|pdf|svg|png] [--out FILE] [--steps 0-9]";
        QTest::newRow("integrators") << "integrators"
                                     << "";
        QTest::newRow("accuracy") << "accuracy"
                                  << "SCENE [--integrators a,b,...]";
        QTest::newRow("help") << "help"
                              << "[COMMAND]";
        QTest::newRow("version") << "version"
                                 << "";
    }
    void commandHelpPrintsItsUsage() {
        QFETCH(QString, command);
        QFETCH(QString, synopsis);
        const QByteArray head = ("usage: lagrangelab " + command + (synopsis.isEmpty() ? "" : " " + synopsis)).toUtf8();
        QList<QStringList> spellings{{command, "--help"}, {"help", command}, {"help", command, "--help"}};
        if (command != "help") spellings.append({command, example("puma560.json"), "--help"});  // help SCENE: an unknown command
        for (const QStringList& args : spellings) {
            const Run r = run(args);
            QCOMPARE(r.exitCode, 0);
            QVERIFY2(r.out.startsWith(head), r.out.constData());
            QVERIFY(r.err.isEmpty());
            for (const char* other : {"eval", "simulate", "derive", "accuracy", "render"})
                if (command != other) QVERIFY2(!r.out.contains(QByteArray("lagrangelab ") + other), other);
        }
        if (synopsis.startsWith("SCENE")) {  // without its scene: the same synopsis as an error, exit 2
            const Run error = run({command});
            QCOMPARE(error.exitCode, 2);
            QVERIFY2(error.err.startsWith("error: " + head), error.err.constData());
        }
    }
};

LL_TEST_GUILESS_MAIN(TestCli)

}  // namespace test_cli
#include "test_cli.moc"
