// The window in Danish (issue 37), under a real X server: with the Danish catalogue
// installed, no text of a menu, action, tab, button, label, dock title, list or table
// header is left as an English source text the catalogue translates; the catalogue has no
// unfinished or obsolete entries and is up to date with the sources (lupdate finds
// nothing new); switching language or notation relabels the derivation on screen without
// deriving it again.
#include "test_registry.hpp"

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QStandardPaths>
#include <QProcess>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QSlider>
#include <QToolBar>
#include <QXmlStreamReader>

#include "core/present/message_text.hpp"
#include "ui/document/app_language.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/main_window.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"
#include "ui/window/language_menu.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_danish_window {

using ll::ui::MainWindow;
namespace present = ll::present;

namespace {

const QString catalogue = QString(LL_SOURCE_DIR) + "/resources/translations/lagrangelab_da.ts";

struct Entry {
    QString source, translation, type;
    bool numerus = false;
};

std::vector<Entry> readCatalogue(const QString& path) {
    std::vector<Entry> out;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return out;
    QXmlStreamReader xml(&f);
    Entry e;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement() && xml.name() == QLatin1String("message")) {
            e = Entry{};
            e.numerus = xml.attributes().value("numerus") == QLatin1String("yes");
        } else if (xml.isStartElement() && xml.name() == QLatin1String("source")) {
            e.source = xml.readElementText();
        } else if (xml.isStartElement() && xml.name() == QLatin1String("translation")) {
            e.type = xml.attributes().value("type").toString();
            e.translation = xml.readElementText(QXmlStreamReader::IncludeChildElements);
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            out.push_back(e);
        }
    }
    return out;
}

QString bare(QString s) { return s.remove('&').trimmed(); }

bool settled(MainWindow& w, int seconds = 60) {
    return ll::test::waitUntil([&] { return w.result() && !w.liveSimulation().busy() && !w.liveDerivation().busy() && w.derivation(); },
                               seconds * 1000);
}

// The planar 2R in a window at 1280×800 on screen, simulated and derived.
std::unique_ptr<MainWindow> opened2R() {
    return ll::test::openedWindow(QString(LL_EXAMPLES_DIR) + "/planar_2r.json",
                                  [](MainWindow& w) { return QTest::qWaitForWindowExposed(&w) && settled(w); });
}

void menuTexts(QMenu* menu, QStringList& out) {
    for (QAction* a : menu->actions()) {
        if (!a->text().isEmpty()) out << a->text();
        if (a->menu()) menuTexts(a->menu(), out);
    }
}

// Every text the window shows: menus and actions, tool bars, buttons, labels, group boxes,
// dock titles, tabs, combo boxes, table headers and cells.
QStringList windowTexts(MainWindow& w) {
    QStringList texts;
    for (QAction* a : w.menuBar()->actions()) {
        texts << a->text();
        if (a->menu()) menuTexts(a->menu(), texts);
    }
    for (QToolBar* bar : w.findChildren<QToolBar*>())
        for (QAction* a : bar->actions()) texts << a->text();
    for (QAbstractButton* b : w.findChildren<QAbstractButton*>()) texts << b->text();
    for (QLabel* l : w.findChildren<QLabel*>()) texts << l->text();
    for (QGroupBox* g : w.findChildren<QGroupBox*>()) texts << g->title();
    for (QDockWidget* d : w.findChildren<QDockWidget*>()) texts << d->windowTitle();
    for (QTabBar* t : w.findChildren<QTabBar*>())
        for (int i = 0; i < t->count(); ++i) texts << t->tabText(i);
    for (QComboBox* c : w.findChildren<QComboBox*>())
        for (int i = 0; i < c->count(); ++i) texts << c->itemText(i);
    for (QTableView* v : w.findChildren<QTableView*>()) {
        if (!v->model()) continue;
        for (int c = 0; c < v->model()->columnCount(); ++c) texts << v->model()->headerData(c, Qt::Horizontal).toString();
        for (int r = 0; r < v->model()->rowCount(); ++r) {
            texts << v->model()->headerData(r, Qt::Vertical).toString();
            for (int c = 0; c < v->model()->columnCount(); ++c) texts << v->model()->data(v->model()->index(r, c)).toString();
        }
    }
    return texts;
}

