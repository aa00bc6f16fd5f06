#include "ui/document/answer_checking.hpp"

#include "core/model/diagnostics.hpp"
#include "core/present/diagnostic_text.hpp"
#include "ui/document/app_language.hpp"

namespace ll::ui {

AnswerChecking::AnswerChecking(QObject* parent) : QObject(parent) { pool_.setMaxThreadCount(1); }

AnswerChecking::~AnswerChecking() {
    keys_.cancel();
    pool_.waitForDone();
}

void AnswerChecking::setScene(const Scene& scene) {
    const int number = keys_.request();
    key_.reset();
    pool_.start([self = this, scene = std::make_shared<const Scene>(scene), number, language = windowLanguage()] {
        std::shared_ptr<const AnswerKey> key;
        std::map<int, std::vector<std::string>> practice;
        QString why;
        try {
            key = AnswerKey::build(*scene);
            for (int step = 0; step <= 8; ++step) practice[step] = key->practiceEntries(step);
        } catch (const InputError& e) {
            for (const Diagnostic& d : e.diagnostics()) why += QString::fromStdString(present::diagnosticBody(d, language) + "\n");
        } catch (const std::exception& e) {
            why = QString::fromStdString(e.what());
        }
        self->keys_.deliver(number, [self, number, key, practice, why] {  // dropped when a newer scene's key is asked for
            self->keyNumber_ = number;
            self->key_ = key;
            self->practice_ = practice;
            if (!key) {
                self->waiting_.clear();
                emit self->keyFailed(why.trimmed());
                return;
            }
            const std::map<QString, Waiting> waiting = std::move(self->waiting_);
            self->waiting_.clear();
            emit self->keyReady();
            for (const auto& [entry, w] : waiting) self->check(entry, w.answer, w.reveal);
        });
    });
}

std::vector<std::string> AnswerChecking::practiceEntries(int step) const {
    const auto found = practice_.find(step);
    return key_ && found != practice_.end() ? found->second : std::vector<std::string>{};
}

void AnswerChecking::clear() {
    keys_.request();  // a key being built is dropped when it arrives
    key_.reset();
    waiting_.clear();
}

void AnswerChecking::check(const QString& entry, const QString& answer, bool reveal) {
    const int number = ++checks_;
    newestCheck_[entry] = number;
    if (!key_) {
        if (building()) waiting_[entry] = {answer, reveal};
        return;
    }
    start(entry, answer, reveal, number);
}

void AnswerChecking::start(const QString& entry, const QString& answer, bool reveal, int number) {
    pool_.start([self = this, key = key_, request = AnswerRequest{entry.toStdString(), answer.toStdString(), reveal}, entry, answer, number,
                 keyNumber = keyNumber_] {
        auto result = std::make_shared<AnswerCheck>(key->check(request));
        if (request.reveal && result->rightAnswer.empty()) result->rightAnswer = key->rightAnswer(request.entry);  // nothing typed yet
        self->checked_.post([self, entry, answer, number, keyNumber, result] {
            // void when the same entry was checked again since, or the scene changed
            const auto newest = self->newestCheck_.find(entry);
            if (newest == self->newestCheck_.end() || newest->second != number || keyNumber != self->keyNumber_ || !self->key_) return;
            emit self->checked(entry, answer, *result);
        });
    });
}

}  // namespace ll::ui
