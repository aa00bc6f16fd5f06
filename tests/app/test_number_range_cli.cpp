// Numbers at the ends of double precision, through the real command line (issue 13's
// two defects). A subnormal number anywhere in a scene used to stop eval, derive and
// simulate with "error: floating point underflow." and exit 1 (CLN under GiNaC throws);
// a finite value that overflows later (a spring's rest at 1e300) made eval print
// "Epot": null with exit 0. Now the first is refused naming the field and the second
// names the quantity; both exit 2 and print no result.
#include "test_registry.hpp"
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include "core/model/scene.hpp"
#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_evaluation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_number_range_cli {

namespace {

struct Run {
    int exitCode;
    QString out, err;
};

Run run(const QStringList& args) {
    QProcess p;
    p.start(LL_CLI, args);
    p.waitForFinished(120000);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

// examples/NAME with `from` replaced by `to` (exactly once), written to dir.
QString edited(const QTemporaryDir& dir, const char* name, const QString& from, const QString& to) {
    QFile in(QString(LL_EXAMPLES_DIR) + "/" + name);
    if (!in.open(QIODevice::ReadOnly)) qFatal("cannot read %s", name);
    QString text = QString::fromUtf8(in.readAll());
    if (text.count(from) != 1) qFatal("'%s' is not in %s exactly once", qPrintable(from), name);
    text.replace(from, to);
    const QString path = dir.filePath(name);
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
    out.write(text.toUtf8());
    return path;
}

// Exit 2, nothing on stdout, and every stderr line that is an error names `field`.
void expectRefused(const Run& r, const QString& field, const QString& words) {
    QVERIFY2(r.exitCode == 2, qPrintable(QString::number(r.exitCode) + ": " + r.err));
    QVERIFY2(r.out.isEmpty(), qPrintable(r.out));
    const QStringList errors = r.err.split('\n', Qt::SkipEmptyParts).filter(QRegularExpression("^error: "));
    QCOMPARE(errors.size(), 1);
    // the field as JSON counts it, then its joint in words when it is a joint's
    QVERIFY2(errors[0].contains(QRegularExpression(": " + QRegularExpression::escape(field) + "( \\(joint \\d+\\))?: ")) &&
                 errors[0].contains(words),
             qPrintable(errors[0]));
    QVERIFY2(!r.err.contains("underflow."), qPrintable(r.err));
}

}  // namespace

class TestNumberRangeCli : public QObject {
    Q_OBJECT
private slots:
    void subnormalNumbersAreRefusedNamingTheField() {
        QTemporaryDir dir;
        // A parameter given as a bare number: the reported case.
        const QString parameter = edited(dir, "planar_2r.json", "\"I2\": 0.08", "\"I2\": 1e-310");
        expectRefused(run({"eval", parameter}), "parameters.I2", "too close to zero");
        expectRefused(run({"derive", parameter}), "parameters.I2", "too close to zero");
        expectRefused(run({"simulate", parameter, "--duration", "0.1"}), "parameters.I2", "too close to zero");
        // A robot field as a bare number and as an expression, and a negative one.
        QTemporaryDir dir2, dir3, dir4;
        const QString bare = edited(dir2, "planar_2r.json", "\"zz\": \"I2\"", "\"zz\": 4e-320");
        expectRefused(run({"eval", bare}), "robot.joints[1].inertia.zz", "too close to zero");
        const QString text = edited(dir3, "planar_2r.json", "\"zz\": \"I2\"", "\"zz\": \"1e-310\"");
        expectRefused(run({"derive", text}), "robot.joints[1].inertia.zz", "too close to zero");
        const QString gravity = edited(dir4, "double_pendulum.json", "\"gravity\": [0, -9.81, 0]", "\"gravity\": [-2e-309, -9.81, 0]");
        expectRefused(run({"simulate", gravity, "--duration", "0.1"}), "effects.gravity[0]", "too close to zero");
        // The smallest normal double is a number, but no physical inertia: named as such.
        QTemporaryDir dir5;
        const QString normal = edited(dir5, "planar_2r.json", "\"xx\": 0, \"yy\": \"I2\"", "\"xx\": 2.3e-308, \"yy\": \"I2\"");
        expectRefused(run({"eval", normal}), "robot.joints[1].inertia.xx", "absurdly small inertia 2.3e-308 kg m²");
    }

    void overflowingSpringIsAnErrorNamingTheQuantity() {
        QTemporaryDir dir;
        const QString rest =
            edited(dir, "mass_spring_pair.json", "\"stiffness\": \"K1\", \"rest\": 0", "\"stiffness\": \"K1\", \"rest\": 1e300");
        // ½ K1 (q1 − 1e300)² overflows in E_pot at the initial state.
        const Run eval = run({"eval", rest});
        expectRefused(eval, "Epot", "not finite");
        QVERIFY(!eval.out.contains("null"));
        const Run simulate = run({"simulate", rest, "--duration", "0.1"});
        expectRefused(simulate, "Epot", "not finite");
        // The degree hint for a bare number beyond 2π names no absurd multiple of pi.
        QVERIFY2(!eval.err.contains("9223372036854775808"), qPrintable(eval.err));
    }

