#pragma once
// What the window shows, as a view (core/io/window_view.hpp): captured from the window's
// parts as they are, and restored through the same setters the command-line options use
// (the scene opened when another is open, the language, presentation mode, then, once the
// scene's run and derivation are on screen, the step, the pick, the time, the tabs, the DH
// step-through, the teach pose, the toggles and last the camera, which is kept exactly).
// A view that no longer fits its scene (an entry gone after an edit, a step the derivation
// has not, a joint it has not) is restored as far as it can be, and `restored` lists what
// was not: never a silent difference. View → Save view… and Open view… are here.
#include <QObject>
#include <QString>
#include <QStringList>

#include "core/io/window_view.hpp"

class QMenu;

namespace ll::ui {

class MainWindow;
struct WindowParts;

class ViewState : public QObject {
    Q_OBJECT
public:
    ViewState(MainWindow& window, const WindowParts& parts);

    // The view of the window now. The scene is the document's file, or (unsaved, or edited
    // since it was saved) the document's JSON itself, so the view shows what is on screen.
    // Fields of a newer version that the view restored last had are kept.
    WindowView capture() const;
    // Starts restoring `view`; `restored(problems)` when it is on screen. A view restored
    // while another is being restored replaces it.
    void restore(const WindowView& view);
    bool restoring() const { return restoring_; }

    void addTo(QMenu* menu);
    void saveAs();    // View → Save view…
    void openFile();  // View → Open view…

signals:
    // What the view asked for that could not be shown, one line each (empty: all of it).
    void restored(const QStringList& problems);

private:
    bool sceneShown() const;  // the scene's run and derivation are on screen
    void finish(int generation, int settle);
    void applyShown();
    void applyPlots();

    MainWindow& window_;
    const WindowParts& parts_;
    WindowView view_;  // the view restored last (its fields unknown to this version go into a capture)
    QStringList problems_;
    bool restoring_ = false;
    bool interactive_ = false;  // opened from the menu: what could not be restored is shown in a box
    int generation_ = 0;  // of the newest restore: an older one's pending steps stop
    std::string embedded_;  // the embedded scene last opened (dumped), so the same is not opened again
};

}  // namespace ll::ui
