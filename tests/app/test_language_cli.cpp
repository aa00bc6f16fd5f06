// The derivation in the course's language and its textbook's notation (issue 37), through
// the program as a student runs it: `derive --lang da` writes the Danish step titles in
// text, LaTeX and the typeset PDF; --lang works with only the C.UTF-8 locale and without
// it LANGUAGE/LANG decide as Debian's tools read them; each notation profile's letters
// in text, LaTeX and JSON for the 2R and the PUMA 560; every step title any example has
// has Danish words (core/present/danish/document.def); bad --lang and --notation values
// are refused with exit code 2.
#include "test_registry.hpp"

#include <QProcess>
#include <QFile>
#include <QTemporaryDir>
#include <filesystem>

#include "process_run.hpp"
#include "core/io/scene_file.hpp"
#include "core/model/diagnostics.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "core/present/language.hpp"
#include "core/present/message_text.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_language_cli {

using namespace ll;

namespace {

struct Run {
    int code;
    QString out, err;
};

// The program as on a fresh Debian, with `env` added.
Run run(const QStringList& args, const QStringList& env = {}, const QString& program = LL_CLI) {
    const test::ProcessRun r = test::runProcess(program, args, {}, test::freshLocaleEnvironment(env), 300000);
    return {r.exitCode, QString::fromUtf8(r.out), QString::fromUtf8(r.err)};
}

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

}  // namespace

class TestLanguageCli : public QObject {
    Q_OBJECT
private slots:
    void danishStepTitlesInTextLatexAndPdf() {
        const Run text = run({"derive", example("planar_2r.json"), "--lang", "da"});
        QVERIFY2(text.code == 0, qPrintable(text.err));
        for (const char* s : {"Trin 0. DH-parametre (standardkonvention)", "Trin 7. Kinetisk energi og massematricen",
                              "Trin 8. Bevægelsesligninger (Lagrange–d'Alembert)", "Aktuering: ingen input (underaktueret: m = 0 < n = 2)",
                              "række i:", "kun ikke-konservative kræfter"})
            QVERIFY2(text.out.contains(QString::fromUtf8(s)), s);
        QVERIFY(!text.out.contains("Step ") && !text.out.contains("Kinetic energy") && !text.out.contains("Actuation"));
        const Run latex = run({"derive", example("planar_2r.json"), "--lang", "da", "--format", "latex"});
        QVERIFY(latex.out.contains(QString::fromUtf8("\\section*{Trin 7: Kinetisk energi og massematricen}")));
        QVERIFY(latex.out.contains(QString::fromUtf8("\\paragraph{Aktuering} ingen input")));
        QTemporaryDir dir;
        const QString pdf = dir.filePath("2r_da.pdf");
        QCOMPARE(run({"derive", example("planar_2r.json"), "--lang", "da", "--format", "pdf", "--out", pdf}).code, 0);
        const Run pages = run({pdf, "-"}, {}, "pdftotext");
        QVERIFY2(pages.out.contains(QString::fromUtf8("Trin 7. Kinetisk energi og massematricen")), qPrintable(pages.out.left(2000)));
        QVERIFY(pages.out.contains(QString::fromUtf8("Euler–Lagrange-model")) && !pages.out.contains("Step 7"));
        // JSON: the step titles in Danish, the field names and expressions as they are.
        const Run json = run({"derive", example("planar_2r.json"), "--lang", "da", "--format", "json"});
        QVERIFY(json.out.contains(QString::fromUtf8("\"title\": \"Kinetisk energi og massematricen\"")));
        QVERIFY(json.out.contains("\"name\": \"B\""));
    }

    // The structured form (the Panda) in Danish too: its section titles, form line and the
    // notes on its names.
    void structuredFormInDanish() {
        const Run text = run({"derive", example("panda.json"), "--lang", "da", "--steps", "7"});
        QVERIFY2(text.code == 0, qPrintable(text.err));
        for (const char* s : {"Form: struktureret (auto: 7 led:", "Trin 7. Massematrix:", "(bidrag fra link 2 til b11; afhænger af q2)"})
            QVERIFY2(text.out.contains(QString::fromUtf8(s)), s);
        QVERIFY2(!text.out.contains("contribution of") && !text.out.contains("depends on"), qPrintable(text.out.left(1500)));
    }