    // Found by the mutation run: a robot field typed as a decimal expression ("0.5*I2")
    // stopped `derive` with "rem: arguments must be polynomials over the rationals" (a
    // float in the polynomial reductions). Decimals are made exact like bare numbers, so
    // the derivation equals the one with the exact fraction.
    void decimalExpressionsDerive() {
        QTemporaryDir a, b;
        const Run decimal = run({"derive", edited(a, "planar_2r.json", "\"zz\": \"I2\"", "\"zz\": \"0.5*I2\""), "--format", "json"});
        const Run exact = run({"derive", edited(b, "planar_2r.json", "\"zz\": \"I2\"", "\"zz\": \"I2/2\""), "--format", "json"});
        QVERIFY2(decimal.exitCode == 0, qPrintable(decimal.err));
        QCOMPARE(exact.exitCode, 0);
        const auto b11 = [](const QString& json) {
            return QJsonDocument::fromJson(json.toUtf8()).object()["B"].toArray()[0].toArray()[0].toString();
        };
        QVERIFY(!b11(exact.out).isEmpty());
        QCOMPARE(b11(decimal.out), b11(exact.out));
    }

    // Found by the mutation run: an angle offset that is not a multiple of pi/12
    // (theta 0.3, or 1e300) stopped `derive` with GiNaC's "rem: ..." naming no field.
    // Since the structured derivation (issue 15) any offset derives; a huge one either
    // derives or is refused in one line naming the field, and eval takes both.
    void derivationTakesOtherAngleOffsets() {
        for (const char* theta : {"0.3", "1e300"}) {
            QTemporaryDir dir;
            const QString scene = edited(dir, "planar_2r.json", "\"a\": \"a1\", \"alpha\": 0, \"d\": 0, \"theta\": 0",
                                         QString("\"a\": \"a1\", \"alpha\": 0, \"d\": 0, \"theta\": %1").arg(theta));
            const Run derive = run({"derive", scene});
            if (QString(theta) == "0.3") {
                QVERIFY2(derive.exitCode == 0, qPrintable(derive.err));
            } else {
                QVERIFY2(derive.exitCode == 0 || derive.exitCode == 2, qPrintable(derive.err));
                if (derive.exitCode == 2)
                    QVERIFY2(derive.err.contains("robot.joints[0].theta") && !derive.err.contains("rem:"), qPrintable(derive.err));
            }
            QCOMPARE(run({"eval", scene}).exitCode, 0);
        }
    }

    // A finite scene evaluated at a state where a term overflows: refused naming the
    // quantity at that state, for a robot (g) and a hand-typed Lagrangian (E_pot).
    void overflowAtAGivenStateIsAnError() {
        const Run robot = run({"eval", QString(LL_EXAMPLES_DIR) + "/mass_spring_pair.json", "--q", "1e300,-1e300"});
        QCOMPARE(robot.exitCode, 2);
        QVERIFY2(robot.out.isEmpty() && robot.err.contains("Epot:") && robot.err.contains("not finite"), qPrintable(robot.err));
        const Run lagrangian =
            run({"eval", QString(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json", "--q", "1e200,0", "--qd", "0,0"});
        QCOMPARE(lagrangian.exitCode, 2);
        QVERIFY2(lagrangian.out.isEmpty() && lagrangian.err.contains("Epot:"), qPrintable(lagrangian.err));
        // In-process, the same call: every number it returns is finite, or it throws.
        const ll::Scene scene = ll::loadScene(std::string(LL_EXAMPLES_DIR) + "/mass_spring_pair.json").scene;
        const Eigen::VectorXd q = Eigen::Vector2d(0.1, -0.1), qd = Eigen::Vector2d::Zero();
        const ll::SceneEvaluation ok = ll::evaluateScene(scene, q, qd, 0.0);
        // E_pot = ½ K1 q1² + ½ K2 q2² with K1 = 10, K2 = 4 (the notes' 0.07 J).
        QVERIFY(std::abs(ok.terms.Epot - 0.07) < 1e-12);
        bool named = false;
        try {
            (void)ll::evaluateScene(scene, Eigen::Vector2d(1e160, 0), qd, 0.0);
        } catch (const ll::InputError& e) {
            named = e.diagnostics().front().field == "Epot";
        }
        QVERIFY(named);
    }
};

LL_TEST_APPLESS_MAIN(TestNumberRangeCli)

}  // namespace test_number_range_cli
#include "test_number_range_cli.moc"
