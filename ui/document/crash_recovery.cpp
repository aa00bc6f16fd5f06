#include "ui/document/crash_recovery.hpp"

#include <QCoreApplication>
#include <QCryptographicHash>
#include <QSet>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>
#include <cerrno>
#include <csignal>

#include <unistd.h>

#include "core/io/atomic_file.hpp"
#include "core/model/diagnostics.hpp"
#include "core/present/message_text.hpp"
#include "ui/document/app_language.hpp"

namespace ll::ui {
namespace {

QString sha256(const QByteArray& bytes) { return QCryptographicHash::hash(bytes, QCryptographicHash::Sha256).toHex(); }

// A process that still runs (or runs as another user) keeps its copy: it is its window's.
bool running(qint64 pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// The copies of this process's windows that are still open (GUI thread only).
QSet<QString>& liveCopies() {
    static QSet<QString> live;
    return live;
}

QString shown(const SceneJson* v) {
    if (!v) return QObject::tr("(none)");
    const std::string text = v->dump();
    return QString::fromStdString(text.size() > 40 ? text.substr(0, 37) + "..." : text);
}

void collectChanges(const SceneJson* before, const SceneJson* after, const std::string& path, QStringList& out) {
    if (before && after && *before == *after) return;
    const bool objects = before && after && before->is_object() && after->is_object();
    const bool arrays = before && after && before->is_array() && after->is_array();
    if (objects) {
        for (auto it = before->begin(); it != before->end(); ++it) {
            const std::string child = path.empty() ? it.key() : path + "." + it.key();
            collectChanges(&it.value(), after->contains(it.key()) ? &(*after)[it.key()] : nullptr, child, out);
        }
        for (auto it = after->begin(); it != after->end(); ++it)
            if (!before->contains(it.key())) collectChanges(nullptr, &it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
        return;
    }
    if (arrays) {
        const std::size_t n = std::max(before->size(), after->size());
        for (std::size_t i = 0; i < n; ++i)
            collectChanges(i < before->size() ? &(*before)[i] : nullptr, i < after->size() ? &(*after)[i] : nullptr,
                           path + "[" + std::to_string(i) + "]", out);
        return;
    }
    const Diagnostic field{Severity::Warning, path, {}};
    out << QString::fromStdString(present::messageText(field.place(), windowLanguage())) + ": " + shown(before) + QString::fromUtf8(" → ") +
               shown(after);
}

}  // namespace

CrashRecovery::CrashRecovery(QString directory) : directory_(std::move(directory)) {}

CrashRecovery::~CrashRecovery() { liveCopies().remove(own_); }

QString CrashRecovery::defaultDirectory() {
    const QByteArray env = qgetenv("LAGRANGELAB_RECOVERY_DIR");
    if (!env.isEmpty()) return QString::fromLocal8Bit(env);
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + "/lagrangelab";
}

void CrashRecovery::write(const QString& original, const QString& originalHash, const SceneJson& scene) {
    QDir().mkpath(directory_);
    // Named after the scene and this process: another window (on the same scene too) has its own.
    const QString key = original.isEmpty() ? QString("new") : sha256(QFileInfo(original).absoluteFilePath().toUtf8()).left(16);
    const QString file = directory_ + "/" + key + "-" + QString::number(QCoreApplication::applicationPid()) + ".json";
    if (!own_.isEmpty() && own_ != file) {  // saved under another name since
        QFile::remove(own_);
        liveCopies().remove(own_);
    }
    const SceneJson copy = {{"format", "lagrangelab-recovery/1"},
                            {"recovery_of", original.isEmpty() ? std::string() : QFileInfo(original).absoluteFilePath().toStdString()},
                            {"original_sha256", originalHash.toStdString()},
                            {"pid", QCoreApplication::applicationPid()},
                            {"written", QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString()},
                            {"scene", scene}};
    saveFileAtomically(file.toStdString(), copy.dump(1), Backup::None);
    own_ = file;
    liveCopies().insert(own_);
}

void CrashRecovery::discard() {
    if (!own_.isEmpty()) QFile::remove(own_);
    liveCopies().remove(own_);
    own_.clear();
}

std::vector<RecoveryCopy> CrashRecovery::leftBehind(QStringList* damaged) const {
    std::vector<RecoveryCopy> copies;
    for (const QFileInfo& info : QDir(directory_).entryInfoList({"*.json"}, QDir::Files)) {
        if (info.absoluteFilePath() == own_) continue;
        QFile f(info.absoluteFilePath());
        SceneJson copy;
        bool whole = f.open(QIODevice::ReadOnly);
        if (whole) {
            try {
                copy = SceneJson::parse(f.readAll().toStdString());
                whole = copy.is_object() && copy.value("format", "") == "lagrangelab-recovery/1" && copy.contains("scene") &&
                        copy["scene"].is_object() && copy.value("pid", 0LL) > 0;
            } catch (const std::exception&) {
                whole = false;
            }
        }
        if (!whole) {  // cut short or empty: set aside, never half-loaded
            f.close();
            const QString aside = info.absoluteFilePath() + ".damaged";
            QFile::remove(aside);
            QFile::rename(info.absoluteFilePath(), aside);
            if (damaged) *damaged << QObject::tr("A recovery copy that was cut short was set aside: %1").arg(aside);
            continue;
        }
        const qint64 pid = copy.value("pid", 0LL);
        if (pid == QCoreApplication::applicationPid() ? liveCopies().contains(info.absoluteFilePath()) : running(pid))
            continue;  // another window's, still open
        RecoveryCopy r;
        r.file = info.absoluteFilePath();
        r.original = QString::fromStdString(copy.value("recovery_of", std::string()));
        r.originalHash = QString::fromStdString(copy.value("original_sha256", std::string()));
        r.scene = copy["scene"];
        r.written = QDateTime::fromString(QString::fromStdString(copy.value("written", std::string())), Qt::ISODate);
        copies.push_back(std::move(r));
    }
    std::sort(copies.begin(), copies.end(), [](const RecoveryCopy& a, const RecoveryCopy& b) { return a.written > b.written; });
    return copies;
}

bool CrashRecovery::originalChanged(const RecoveryCopy& copy) {
    if (copy.original.isEmpty()) return false;
    return hashOfFile(copy.original) != copy.originalHash;
}

QStringList CrashRecovery::changes(const SceneJson& before, const SceneJson& after, int most) {
    QStringList all;
    collectChanges(&before, &after, "", all);
    if (all.size() <= most) return all;
    QStringList shownLines = all.mid(0, most);
    shownLines << QObject::tr("… and %1 more").arg(all.size() - most);
    return shownLines;
}

QString CrashRecovery::hashOfFile(const QString& path) {
    QFile f(path);
    if (path.isEmpty() || !f.open(QIODevice::ReadOnly)) return {};
    return sha256(f.readAll());
}

void CrashRecovery::remove(const RecoveryCopy& copy) { QFile::remove(copy.file); }

}  // namespace ll::ui