    // As Debian's tools read the environment: LANGUAGE first, then LC_ALL, LC_MESSAGES,
    // LANG; --lang over all of them; C and C.UTF-8 are English.
    void environmentDecidesWithoutLang() {
        const auto title = [](const Run& r) { return r.out.contains(QString::fromUtf8("Trin 7. Kinetisk energi")); };
        QVERIFY(!title(run({"derive", example("planar_2r.json"), "--steps", "7"})));
        QVERIFY(title(run({"derive", example("planar_2r.json"), "--steps", "7"}, {"LANGUAGE=da"})));
        QVERIFY(title(run({"derive", example("planar_2r.json"), "--steps", "7"}, {"LANGUAGE=sv:da:en"})));
        QVERIFY(title(run({"derive", example("planar_2r.json"), "--steps", "7"}, {"LC_ALL=da_DK.UTF-8"})));
        QVERIFY(!title(run({"derive", example("planar_2r.json"), "--steps", "7", "--lang", "en"}, {"LANGUAGE=da"})));
        QVERIFY(title(run({"derive", example("planar_2r.json"), "--steps", "7", "--lang", "da"}, {"LANGUAGE=en"})));
    }

    void badValuesAreRefused() {
        const Run lang = run({"derive", example("planar_2r.json"), "--lang", "fr"});
        QCOMPARE(lang.code, 2);
        QVERIFY2(lang.err.contains("--lang") && lang.err.contains("'fr'"), qPrintable(lang.err));
        const Run notation = run({"derive", example("planar_2r.json"), "--notation", "lagrange"});
        QCOMPARE(notation.code, 2);
        QVERIFY2(notation.err.contains("--notation") && notation.err.contains("'lagrange'"), qPrintable(notation.err));
        // codegen keeps its own --lang c|python, and takes --lang da beside it
        QTemporaryDir dir;
        QCOMPARE(run({"codegen", example("planar_2r.json"), "--lang", "python", "--out", dir.filePath("m.py")}).code, 0);
        // every command takes --lang
        QCOMPARE(run({"check", example("planar_2r.json"), "--lang", "da"}).code, 0);
    }

