#pragma once
// Running a program from a test: exit code, stdout and stderr.
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace ll::test {

struct ProcessRun {
    int exitCode;  // -1: it could not be started or did not finish
    QByteArray out, err;
};

inline ProcessRun runProcess(const QString& program, const QStringList& args, const QString& workingDirectory = {},
                             const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment(),
                             int timeoutMs = 600000) {
    QProcess p;
    p.setProcessEnvironment(env);
    if (!workingDirectory.isEmpty()) p.setWorkingDirectory(workingDirectory);
    p.start(program, args);
    if (!p.waitForStarted(60000)) return {-1, {}, p.errorString().toUtf8()};
    const bool finished = p.waitForFinished(timeoutMs);
    const bool normal = finished && p.exitStatus() == QProcess::NormalExit;
    return {normal ? p.exitCode() : -1, p.readAllStandardOutput(), p.readAllStandardError()};
}

}  // namespace ll::test
