#include "ui/document/scene_document.hpp"

#include <algorithm>

#include <cmath>
#include <fstream>
#include <sstream>

#include <QFile>
#include <QUndoCommand>

#include "core/io/atomic_file.hpp"
#include "core/io/scene_file.hpp"
#include "core/present/diagnostic_text.hpp"
#include "ui/document/app_language.hpp"
#include "core/pipeline/scene_check.hpp"

namespace ll::ui {

// One edit: the whole JSON before and after (a scene is a few kilobytes, so a snapshot
// is cheaper to get right than an inverse per kind of edit).
class SceneEditCommand : public QUndoCommand {
public:
    SceneEditCommand(SceneDocument& doc, SceneJson before, SceneJson after, const QString& text, int gesture)
        : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)), gesture_(gesture) {}
    void undo() override { doc_.setJson(before_); }
    void redo() override { doc_.setJson(after_); }
    // Edits of one gesture merge (QUndoStack asks when the ids agree): this one then ends
    // where the newer one did.
    int id() const override { return gesture_ != 0 ? 1 : -1; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* newer = static_cast<const SceneEditCommand*>(other);
        if (newer->gesture_ != gesture_) return false;
        after_ = newer->after_;
        setText(newer->text());
        return true;
    }

private:
    SceneDocument& doc_;
    SceneJson before_, after_;
    int gesture_ = 0;
};

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) { checker_.setMaxThreadCount(1); }

SceneDocument::~SceneDocument() { checker_.waitForDone(); }

namespace {

// Whole-text problems (JSON syntax, unknown keys, bad values) as the loader reports them,
// or the errors of checkScene, each "field: message".
std::vector<Diagnostic> diagnose(const std::string& text, Scene* scene) {
    try {
        Scene parsed = parseScene(text);
        std::vector<Diagnostic> found = checkScene(parsed);
        if (scene) *scene = std::move(parsed);
        return found;
    } catch (const InputError& e) {
        return e.diagnostics();
    } catch (const std::exception& e) {
        return {Diagnostic{Severity::Error, "scene", literal(e.what())}};
    }
}

}  // namespace

bool SceneDocument::loadText(const std::string& text, const QString& path, QStringList* errors) {
    Scene scene;
    std::vector<Diagnostic> found = diagnose(text, &scene);
    return adopt(text, path, std::move(found), scene, errors);
}

bool SceneDocument::adopt(const std::string& text, const QString& path, std::vector<Diagnostic> found, Scene& scene, QStringList* errors) {
    const QString prefix = path.isEmpty() ? QString() : path + ": ";
    if (ll::hasErrors(found)) {
        if (errors)
            for (const Diagnostic& d : found)
                if (d.severity == Severity::Error) *errors << prefix + QString::fromStdString(present::diagnosticBody(d, windowLanguage()));
        return false;
    }
    SceneJson parsed;
    try {
        parsed = SceneJson::parse(text);
    } catch (const std::exception& e) {
        if (errors) *errors << prefix + QString::fromUtf8(e.what());
        return false;
    }
    undo_.clear();
    path_ = path;
    json_ = parsed;
    validated_ = checks_.request();
    emit changed();
    accept(std::move(found), &scene);
    undo_.setClean();
    return true;
}

namespace {

// The file's bytes, or false with the reason in `errors`.
bool readScene(const QString& path, std::string& text, QStringList* errors) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (errors) *errors << path + ": " + file.errorString();
        return false;
    }
    text = file.readAll().toStdString();
    return true;
}

QString shownPath(const QString& path) { return path.startsWith(":/") ? QString() : path; }

}  // namespace

bool SceneDocument::loadFile(const QString& path, QStringList* errors) {
    std::string text;
    return readScene(path, text, errors) && loadText(text, shownPath(path), errors);
}

void SceneDocument::loadFileInBackground(const QString& path, std::function<void(bool, const QStringList&)> done) {
    std::string text;
    QStringList errors;
    if (!readScene(path, text, &errors)) {
        done(false, errors);
        return;
    }
    checkInBackground(std::move(text), shownPath(path), true, std::move(done));
}

void SceneDocument::loadUnsavedInBackground(std::string text, const QString& name, std::function<void(bool, const QStringList&)> done) {
    checkInBackground(std::move(text), name, false, std::move(done));
}

void SceneDocument::checkInBackground(std::string scene, const QString& name, bool fromFile,
                                      std::function<void(bool, const QStringList&)> done) {
    auto text = std::make_shared<std::string>(std::move(scene));
    checker_.start([self = this, text, name, fromFile, done = std::move(done)] {
        auto scene = std::make_shared<Scene>();
        auto found = std::make_shared<std::vector<Diagnostic>>(diagnose(*text, scene.get()));
        self->loaded_.post([self, text, name, fromFile, done, scene, found] {
            QStringList lines;
            const bool ok = self->adopt(*text, fromFile ? name : QString(), std::move(*found), *scene, &lines);
            if (ok && !fromFile) self->undo_.resetClean();  // nothing on disk holds it yet
            if (!fromFile)
                for (QString& line : lines) line = name + ": " + line;
            done(ok, lines);
        });
    });
}