    // Errors and warnings in both languages; the field names untouched.
    void errorsAndWarningsInDanish() {
        QTemporaryDir dir;
        const QString bad = dir.filePath("bad.json");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"json({"format": "lagrangelab-scene/1", "name": "bad", "robot": {"convention": "standard", "joints": [
            {"type": "revolute", "a": 1, "alpha": 0, "d": 0, "theta": 0, "mass": -1, "com": [0, 0, 0], "inertia": {"xx": 0, "yy": 0, "zz": 0}}]}})json");
        f.close();
        const Run da = run({"derive", bad, "--lang", "da"});
        QCOMPARE(da.code, 2);
        QVERIFY2(da.err.contains(QString::fromUtf8("fejl: ") + bad +
                                 QString::fromUtf8(": robot.joints[0].mass (led 1): massen er negativ (-1 kg); den skal være >= 0")),
                 qPrintable(da.err));
        const Run en = run({"derive", bad});
        QVERIFY2(en.err.contains("error: " + bad + ": robot.joints[0].mass (joint 1): mass is negative (-1 kg); it must be >= 0"),
                 qPrintable(en.err));
        // Other kinds of message read as whole Danish sentences, no English clause left.
        const char* broken[] = {
            R"json({"format": "lagrangelab-scene/1", "name": "k", "robot": {"convention": "standard", "joints": [{"type": "revolute", "a": 1, "alpha": 0, "d": 0, "theta": 0, "mass": 1, "com": [0,0,0], "inertia": {"xx": 0.1, "yy": 0.1, "zz": 0.1}, "colour": 3}]}})json",
            R"json({"format": "lagrangelab-scene/1", "name": "k", "robot": {"convention": "standard", "joints": [{"type": "revolute", "a": 1, "alpha": 0, "d": 0, "theta": 0, "mass": 1, "com": [0,0,0], "inertia": {"xx": 0.1, "yy": 0.1, "zz": 0.1}}]}, "effects": {"gravity": [0, -9.81]}})json",
            R"json({"format": "lagrangelab-scene/1", "name": "k", "robot": {"convention": "standard", "joints": [{"type": "revolute", "a": 1, "alpha": 0, "d": 0, "theta": 0, "mass": 1, "com": [0,0,0], "inertia": {"xx": -0.1, "yy": 0.1, "zz": 0.1}}]}, "initial": {"q": [0, 1]}})json"};
        const QStringList expected = {QString::fromUtf8("ukendt nøgle"), QString::fromUtf8("forventede en liste med 3 tal"),
                                      QString::fromUtf8("inertitensoren er ikke positiv semidefinit")};
        for (int k = 0; k < 3; ++k) {
            QFile b(dir.filePath(QString("broken%1.json").arg(k)));
            QVERIFY(b.open(QIODevice::WriteOnly));
            b.write(broken[k]);
            b.close();
            const Run r = run({"derive", b.fileName(), "--lang", "da"});
            QCOMPARE(r.code, 2);
            QVERIFY2(r.err.contains(expected[k]), qPrintable(r.err));
            for (const char* english : {" must ", "expected", " got ", " is not ", " the ", "error:", "hint:"})
                QVERIFY2(!r.err.contains(english), qPrintable(QString(english) + " in " + r.err));
        }
        const Run warned = run({"derive", example("stanford_arm.json"), "--lang", "da", "--steps", "0"});
        QVERIFY2(warned.err.contains(QString::fromUtf8("advarsel: ")) &&
                     warned.err.contains(QString::fromUtf8("overholder ikke trekantsuligheden")) &&
                     warned.err.contains(QString::fromUtf8("tip: intet fysisk legeme har denne inerti")) &&
                     !warned.err.contains("warning:"),
                 qPrintable(warned.err));
    }

    // A simulation that stops, a camera or an entry the command line refuses: the core's
    // words and the program's frame around them in Danish, the English lines as ever.
    void stoppedSimulationAndRefusedValuesInDanish() {
        QTemporaryDir dir;
        const QStringList stiff = {"simulate", example("hard/stiff_spring.json"), "--integrator", "dopri5", "--out", dir.filePath("t.csv")};
        const Run en = run(stiff);
        QCOMPARE(en.code, 3);
        QVERIFY2(en.err.contains("\nerror: simulation stopped: the scene is stiff for dopri5: at t = "), qPrintable(en.err));
        const Run da = run(stiff + QStringList{"--lang", "da"});
        QCOMPARE(da.code, 3);
        const QString stopped = da.err.split('\n', Qt::SkipEmptyParts).last();
        QVERIFY2(stopped.startsWith(QString::fromUtf8("fejl: simuleringen stoppede: scenen er stiv for dopri5: ved t = ")) &&
                     stopped.contains(QString::fromUtf8("Brug den implicitte integrator rosenbrock4")),
                 qPrintable(stopped));
        for (const char* english : {" the ", " stiff ", "error:"})
            QVERIFY2(!stopped.contains(english), qPrintable(english + (": " + stopped)));

        const QStringList camera = {"render", example("planar_2r.json"), "--out", dir.filePath("x.png"), "--camera", "diagonal"};
        QCOMPARE(run(camera).err,
                 QString::fromUtf8("error: --camera diagonal: unknown camera: expected front, side, top, iso, auto or "
                                   "azimuth,elevation[,distance] (degrees, elevation within ±90, distance > 0 in metres)\n"));
        const Run cameraDa = run(camera + QStringList{"--lang", "da"});
        QCOMPARE(cameraDa.code, 2);
        QCOMPARE(cameraDa.err, QString::fromUtf8("fejl: --camera diagonal: ukendt kamera: forventede front, side, top, iso, auto eller "
                                                 "azimuth,elevation[,distance] (grader, elevation inden for ±90, afstand > 0 i meter)\n"));

        const QStringList entry = {"derive", example("planar_2r.json"), "--form", "expanded", "--entry", "B13"};
        QCOMPARE(run(entry).err, QString("error: --entry: 'B13': indices run from 1 to 2\n"));
        const Run entryDa = run(entry + QStringList{"--lang", "da"});
        QCOMPARE(entryDa.code, 2);
        QCOMPARE(entryDa.err, QString::fromUtf8("fejl: --entry: 'B13': indekserne går fra 1 til 2\n"));
    }

    void notationProfiles_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("notation");
        QTest::addColumn<QStringList>("text");
        QTest::addColumn<QStringList>("latex");
        QTest::addColumn<QStringList>("jsonNames");
        QTest::addColumn<QStringList>("notInText");
        for (const char* scene : {"planar_2r.json", "puma560.json"}) {
            const bool puma = QString(scene).startsWith("puma");
            QTest::addRow("%s notes", scene) << scene << "notes" << QStringList{puma ? "b11 = " : "B = ", puma ? "Q = " : "Q = "}
                                             << QStringList{"B(q) = ", "B\\ddot{q} + C\\dot{q} + g = Q"} << QStringList{"B", "g", "Q"}
                                             << QStringList{"τ ="};
            QTest::addRow("%s siciliano", scene) << scene << "siciliano" << QStringList{puma ? "b11 = " : "B = ", "τ = "}
                                                 << QStringList{"B(q) = ", "= \\tau"} << QStringList{"B", "g", "τ"} << QStringList{"Q = "};
            QTest::addRow("%s spong", scene) << scene << "spong" << QStringList{puma ? "d11 = " : "D = ", "τ = ", "D q̈ + C q̇ + g = τ"}
                                             << QStringList{"D(q) = ", "d_{ij}", "D\\ddot{q} + C\\dot{q} + g = \\tau"}
                                             << QStringList{"D", "g", "τ"} << QStringList{"B = ", "b11 = "};
            QTest::addRow("%s craig", scene) << scene << "craig"
                                             << QStringList{puma ? "m11 = " : "M = ", "G = ", "τ = ", "θ̈1",
                                                            "Craig's notation goes with modified DH"}
                                             << QStringList{"M(\\Theta) = ", "G(\\Theta) = ", "\\ddot{\\theta}_{1}",
                                                            "V(\\Theta, \\dot{\\Theta})"}
                                             << QStringList{"M", "G", "τ"} << QStringList{"q̈1", "B = ", "g = "};
        }
    }

    void notationProfiles() {
        QFETCH(QString, scene);
        QFETCH(QString, notation);
        QFETCH(QStringList, text);
        QFETCH(QStringList, latex);
        QFETCH(QStringList, jsonNames);
        QFETCH(QStringList, notInText);
        const QString path = example(scene.toUtf8().constData());
        const Run t = run({"derive", path, "--notation", notation});
        QVERIFY2(t.code == 0, qPrintable(t.err));
        for (const QString& s : text) QVERIFY2(t.out.contains(s), qPrintable(s));
        for (const QString& s : notInText) QVERIFY2(!t.out.contains(s), qPrintable(s));
        const Run l = run({"derive", path, "--notation", notation, "--format", "latex"});
        for (const QString& s : latex) QVERIFY2(l.out.contains(s), qPrintable(s));
        const Run j = run({"derive", path, "--notation", notation, "--format", "json"});
        const QJsonDocument doc = QJsonDocument::fromJson(j.out.toUtf8());
        QStringList names;
        for (const QJsonValue step : doc.object()["steps"].toArray())
            for (const QJsonValue item : step.toObject()["items"].toArray()) names << item.toObject()["name"].toString();
        for (const QString& n : jsonNames) QVERIFY2(names.contains(n), qPrintable(n + " not in " + names.join(",")));
        // The model itself does not change: the JSON results (B, C, g, Q for machines) are the same.
        const Run plain = run({"derive", path, "--format", "json"});
        const QJsonObject a = QJsonDocument::fromJson(plain.out.toUtf8()).object(), b = doc.object();
        for (const char* key : {"B", "C", "g", "Q"}) QCOMPARE(b[key], a[key]);
    }

    // Every step title any example's derivation has is a message id with Danish words.
    void everyStepTitleIsTranslated() {
        std::set<MessageId> titles;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(LL_EXAMPLES_DIR)) {
            if (entry.path().extension() != ".json") continue;
            try {
                const Scene scene = loadScene(entry.path().string()).scene;
                DocumentRequest request;
                request.format = present::DocumentFormat::Display;
                const DerivedDocument derived = deriveDocument(scene, request);
                for (const auto& step : derived.display->steps) {
                    QVERIFY2(step.title.id != MessageId::Literal, step.title.literal.c_str());  // not finished English
                    titles.insert(step.title.id);
                }
            } catch (const InputError&) {  // refused by design (massless_joint)
            }
        }
        QVERIFY2(titles.size() >= 11,
                 qPrintable(QString::number(titles.size())));  // 9 robot steps, two conventions, the Lagrangian's step 0
        for (MessageId t : titles) {
            const char* danish = present::danishWords(t);
            QVERIFY2(danish && *danish && std::string(danish) != englishWords(t), messageIdName(t));
        }
    }
};

LL_TEST_GUILESS_MAIN(TestLanguageCli)

}  // namespace test_language_cli
#include "test_language_cli.moc"
