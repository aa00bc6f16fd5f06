#pragma once
// The window's answer key and its checks, off the GUI thread (core/pipeline/answer_check):
// setScene builds the key of a scene on one worker (a newer scene's key wins; the key is
// immutable and shared), check() judges one answer there and brings the plain result back
// through a queued call. A newer check of the same entry makes an older one's result void,
// and so does a newer key. Checks asked before the key is ready wait for it.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <QObject>
#include <QString>

#include "core/model/scene.hpp"
#include "core/pipeline/answer_check.hpp"
#include "ui/document/handover.hpp"
#include "ui/document/newest_wins.hpp"
#include "ui/document/work_pool.hpp"

namespace ll::ui {

class AnswerChecking : public QObject {
    Q_OBJECT
public:
    explicit AnswerChecking(QObject* parent = nullptr);
    ~AnswerChecking() override;

    // Builds the key of `scene` (copied); checks asked from now on wait for it.
    void setScene(const Scene& scene);
    // Forgets the key (exercise mode off): nothing is built until the next setScene.
    void clear();
    // The key of the newest scene; null while it is being built (or could not be).
    const std::shared_ptr<const AnswerKey>& key() const { return key_; }
    bool building() const { return keys_.newest() > keyNumber_; }
    // The key's AnswerKey::practiceEntries(step), made on the worker with the key (it expands
    // entries under the GiNaC lock, which the GUI thread never waits for); empty without a key.
    std::vector<std::string> practiceEntries(int step) const;

    // Judges `answer` for `entry`; `checked` follows (at once when there is no key to build).
    void check(const QString& entry, const QString& answer, bool reveal = false);
    // Blocks until the worker is idle (tests, shutdown).
    void wait() { pool_.waitForDone(); }

signals:
    void keyReady();
    // The key could not be built (why, in the window's language).
    void keyFailed(const QString& why);
    void checked(const QString& entry, const QString& answer, const ll::AnswerCheck& result);

private:
    void start(const QString& entry, const QString& answer, bool reveal, int number);

    WorkPool pool_;
    NewestWins keys_;
    Handover checked_;  // each check's result back to this thread
    int keyNumber_ = 0;  // the request the key answers
    std::shared_ptr<const AnswerKey> key_;
    std::map<int, std::vector<std::string>> practice_;  // of key_, by step
    std::map<QString, int> newestCheck_;                // per entry: the newest check's number
    struct Waiting {
        QString answer;
        bool reveal = false;
    };
    std::map<QString, Waiting> waiting_;  // checks asked while the key is built
    int checks_ = 0;
};

}  // namespace ll::ui
