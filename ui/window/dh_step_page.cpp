#include "ui/window/dh_step_page.hpp"

#include "ui/window/dh_axes_panel.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/relabel.hpp"

namespace ll::ui {

DhStepPage::DhStepPage(QWidget* parent) : QTabWidget(parent), axes_(new DhAxesPanel(this)), rows_(new DhStepPanel(this)) {
    setDocumentMode(true);
    // The order of the notes: the frames are found first, then each row carried out.
    addTab(axes_, QString());
    addTab(rows_, QString());
    setCurrentWidget(rows_);
    (*new Relabel(this))([this] {
        setTabText(0, tr("Find the DH parameters"));
        setTabText(1, tr("Row by row"));
    });
}

}  // namespace ll::ui
