#pragma once
// Running a program from a test: exit code, stdout and stderr.
#include <QFile>
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
                             const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment(), int timeoutMs = 600000) {
    QProcess p;
    p.setProcessEnvironment(env);
    if (!workingDirectory.isEmpty()) p.setWorkingDirectory(workingDirectory);
    p.start(program, args);
    if (!p.waitForStarted(60000)) return {-1, {}, p.errorString().toUtf8()};
    const bool finished = p.waitForFinished(timeoutMs);
    const bool normal = finished && p.exitStatus() == QProcess::NormalExit;
    return {normal ? p.exitCode() : -1, p.readAllStandardOutput(), p.readAllStandardError()};
}

// The environment of a fresh Debian (only the C.UTF-8 locale, no LANGUAGE) with `extra`
// ("NAME=value") added: no language of the test's own environment leaks in.
inline QProcessEnvironment freshLocaleEnvironment(const QStringList& extra = {}) {
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    for (const char* v : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"}) e.remove(v);
    e.insert("LANG", "C.UTF-8");
    e.insert("LC_ALL", "C.UTF-8");
    for (const QString& kv : extra) e.insert(kv.section('=', 0, 0), kv.section('=', 1));
    return e;
}

// `program` run as from a shell without X (no DISPLAY, no WAYLAND_DISPLAY), in a fresh
// locale: a command that must work headless, worded in English.
inline ProcessRun runHeadless(const QString& program, const QStringList& args) {
    QProcessEnvironment env = freshLocaleEnvironment();
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY");
    return runProcess(program, args, {}, env);
}

// A file's bytes; empty when it cannot be read.
inline QByteArray fileBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace ll::test
