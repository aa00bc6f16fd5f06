// `lagrangelab exercise` and `lagrangelab grade` as a lecturer runs them, headless: a robot
// per student within the --vary ranges, the same robots for the same seed, templates that
// list the tasks, sheets and solutions with their page counts, Moodle XML that parses with
// a question per task; grading the templates filled with the key's right answers (all
// right), one wrong answer (wrong, with a hint in the CSV), blanks (unanswered), garbage
// (unreadable); and the bad input: another student's robot, another seed, an unknown
// entry, a duplicated student id, each one line and exit 2.
#include "test_registry.hpp"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QProcess>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include "core/io/scene_file.hpp"
#include "core/pipeline/exercise_set.hpp"
#include "process_run.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_exercise_cli {

class TestExerciseCli : public QObject {
    Q_OBJECT
    using Run = ll::test::ProcessRun;
    static Run run(const QStringList& args) { return ll::test::runHeadless(LL_CLI, args); }
    static QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }
    static QByteArray bytes(const QString& path) { return ll::test::fileBytes(path); }
    static QJsonObject json(const QString& path) { return QJsonDocument::fromJson(bytes(path)).object(); }
    static void write(const QString& path, const QByteArray& text) {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text);
    }
    static int pages(const QString& pdf) {
        QProcess info;
        info.start("pdfinfo", {pdf});
        if (!info.waitForFinished(30000)) return -1;
        for (const QByteArray& line : info.readAllStandardOutput().split('\n'))
            if (line.startsWith("Pages:")) return line.mid(6).trimmed().toInt();
        return -1;
    }
    static QString pdfText(const QString& pdf) {
        QProcess text;
        text.start("pdftotext", {pdf, "-"});
        text.waitForFinished(30000);
        return QString::fromUtf8(text.readAllStandardOutput());
    }
    // The right answer of `entry` for the robot in `scene`, in the parameters' names (exact:
    // GiNaC's own syntax, which the answer reader reads), or with the numbers in.
    static QString rightAnswer(const QString& scene, const std::string& entry,
                               ll::symbolic::ParameterMode mode = ll::symbolic::ParameterMode::Parametric) {
        const auto key = ll::AnswerKey::build(ll::parseScene(bytes(scene).toStdString()), mode);
        return QString::fromStdString(ll::maximaAnswer(*key, entry));
    }

    QTemporaryDir dir_;
    QString set_;  // the set made once, graded by the tests below
    const QStringList entries_{"b11", "b12", "g2"};

    QString makeSet(const QString& out, const QString& seed) {
        const Run r = run({"exercise", example("planar_2r.json"), "--out", out, "--count", "3", "--seed", seed, "--vary", "m2=1.2..1.8",
                           "--vary", "a1=0.9..1.1", "--entries", "b11,B12,g2"});
        return r.exitCode == 0 ? QString() : QString::fromUtf8(r.err);
    }

    // The three students' templates filled: every answer right but those `change` changes.
    QStringList fillTemplates(const QString& into, const std::function<void(const QString&, QJsonObject&)>& change = {}) {
        QDir().mkpath(into);
        QStringList files;
        for (const QString& id : {"s01", "s02", "s03"}) {
            QJsonObject t = json(set_ + "/" + id + "/answers.json");
            QJsonObject answers = t["answers"].toObject();
            for (const QString& e : entries_) answers[e] = rightAnswer(set_ + "/" + id + "/scene.json", e.toStdString());
            t["answers"] = answers;
            if (change) change(id, t);
            const QString file = into + "/" + id + ".json";
            write(file, QJsonDocument(t).toJson());
            files << file;
        }
        return files;
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        set_ = dir_.filePath("set");
        const QString error = makeSet(set_, "7");
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void aRobotPerStudentWithinTheRanges() {
        const QJsonObject manifest = json(set_ + "/exercise.json");
        QCOMPARE(manifest["seed"].toInteger(), 7);
        QCOMPARE(manifest["entries"].toVariant().toStringList(), entries_);  // B12 typed, b12 listed
        const QJsonArray students = manifest["students"].toArray();
        QCOMPARE(students.size(), 3);
        QSet<QString> robots, valueSets;
        for (const QJsonValue& v : students) {
            const QJsonObject s = v.toObject();
            const QString id = s["id"].toString();
            const QJsonObject values = s["values"].toObject();
            QCOMPARE(values.keys(), (QStringList{"a1", "m2"}));
            const double m2 = values["m2"].toDouble(), a1 = values["a1"].toDouble();
            QVERIFY2(m2 >= 1.2 && m2 <= 1.8, qPrintable(QString::number(m2)));
            QVERIFY2(a1 >= 0.9 && a1 <= 1.1, qPrintable(QString::number(a1)));
            QCOMPARE(std::round(m2 * 100) / 100, m2);  // teachable: two decimals in a range 0.6 wide
            // the student's scene holds the drawn values, the others as the example has them
            const QJsonObject parameters = json(set_ + "/" + id + "/scene.json")["parameters"].toObject();
            QCOMPARE(parameters["m2"].toDouble(), m2);
            QCOMPARE(parameters["a1"].toDouble(), a1);
            QCOMPARE(parameters["m1"].toDouble(), 2.0);
            // its template: this student, this set, this robot, the tasks blank
            const QJsonObject t = json(set_ + "/" + id + "/answers.json");
            QCOMPARE(t["student"].toString(), id);
            QCOMPARE(t["seed"].toInteger(), 7);
            QCOMPARE(t["robot"].toString(), s["robot"].toString());
            QCOMPARE(t["answers"].toObject().keys(), (QStringList{"b11", "b12", "g2"}));
            for (const QString& e : entries_) QCOMPARE(t["answers"].toObject()[e].toString(), QString());
            robots << s["robot"].toString();
            valueSets << QString("%1,%2").arg(m2).arg(a1);
            QCOMPARE(pages(set_ + "/" + id + "/sheet.pdf"), 1);
            const QString sheet = pdfText(set_ + "/" + id + "/sheet.pdf");
            QVERIFY2(sheet.contains(id) && sheet.contains(QString::number(m2)), qPrintable(sheet));
        }
        QCOMPARE(robots.size(), 3);
        QCOMPARE(valueSets.size(), 3);
        QCOMPARE(pages(set_ + "/solutions.pdf"), 3);  // a page per student
    }

    void theSameSeedTheSameRobots() {
        const QString again = dir_.filePath("again"), other = dir_.filePath("other");
        QVERIFY(makeSet(again, "7").isEmpty());
        QVERIFY(makeSet(other, "8").isEmpty());
        QCOMPARE(bytes(again + "/exercise.json"), bytes(set_ + "/exercise.json"));
        for (const QString& id : {"s01", "s02", "s03"})
            QCOMPARE(bytes(again + "/" + id + "/scene.json"), bytes(set_ + "/" + id + "/scene.json"));
        QVERIFY(bytes(other + "/exercise.json") != bytes(set_ + "/exercise.json"));
    }

    void moodleXmlHasAQuestionPerTask() {
        QXmlStreamReader xml(bytes(set_ + "/moodle.xml"));
        int questions = 0, inputs = 0;
        QStringList tests, variables;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement()) continue;
            if (xml.name() == u"question" && xml.attributes().value("type") == u"stack") ++questions;
            if (xml.name() == u"input") ++inputs;
            if (xml.name() == u"answertest") tests << xml.readElementText();
            if (xml.name() == u"questionvariables") {
                xml.readNextStartElement();
                variables << xml.readElementText();
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(questions, 3);
        QCOMPARE(inputs, 3);
        QCOMPARE(tests, (QStringList{"AlgEquiv", "AlgEquiv", "AlgEquiv"}));
        // the varied parameters drawn by STACK on the set's grid, the model answer in Maxima's syntax
        QVERIFY2(variables[0].contains("m2: (120 + rand(61))/100;"), qPrintable(variables[0]));
        QVERIFY2(variables[0].contains("a1: (90 + rand(21))/100;"), qPrintable(variables[0]));
        QVERIFY2(variables[0].contains("ta: ") && variables[0].contains("cos(q2)"), qPrintable(variables[0]));
    }

    void rightAnswersAreAllRight() {
        const QStringList files = fillTemplates(dir_.filePath("right"));
        const QString out = dir_.filePath("graded-right");
        const Run r = run(QStringList{"grade", set_} + files + QStringList{"--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.out.startsWith("3 students, 9 answers: 9 right, 0 wrong, 0 unreadable, 0 unanswered"), r.out.constData());
        const QList<QByteArray> lines = bytes(out + "/grades.csv").trimmed().split('\n');
        QCOMPARE(lines.size(), 10);
        QCOMPARE(lines[0], QByteArray("student,entry,verdict,hint"));
        QCOMPARE(lines[1], QByteArray("s01,b11,right,"));
        for (const QString& id : {"s01", "s02", "s03"}) QCOMPARE(pages(out + "/" + id + "/feedback.pdf"), 1);
        // a student without a file is named after the summary
        const Run two = run({"grade", set_, files[0], files[1], "--out", dir_.filePath("graded-two")});
        QVERIFY2(two.exitCode == 0, two.err.constData());
        QVERIFY2(two.out.startsWith("2 students, 6 answers: 6 right, 0 wrong, 0 unreadable, 0 unanswered\n"
                                    "no answer file from 1 of 3 students: s03\n"),
                 two.out.constData());
    }

    void aWrongAnswerGetsAHint() {
        const QStringList files = fillTemplates(dir_.filePath("wrong"), [&](const QString& id, QJsonObject& t) {
            QJsonObject answers = t["answers"].toObject();
            if (id == "s01") {  // typed from the sheet's numbers, as a student does: exact decimals
                const QJsonObject values = json(set_ + "/exercise.json")["students"].toArray()[0].toObject()["values"].toObject();
                const QString m2 = QString::number(values["m2"].toDouble()), a1 = QString::number(values["a1"].toDouble());
                answers["b11"] = QString("0.166667 + 0.08 + 2*0.5^2 + %1*(%2^2 + 0.4^2 + 2*%2*0.4*c2)").arg(m2, a1);
            }
            if (id == "s02") {  // the sign of the numbers' answer
                answers["b11"] = "-(" + rightAnswer(set_ + "/s02/scene.json", "b11", ll::symbolic::ParameterMode::Numeric) + ")";
                answers["b12"] = "";        // left blank
                answers["g2"] = "3 +* q1";  // unreadable
            }
            t["answers"] = answers;
        });
        const QString out = dir_.filePath("graded-wrong");
        const Run r = run(QStringList{"grade", set_} + files + QStringList{"--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.out.startsWith("3 students, 9 answers: 6 right, 1 wrong, 1 unreadable, 1 unanswered"), r.out.constData());
        const QString csv = QString::fromUtf8(bytes(out + "/grades.csv"));
        QVERIFY2(csv.contains("\ns01,b11,right,\n"), qPrintable(csv));
        QVERIFY2(csv.contains("\ns02,b11,wrong,Only the sign is wrong.\n"), qPrintable(csv));
        QVERIFY2(csv.contains("\ns02,b12,unanswered,\n"), qPrintable(csv));
        QVERIFY2(csv.contains("\ns02,g2,unreadable,"), qPrintable(csv));
        // the feedback names the verdicts and never gives the right answer away
        const QString feedback = pdfText(out + "/s02/feedback.pdf");
        QVERIFY2(feedback.contains("0 of 3 answers right") && feedback.contains("Only the sign is wrong.") &&
                     feedback.contains("unanswered"),
                 qPrintable(feedback));
        const QString danish = dir_.filePath("graded-da");
        const Run da = run(QStringList{"grade", set_} + files + QStringList{"--out", danish, "--lang", "da"});
        QVERIFY2(da.exitCode == 0, da.err.constData());
        QVERIFY2(da.out.startsWith("3 studerende, 9 svar: 6 rigtige"), da.out.constData());
        QVERIFY(pdfText(danish + "/s02/feedback.pdf").contains("ikke besvaret"));
    }

    // A student may do the exercise in the window: their scene.json opens with the tasks
    // asked (its exercise section), and the scene saved with the answers is graded as their
    // hand-in, its student found by the robot (the answers do not change the fingerprint).
    void aSceneSavedByTheWindowIsGraded() {
        QJsonObject scene = json(set_ + "/s02/scene.json");
        QCOMPARE(scene["exercise"].toObject()["entries"].toVariant().toStringList(), entries_);
        QJsonObject answers;
        answers["b11"] = rightAnswer(set_ + "/s02/scene.json", "b11");
        answers["g2"] = "1";
        QJsonObject exercise = scene["exercise"].toObject();
        exercise["answers"] = answers;
        scene["exercise"] = exercise;
        const QString handedIn = dir_.filePath("handed-in-s02.json");
        write(handedIn, QJsonDocument(scene).toJson());
        const QString out = dir_.filePath("graded-scene");
        const Run r = run({"grade", set_, handedIn, "--out", out});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QString csv = QString::fromUtf8(bytes(out + "/grades.csv"));
        QVERIFY2(csv.contains("\ns02,b11,right,\n") && csv.contains("\ns02,b12,unanswered,\n") && csv.contains("\ns02,g2,wrong,"),
                 qPrintable(csv));
        // check-answer with a student's answer file: their own robot judged; another's refused
        QJsonObject filled = json(set_ + "/s02/answers.json");
        QJsonObject its = filled["answers"].toObject();
        its["b11"] = answers["b11"];
        filled["answers"] = its;
        write(dir_.filePath("s02-answers.json"), QJsonDocument(filled).toJson());
        const Run own = run({"check-answer", set_ + "/s02/scene.json", "--answer-file", dir_.filePath("s02-answers.json")});
        QVERIFY2(own.out.contains("b11: right"), own.out.constData());
        const Run theirs = run({"check-answer", set_ + "/s01/scene.json", "--answer-file", dir_.filePath("s02-answers.json")});
        QCOMPARE(theirs.exitCode, 2);
        QVERIFY2(theirs.err.contains("answers for another robot") && theirs.err.count('\n') == 1, theirs.err.constData());
        // the scene of a robot that is no student's: one line, exit 2
        QJsonObject parameters = scene["parameters"].toObject();
        parameters["a1"] = parameters["a1"].toDouble() + 0.001;
        scene["parameters"] = parameters;
        write(handedIn, QJsonDocument(scene).toJson());
        const Run other = run({"grade", set_, handedIn, "--out", out});
        QCOMPARE(other.exitCode, 2);
        QVERIFY2(other.err.contains("no student's of this exercise set") && other.err.count('\n') == 1, other.err.constData());
    }

    void badInputIsOneLineAndExitTwo() {
        // an answer file for another student's robot
        const QStringList swapped = fillTemplates(dir_.filePath("swapped"), [&](const QString& id, QJsonObject& t) {
            if (id == "s01") t["robot"] = json(set_ + "/s02/answers.json")["robot"];
        });
        Run r = run(QStringList{"grade", set_} + swapped);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: " + swapped[0].toUtf8() + ": \"robot\":") && r.err.count('\n') == 1, r.err.constData());
        // another set's seed
        const QStringList seeded = fillTemplates(dir_.filePath("seeded"), [](const QString& id, QJsonObject& t) {
            if (id == "s03") t["seed"] = 8;
        });
        r = run(QStringList{"grade", set_} + seeded);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: " + seeded[2].toUtf8() + ": \"seed\": 8"), r.err.constData());
        // a task the set has not, and a file that is no JSON
        const QStringList extra = fillTemplates(dir_.filePath("extra"), [](const QString& id, QJsonObject& t) {
            QJsonObject answers = t["answers"].toObject();
            if (id == "s02") answers["b99"] = "1";
            t["answers"] = answers;
        });
        r = run(QStringList{"grade", set_} + extra);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("'b99'") && r.err.count('\n') == 1, r.err.constData());
        write(dir_.filePath("garbage.json"), "{\"student\": ");
        r = run({"grade", set_, dir_.filePath("garbage.json")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("garbage.json: not an answer file"), r.err.constData());
        // the same student twice
        r = run(QStringList{"grade", set_} + fillTemplates(dir_.filePath("twice")) + QStringList{set_ + "/s01/answers.json"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("student 's01' is answered twice"), r.err.constData());

        // exercise: an unknown entry, a duplicated student id, an unknown parameter
        r = run({"exercise", example("planar_2r.json"), "--out", dir_.filePath("x"), "--count", "2", "--entries", "b11,b33"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: --entries: the derivation of Planar 2R arm (uniform rods) has no entry 'b33'"),
                 r.err.constData());
        write(dir_.filePath("class.csv"), "student,name\nanna,Anna\nbo,Bo\nanna,Anna again\n");
        r = run({"exercise", example("planar_2r.json"), "--out", dir_.filePath("x"), "--students", dir_.filePath("class.csv")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("line 4: student 'anna' is listed twice (first on line 2)") && r.err.count('\n') == 1, r.err.constData());
        r = run({"exercise", example("planar_2r.json"), "--out", dir_.filePath("x"), "--count", "2", "--vary", "m9=1..2"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no parameter 'm9'"), r.err.constData());
        r = run({"exercise", example("planar_2r.json"), "--out", dir_.filePath("x"), "--count", "2", "--vary", "m2=2..1"});
        QCOMPARE(r.exitCode, 2);
        r = run({"exercise", example("planar_2r.json"), "--out", dir_.filePath("x"), "--count", "2", "--lang", "da", "--entries", "b33"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("fejl: --entries:"), r.err.constData());
        QVERIFY(!QFileInfo::exists(dir_.filePath("x/exercise.json")));  // nothing made
    }

    void aFamilyOfRobots() {
        // a planar 2R arm and a SCARA: each student gets one, the tasks are those both have
        const QString out = dir_.filePath("family");
        Run r = run({"exercise", example("planar_2r.json"), example("scara.json"), "--out", out, "--count", "6", "--seed", "3", "--entries",
                     "b11,b22", "--vary", "m2=1.2..1.8", "--vary", "m3=0.8..1.2"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject manifest = json(out + "/exercise.json");
        const QJsonArray scenes = manifest["scenes"].toArray();
        QCOMPARE(scenes.size(), 2);
        QCOMPARE(scenes[0].toObject()["file"].toString(), QString("planar_2r.json"));
        QCOMPARE(scenes[1].toObject()["file"].toString(), QString("scara.json"));
        const auto rangeNames = [](const QJsonValue& scene) {
            QStringList names;
            for (const QJsonValue& r : scene.toObject()["ranges"].toArray()) names << r.toObject()["name"].toString();
            return names;
        };
        QCOMPARE(rangeNames(scenes[0]), QStringList{"m2"});  // each member's own parameters only
        QCOMPARE(rangeNames(scenes[1]), (QStringList{"m2", "m3"}));
        QMap<QString, int> members;
        for (const QJsonValue& v : manifest["students"].toArray()) {
            const QJsonObject s = v.toObject();
            const QString scene = s["scene"].toString();
            ++members[scene];
            const QJsonObject own = json(out + "/" + s["id"].toString() + "/scene.json");
            QCOMPARE(own["robot"].toObject()["joints"].toArray().size(), scene == "scara.json" ? 4 : 2);
            const double m2 = own["parameters"].toObject()["m2"].toDouble();
            QVERIFY2(m2 >= 1.2 && m2 <= 1.8, qPrintable(QString::number(m2)));
            QCOMPARE(s["values"].toObject().contains("m3"), scene == "scara.json");  // a member's own parameters only
        }
        QCOMPARE(members.size(), 2);  // both members drawn for this seed
        int questions = 0;
        QXmlStreamReader xml(bytes(out + "/moodle.xml"));
        while (!xml.atEnd())
            if (xml.readNext() == QXmlStreamReader::StartElement && xml.attributes().value("type") == u"stack") ++questions;
        QVERIFY(!xml.hasError());
        QCOMPARE(questions, 4);  // a question per member and task
        // a task one member has not: one line naming that member
        r = run({"exercise", example("planar_2r.json"), example("scara.json"), "--out", dir_.filePath("y"), "--count", "2", "--entries",
                 "b33"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: --entries: the derivation of Planar 2R arm (uniform rods) has no entry 'b33'"),
                 r.err.constData());
    }

    void studentsFromASpreadsheet() {
        // a spreadsheet's CSV: byte-order mark, a header, quoted ids, comments and blank lines
        write(dir_.filePath("roster.csv"), "\xEF\xBB\xBFstudent;name\n\"anna.k\";Anna\n# on leave: dan\n\nbo_2;Bo\ncarl-3\n");
        const QString out = dir_.filePath("roster");
        const Run r =
            run({"exercise", example("planar_2r.json"), "--out", out, "--students", dir_.filePath("roster.csv"), "--entries", "g2"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QStringList ids;
        for (const QJsonValue& v : json(out + "/exercise.json")["students"].toArray()) ids << v.toObject()["id"].toString();
        QCOMPARE(ids, (QStringList{"anna.k", "bo_2", "carl-3"}));
        for (const QString& id : ids) QVERIFY2(QFileInfo(out + "/" + id + "/sheet.pdf").size() > 0, qPrintable(id));
        write(dir_.filePath("bad.csv"), "student\nanna\n../etc\n");
        const Run bad = run({"exercise", example("planar_2r.json"), "--out", out, "--students", dir_.filePath("bad.csv")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("line 3: '../etc' is not a student id"), bad.err.constData());
    }

    void stepZeroAsksForTheDhTable() {
        const QString out = dir_.filePath("steps");
        const Run r = run({"exercise", example("planar_2r.json"), "--out", out, "--count", "1", "--steps", "0-2", "--lang", "da"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject manifest = json(out + "/exercise.json");
        QVERIFY(manifest["dh_table"].toBool());
        const QStringList entries = manifest["entries"].toVariant().toStringList();
        QVERIFY2(entries.contains("T_2^0(1,4)") && entries.contains("p_c2(1)"), qPrintable(entries.join(' ')));
        QVERIFY2(!entries.contains("T_2^0(4,4)") && !entries.contains("p_c2(3)"), qPrintable(entries.join(' ')));  // constants, zeros
        QVERIFY(pdfText(out + "/s01/sheet.pdf").contains("Trin 0"));
    }
};

LL_TEST_MAIN(TestExerciseCli)

}  // namespace test_exercise_cli
#include "test_exercise_cli.moc"
