#pragma once
// Matrices at one pose, typeset (ui/math_typesetter) with their units: the teach panel's
// E_pot, g(q) and B(q) (core/pipeline/pose_results' teachMatrices). A click on an entry
// reports its quantity and indices, so picking b₁₂ here picks it everywhere; the picked
// entry is tinted. Each item is one line, scaled down to the widget's width if needed.
#include <memory>
#include <optional>
#include <vector>

#include <QColor>
#include <QWidget>

#include "core/present/display_document.hpp"
#include "ui/paint/math_typesetter.hpp"

namespace ll::ui {

class PoseMatrices : public QWidget {
    Q_OBJECT
public:
    explicit PoseMatrices(QWidget* parent = nullptr);

    void setStep(present::DisplayStep step);
    const present::DisplayStep& step() const { return step_; }
    // Tints the entry (row, col) of the item of `quantity` (row < 0: the item); none: clear.
    void setMark(std::optional<present::Quantity> quantity, int row = -1, int col = -1);
    // Each item as text prints it: "E_pot(q) = 5.886 J", "B(q) = …".
    QString text() const;
    QSize sizeHint() const override;

signals:
    void entryPicked(ll::present::Quantity quantity, int row, int col);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    struct Line {
        MathBox box;
        QPointF origin;  // where it was painted last
        double scale = 1;
    };
    void layoutLines();
    present::DisplayStep step_;
    std::vector<Line> lines_;
    std::optional<present::Quantity> markQuantity_;
    int markRow_ = -1, markCol_ = -1;
};

}  // namespace ll::ui