void SceneDocument::saveFile(const QString& path) {
    saveFileAtomically(path.toStdString(), text() + "\n", Backup::Keep);
    path_ = path;
    undo_.setClean();
}

SceneJson SceneDocument::value(const std::string& pointer) const {
    const SceneJson::json_pointer p(pointer);
    return json_.contains(p) ? json_.at(p) : SceneJson();
}

void SceneDocument::setValue(const std::string& pointer, const SceneJson& v, const QString& description, int gesture) {
    SceneJson after = json_;
    const SceneJson::json_pointer p(pointer);
    if (v.is_null()) {
        if (!after.contains(p)) return;
        after.at(p.parent_pointer()).erase(p.back());
    } else {
        if (after.contains(p) && after.at(p) == v) return;
        after[p] = v;
    }
    const SceneJson before = json_;
    replace(after, description, gesture);
    lastEdited_ = fieldOfPointer(pointer);
    stillUsed_ = parametersStillUsed(before, json_, pointer);
}

void SceneDocument::replace(const SceneJson& after, const QString& description, int gesture) {
    if (after == json_) return;
    undo_.push(new SceneEditCommand(*this, json_, after, description, gesture));
}

QString SceneDocument::errorAt(const std::string& field) const {
    QStringList found;
    for (const Diagnostic& d : diagnostics_)
        if (d.field == field) found << QString::fromStdString(present::diagnosticText(d, windowLanguage(), present::Place::Omitted));
    return found.join('\n');
}

namespace {

// The "exercise" section when it is well formed (entries: names; answers: texts by entry);
// nothing otherwise (the scene check then says what is wrong with it).
std::optional<Exercise> exerciseIn(const SceneJson& json) {
    Exercise e;
    const auto section = json.find("exercise");
    if (section == json.end()) return e;
    if (!section->is_object()) return std::nullopt;
    for (const auto& [key, value] : section->items()) {
        if (key == "entries" && value.is_array()) {
            for (const SceneJson& entry : value)
                if (entry.is_string()) e.entries.push_back(entry.get<std::string>());
                else return std::nullopt;
        } else if (key == "answers" && value.is_object()) {
            for (const auto& [entry, answer] : value.items())
                if (answer.is_string()) e.answers.emplace_back(entry, answer.get<std::string>());
                else return std::nullopt;
        } else {
            return std::nullopt;
        }
    }
    return e;
}

bool sameModel(SceneJson a, SceneJson b) {
    a.erase("exercise");
    b.erase("exercise");
    return a == b;
}

}  // namespace

Exercise SceneDocument::exercise() const { return exerciseIn(json_).value_or(Exercise{}); }

void SceneDocument::setJson(const SceneJson& json) {
    // Only the student's answers or the entries asked changed, and the model they are about
    // is checked and valid: nothing to check, simulate or derive again.
    if (!validating() && !hasErrors() && validRevision_ > 0 && sameModel(json_, json))
        if (std::optional<Exercise> exercise = exerciseIn(json)) {
            json_ = json;
            lastEdited_.clear();
            stillUsed_.clear();
            validScene_.exercise = std::move(*exercise);
            emit exerciseChanged();
            return;
        }
    json_ = json;
    lastEdited_.clear();  // setValue names its field after this
    stillUsed_.clear();
    checks_.request();
    emit changed();
    validate();
}

void SceneDocument::validate() {
    const int revision = checks_.newest();
    checker_.start([self = this, text = json_.dump(), revision] {
        auto scene = std::make_shared<Scene>();
        auto found = std::make_shared<std::vector<Diagnostic>>(diagnose(text, scene.get()));
        self->checks_.deliver(revision, [self, revision, scene, found] {  // dropped when a newer edit is being checked
            self->validated_ = revision;
            self->accept(std::move(*found), scene.get());
        });
    });
}

void SceneDocument::accept(std::vector<Diagnostic> diagnostics, Scene* scene) {
    diagnostics_ = std::move(diagnostics);
    const bool valid = !ll::hasErrors(diagnostics_);
    if (valid) {
        validScene_ = std::move(*scene);
        ++validRevision_;
    }
    emit validated();
    if (valid) emit validSceneChanged();
}

QString SceneDocument::display(const SceneJson& v) {
    if (v.is_string()) return QString::fromStdString(v.get<std::string>());
    if (v.is_number_integer()) return QString::number(v.get<long long>());
    if (v.is_number()) return QString::number(v.get<double>(), 'g', 15).replace("e+", "e");
    if (v.is_null()) return {};
    return QString::fromStdString(v.dump());
}

SceneJson SceneDocument::parseCell(const QString& text) {
    const QString t = text.trimmed();
    bool ok = false;
    const long long i = t.toLongLong(&ok);
    if (ok) return i;
    const double d = t.toDouble(&ok);
    if (ok && std::isfinite(d)) return d;
    return t.toStdString();
}

}  // namespace ll::ui