// The texts of `texts` that are an English source the catalogue translates into something else.
QStringList englishLeft(const QStringList& texts) {
    std::map<QString, QString> english;
    for (const Entry& e : readCatalogue(catalogue))
        if (!e.numerus && bare(e.translation) != bare(e.source)) english[bare(e.source)] = e.translation;
    QStringList left;
    for (const QString& t : texts)
        if (english.count(bare(t))) left << bare(t);
    left.removeDuplicates();
    return left;
}

QStringList menuTitles(MainWindow& w) {
    QStringList menus;
    for (QAction* a : w.menuBar()->actions()) menus << bare(a->text());
    return menus;
}

}  // namespace

class TestDanishWindow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);  // the window's settings in a test folder
        QVERIFY(ll::ui::installLanguage(present::Language::Danish));
    }

    void catalogueIsComplete() {
        const std::vector<Entry> entries = readCatalogue(catalogue);
        QVERIFY(entries.size() > 250);
        for (const Entry& e : entries) {
            QVERIFY2(e.type.isEmpty(), qPrintable(e.type + ": " + e.source));  // not unfinished, obsolete or vanished
            QVERIFY2(!e.translation.trimmed().isEmpty(), qPrintable(e.source));
            for (const QString& mark : {"%1", "%2", "%3", "%n"})
                if (e.source.contains(mark)) QVERIFY2(e.translation.contains(mark), qPrintable(mark + " lost in " + e.source));
        }
        // Up to date with the sources: lupdate over a copy finds nothing new and nothing gone.
        QTemporaryDir dir;
        const QString copy = dir.filePath("da.ts");
        QVERIFY(QFile::copy(catalogue, copy));
        QProcess lupdate;
        lupdate.start("/usr/lib/qt6/bin/lupdate", {"-no-obsolete", "-locations", "relative", "-target-language", "da_DK",
                                                   QString(LL_SOURCE_DIR) + "/ui", QString(LL_SOURCE_DIR) + "/app", "-ts", copy});
        QVERIFY(lupdate.waitForFinished(120000));
        const QString report = QString::fromUtf8(lupdate.readAllStandardOutput() + lupdate.readAllStandardError());
        QVERIFY2(report.contains("(0 new and"), qPrintable(report));
        QVERIFY2(!report.contains("Removed"), qPrintable(report));
    }

    void noEnglishLeft() {
        const auto window = opened2R();
        MainWindow& w = *window;
        const QStringList texts = windowTexts(w);
        QVERIFY(texts.size() > 100);
        const QStringList left = englishLeft(texts);
        QVERIFY2(left.isEmpty(), qPrintable("English left: " + left.join(" | ")));
        // and the Danish is there: the menus as Danish desktop programs name them
        const QStringList menus = menuTitles(w);
        QVERIFY2(menus.contains("Filer") && menus.contains("Rediger") && menus.contains("Vis"), qPrintable(menus.join(",")));
    }

    // Laid out for the longer language at 1280×800: every button of the 3D view's bar is
    // shown inside it (wrapped to a second row if need be, none behind "»"), and the
    // playback's time slider is wide enough to scrub (not squeezed to a box). The
    // screenshot is kept with LL_TEST_KEEP=1.
    void danishFitsAt1280x800() {
        QTemporaryDir dir;
        dir.setAutoRemove(!qEnvironmentVariableIsSet("LL_TEST_KEEP"));
        const auto window = opened2R();
        MainWindow& w = *window;
        QVERIFY(ll::test::nextFrameDrawn(w));
        w.screenshot().save(dir.filePath("danish-1280x800.png"));
        auto* bar = w.findChild<QWidget*>("view-bar");
        QVERIFY(bar);
        QStringList shown;
        for (QToolButton* b : bar->findChildren<QToolButton*>()) {
            if (b->text() == "mesh-filer") {  // only for a robot drawn by its meshes (from URDF): not the 2R
                QVERIFY(b->isHidden());
                continue;
            }
            QVERIFY2(b->isVisible(), qPrintable(b->text()));
            const QRect r(b->mapTo(bar, QPoint(0, 0)), b->size());
            QVERIFY2(bar->rect().contains(r), qPrintable(b->text()));
            QVERIFY2(b->width() >= b->sizeHint().width(), qPrintable(b->text()));  // its whole text
            shown << b->text();
        }
        QCOMPARE(shown.size(), 9);  // Fit, four views, four toggles
        QVERIFY2(shown.contains("koordinatsystemer") && shown.contains("massemidtpunkter"), qPrintable(shown.join(", ")));
        auto* slider = w.playback().findChild<QSlider*>();
        QVERIFY(slider);
        qInfo("time slider %d px of the %d px 3D view", slider->width(), w.sceneView().width());
        QVERIFY2(slider->width() >= w.sceneView().width() * 3 / 4, qPrintable(QString::number(slider->width())));
    }

    // View → Language and Notation relabel the derivation on screen; nothing is derived again.
    void switchingRelabelsWithoutDeriving() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(QString(LL_EXAMPLES_DIR) + "/planar_2r.json", nullptr, true));
        QVERIFY(settled(w));
        const auto titleOfStep7 = [](const present::DisplayDocument& d) { return present::messageText(d.steps.at(7).title, d.language); };
        QCOMPARE(titleOfStep7(*w.derivationView().document()), std::string("Kinetic energy and the mass matrix"));
        const int runs = w.liveDerivation().runs();
        w.language().set({present::Language::Danish, present::Notation::Spong});
        ll::test::flushEvents();  // whatever the switch posted: no derivation among it
        QCOMPARE(w.liveDerivation().runs(), runs);
        const auto doc = w.derivationView().document();
        QCOMPARE(doc->language, present::Language::Danish);
        QCOMPARE(titleOfStep7(*doc), std::string("Kinetisk energi og massematricen"));
        bool massMatrixIsD = false;
        for (const auto& item : doc->steps.at(7).items)
            massMatrixIsD = massMatrixIsD || (item.quantity == present::Quantity::MassMatrix && item.name == "D");
        QVERIFY(massMatrixIsD);
        QVERIFY(w.derivationPanel().findChild<QPlainTextEdit*>());
        const QString text = w.derivationPanel().findChild<QPlainTextEdit*>()->toPlainText();
        QVERIFY2(text.contains(QString::fromUtf8("Trin 7. Kinetisk energi og massematricen")) && text.contains("D = "),
                 qPrintable(text.left(500)));
        // and back, through the View menu as a student would
        QAction* english = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->data().toString() == "en") english = a;
        QVERIFY(english);
        english->trigger();
        QCOMPARE(titleOfStep7(*w.derivationView().document()), std::string("Kinetic energy and the mass matrix"));
        QCOMPARE(w.liveDerivation().runs(), runs);
    }

    // View → Language → Dansk relabels the whole window at once, without a restart: menus,
    // tool bars, docks, tabs, panels, tables; English comes back the same way. The
    // screenshots before and after are kept with LL_TEST_KEEP=1.
    void theWindowRelabelsItselfLive() {
        QVERIFY(ll::ui::installLanguage(present::Language::English));
        QTemporaryDir dir;
        dir.setAutoRemove(!qEnvironmentVariableIsSet("LL_TEST_KEEP"));
        const auto window = opened2R();
        MainWindow& w = *window;
        QVERIFY2(menuTitles(w).contains("File"), qPrintable(menuTitles(w).join(",")));
        QVERIFY(ll::test::nextFrameDrawn(w));
        const QImage before = w.screenshot();
        before.save(dir.filePath("language-before.png"));
        const auto choose = [&](const char* code) {
            for (QAction* a : w.findChildren<QAction*>())
                if (a->data().toString() == QLatin1String(code)) return a->trigger(), true;
            return false;
        };
        QVERIFY(choose("da"));
        ll::test::flushEvents();
        const QStringList left = englishLeft(windowTexts(w));
        QVERIFY2(left.isEmpty(), qPrintable("English left after the switch: " + left.join(" | ")));
        QVERIFY2(menuTitles(w).contains("Filer") && menuTitles(w).contains("Vis"), qPrintable(menuTitles(w).join(",")));
        QCOMPARE(w.derivationView().document()->language, present::Language::Danish);
        QVERIFY(ll::test::nextFrameDrawn(w));
        const QImage after = w.screenshot();
        after.save(dir.filePath("language-after.png"));
        // The menu bar was painted anew with other words.
        const QRect bar(w.menuBar()->mapTo(&w, QPoint(0, 0)), w.menuBar()->size());
        QVERIFY(before.copy(bar) != after.copy(bar));
        // and back
        QVERIFY(choose("en"));
        ll::test::flushEvents();
        QVERIFY2(menuTitles(w).contains("File") && !menuTitles(w).contains("Filer"), qPrintable(menuTitles(w).join(",")));
        QVERIFY(ll::ui::installLanguage(present::Language::Danish));  // as initTestCase left it
    }
};

LL_TEST_MAIN(TestDanishWindow)

}  // namespace test_danish_window
#include "test_danish_window.moc"
