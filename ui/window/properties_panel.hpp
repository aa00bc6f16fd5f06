#pragma once
// The "Properties" tab: the properties every Euler–Lagrange model has, checked along the
// run (core/simulation/model_properties, what `lagrangelab check` prints): each with a
// pass or fail badge, its worst value with its unit and tolerance, where that was (t
// and q; a click there moves the playback to it), and one sentence a student reads.
#include <memory>

#include <QWidget>

#include "core/simulation/model_properties.hpp"

class QLabel;

namespace ll::ui {

class PropertiesPanel : public QWidget {
    Q_OBJECT
public:
    explicit PropertiesPanel(QWidget* parent = nullptr);

    // Null: the run is still being checked.
    void setProperties(std::shared_ptr<const ModelProperties> properties);
    const ModelProperties* properties() const { return properties_.get(); }
    // What the panel says (tests read it).
    QString text() const;

signals:
    void timePicked(double t);

private:
    std::shared_ptr<const ModelProperties> properties_;
    QLabel* summary_;
    QLabel* body_;
};

}  // namespace ll::ui
