#include "ui/window/teach_panel.hpp"

#include "ui/window/relabel.hpp"

#include <cmath>
#include <numbers>

#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QScrollArea>
#include <QSlider>
#include <QVBoxLayout>

#include "core/pipeline/pose_results.hpp"

namespace ll::ui {

namespace {
// Slider units: 0.1° for revolute joints, 1 mm for prismatic ones.
double unitOf(JointType type) { return type == JointType::Revolute ? 0.1 * std::numbers::pi / 180 : 1e-3; }
}  // namespace

struct TeachPanel::Model {
    Scene scene;
    explicit Model(const Scene& s) : scene(s) {}
};

TeachPanel::TeachPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    auto* left = new QWidget(this);
    sliderBox_ = new QVBoxLayout(left);
    auto* right = new QWidget(this);
    auto* rightBox = new QVBoxLayout(right);
    rightBox->setContentsMargins(0, 0, 0, 0);
    auto* scroll = new QScrollArea(right);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    matrices_ = new PoseMatrices(scroll);
    scroll->setWidget(matrices_);
    message_ = new QLabel(right);
    (*new Relabel(this))([this] { message_->setText(tr("Teach mode poses robots; this scene is a hand-typed Lagrangian.")); });
    message_->setWordWrap(true);
    message_->hide();
    rightBox->addWidget(message_);
    rightBox->addWidget(scroll, 1);
    layout->addWidget(left, 1);
    layout->addWidget(right, 2);
    connect(matrices_, &PoseMatrices::entryPicked, this, &TeachPanel::entryPicked);
}

TeachPanel::~TeachPanel() = default;

void TeachPanel::setScene(const Scene& scene) {
    if (scene.lagrangian || scene.robot.dof() == 0) {
        model_.reset();
        for (QSlider* s : sliders_) s->parentWidget()->deleteLater();
        sliders_.clear(), labels_.clear();
        matrices_->setStep({});
        matrices_->hide();
        message_->show();
        return;
    }
    message_->hide();
    matrices_->show();
    const int n = scene.robot.dof();
    const bool keep = model_ && static_cast<int>(sliders_.size()) == n;
    model_ = std::make_unique<Model>(scene);
    if (!keep) {
        for (QSlider* s : sliders_) s->parentWidget()->deleteLater();
        sliders_.clear(), labels_.clear();
        q_ = scene.initial.q.size() == n ? scene.initial.q : Eigen::VectorXd::Zero(n);
        for (int i = 0; i < n; ++i) {
            auto* row = new QWidget(this);
            auto* h = new QHBoxLayout(row);
            h->setContentsMargins(0, 0, 0, 0);
            auto* name = new QLabel(QString("q%1").arg(i + 1), row);
            auto* slider = new QSlider(Qt::Horizontal, row);
            const JointType type = scene.robot.joints[static_cast<std::size_t>(i)].dh.type;
            if (type == JointType::Revolute) slider->setRange(-1800, 1800);
            else slider->setRange(-1000, 1000);
            auto* value = new QLabel(row);
            value->setMinimumWidth(90);
            h->addWidget(name);
            h->addWidget(slider, 1);
            h->addWidget(value);
            sliderBox_->addWidget(row);
            sliders_.push_back(slider);
            labels_.push_back(value);
            connect(slider, &QSlider::valueChanged, this, &TeachPanel::slidersMoved);
        }
        sliderBox_->addStretch(1);
    }
    setPose(q_);
}

void TeachPanel::setPose(const Eigen::VectorXd& q) {
    if (!model_ || q.size() != static_cast<int>(sliders_.size())) return;
    for (std::size_t i = 0; i < sliders_.size(); ++i) {
        const QSignalBlocker block(sliders_[i]);
        sliders_[i]->setValue(static_cast<int>(std::lround(q[static_cast<int>(i)] / unitOf(model_->scene.robot.joints[i].dh.type))));
    }
    q_ = q;
    evaluate();
    emit poseChanged(q_);
}

void TeachPanel::slidersMoved() {
    if (!model_) return;
    for (std::size_t i = 0; i < sliders_.size(); ++i)
        q_[static_cast<int>(i)] = sliders_[i]->value() * unitOf(model_->scene.robot.joints[i].dh.type);
    evaluate();
    emit poseChanged(q_);
}

void TeachPanel::evaluate() {
    if (!model_) return;
    Model& m = *model_;
    matrices_->setStep(teachMatrices(m.scene, q_));
    for (std::size_t i = 0; i < labels_.size(); ++i) {
        const double v = q_[static_cast<int>(i)];
        labels_[i]->setText(m.scene.robot.joints[i].dh.type == JointType::Revolute ? tr("%1°").arg(v * 180 / std::numbers::pi, 0, 'f', 1)
                                                                                   : tr("%1 m").arg(v, 0, 'f', 3));
    }
}

QString TeachPanel::readout() const {
    // "E_pot(q) = …": the label with its argument, as the sliders' pose is the q.
    return matrices_->text().replace(QString::fromUtf8("E_pot ="), QString::fromUtf8("E_pot(q) ="));
}

}  // namespace ll::ui
