#include "ui/window/ghost_run.hpp"

#include <QActionGroup>
#include <QMainWindow>
#include <QMenu>
#include <QStringList>

#include "core/simulation/integrators.hpp"
#include "ui/window/relabel.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/trajectory_chart.hpp"

namespace ll::ui {

GhostRun::GhostRun(const SceneDocument& document, const WindowParts& parts) : doc_(document), parts_(parts) {
    connect(&live_, &LiveSimulation::finished, this, &GhostRun::show);
}

void GhostRun::addTo(QMenu* simulation) {
    QMenu* menu = simulation->addMenu(QString());
    Relabel& relabel = *new Relabel(parts_.window);
    relabel([menu] { menu->setTitle(tr("Ghost run")); });
    auto* group = new QActionGroup(menu);
    QStringList names{QString()};
    for (const IntegratorInfo& info : integratorCatalogue())
        if (!info.adaptive) names << QString::fromStdString(info.name);
    names << "dopri5 1e-3";
    for (const QString& name : names) {
        QAction* a = menu->addAction(name, this, [this, name] { setIntegrator(name); });
        if (name.isEmpty()) relabel([a] { a->setText(tr("none")); });
        a->setCheckable(true);
        a->setChecked(name.isEmpty());
        group->addAction(a);
    }
}

void GhostRun::setIntegrator(const QString& integrator) {
    const Scene& scene = doc_.validScene();
    integrator_ = integrator;
    result_.reset();
    sampler_.reset();
    reference_.reset();
    parts_.view->setGhost(nullptr);
    parts_.energy->setGhost(nullptr, {});
    if (integrator.isEmpty()) return;
    SimulationSettings settings = scene.simulation;
    const QStringList words = integrator.split(' ');
    settings.integrator = words[0].toStdString();
    if (words.size() > 1) settings.absTol = settings.relTol = words[1].toDouble();
    if (const IntegratorInfo* info = findIntegrator(settings.integrator); info && !info->adaptive) settings.dt = 0.01;
    live_.setSettingsOverride(settings);
    live_.requestNow(scene);
}

void GhostRun::sceneChanged(const Scene& scene) {
    if (!integrator_.isEmpty()) live_.request(scene);
}

void GhostRun::show(std::shared_ptr<const LiveResult> result) {
    if (integrator_.isEmpty() || !result->visual || result->simulation.trajectory.size() == 0) return;
    result_ = result;
    sampler_ = std::make_unique<TrajectorySampler>(result_->simulation.trajectory);
    parts_.view->setGhost(result_->visual);
    parts_.energy->setGhost(&result_->simulation.trajectory, integrator_);
    emit shown();
}

void GhostRun::runShown(const LiveResult& shown) {
    if (result_ && result_->simulation.trajectory.size() > 0) parts_.energy->setGhost(&result_->simulation.trajectory, integrator_);
    if (!integrator_.isEmpty()) return;
    const Scene& scene = *shown.scene;
    const bool controlled = !scene.lagrangian && scene.effects.control && shown.visual;
    if (!controlled && !reference_) return;
    reference_.reset();
    referenceVisual_.reset();
    if (controlled) {
        reference_ = scene.effects.control->reference;
        referenceVisual_ = std::make_shared<VisualScene>(scene);
        qRef_ = qdRef_ = qddRef_ = Eigen::VectorXd::Zero(scene.dof());
    }
    parts_.view->setGhost(referenceVisual_);
}

void GhostRun::showAt(double t) {
    if (reference_) {
        reference_->evaluate(t, qRef_, qdRef_, qddRef_);
        parts_.view->setGhostPose(qRef_, t);
        return;
    }
    if (!sampler_) return;
    Eigen::VectorXd q(sampler_->dof()), qd(sampler_->dof());
    sampler_->sample(t, q, qd);
    parts_.view->setGhostPose(q, t);
}

}  // namespace ll::ui
