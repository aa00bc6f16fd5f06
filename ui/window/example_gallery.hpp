#pragma once
// The example gallery (File → Examples → Gallery…): every example scene as a picture
// of it at its initial state (resources/thumbnails, made by `scripts/lab thumbnails`)
// with its name; double-click or Open opens it.
#include <QDialog>

class QListWidget;

namespace ll::ui {

class ExampleGallery : public QDialog {
    Q_OBJECT
public:
    explicit ExampleGallery(QWidget* parent = nullptr);
    // The examples shown (resource paths, :/examples/NAME.json) and whether each has its picture.
    QStringList examples() const;
    bool hasPicture(int row) const;
    QListWidget& list() { return *list_; }

signals:
    void chosen(const QString& resourcePath);

private:
    QListWidget* list_;
};

}  // namespace ll::ui
