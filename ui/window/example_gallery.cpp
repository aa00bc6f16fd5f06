#include "ui/window/example_gallery.hpp"

#include "ui/window/relabel.hpp"

#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace ll::ui {
namespace {
constexpr int kPathRole = Qt::UserRole, kPictureRole = Qt::UserRole + 1;
}

ExampleGallery::ExampleGallery(QWidget* parent) : QDialog(parent) {
    (*new Relabel(this))([this] { setWindowTitle(tr("Example gallery")); });
    auto* layout = new QVBoxLayout(this);
    list_ = new QListWidget(this);
    list_->setViewMode(QListView::IconMode);
    list_->setIconSize(QSize(240, 150));
    list_->setGridSize(QSize(270, 210));
    list_->setResizeMode(QListView::Adjust);
    list_->setMovement(QListView::Static);
    list_->setWordWrap(true);
    for (const QString& file : QDir(":/examples").entryList({"*.json"}, QDir::Files, QDir::Name)) {
        const QString path = ":/examples/" + file;
        QFile f(path);
        QString name = QFileInfo(file).completeBaseName();
        if (f.open(QIODevice::ReadOnly))
            if (const QString typed = QJsonDocument::fromJson(f.readAll()).object().value("name").toString(); !typed.isEmpty())
                name = typed;
        const QString picture = ":/thumbnails/" + QFileInfo(file).completeBaseName() + ".png";
        const bool has = QFile::exists(picture);
        auto* item = new QListWidgetItem(has ? QIcon(picture) : QIcon(), name, list_);
        item->setToolTip(file);
        item->setData(kPathRole, path);
        item->setData(kPictureRole, has);
    }
    layout->addWidget(list_, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel, this);
    layout->addWidget(buttons);
    const auto open = [this] {
        if (QListWidgetItem* item = list_->currentItem()) {
            emit chosen(item->data(kPathRole).toString());
            accept();
        }
    };
    connect(buttons, &QDialogButtonBox::accepted, this, open);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(list_, &QListWidget::itemActivated, this, open);
    resize(900, 640);
}

QStringList ExampleGallery::examples() const {
    QStringList paths;
    for (int i = 0; i < list_->count(); ++i) paths << list_->item(i)->data(kPathRole).toString();
    return paths;
}

bool ExampleGallery::hasPicture(int row) const { return row >= 0 && row < list_->count() && list_->item(row)->data(kPictureRole).toBool(); }

}  // namespace ll::ui
