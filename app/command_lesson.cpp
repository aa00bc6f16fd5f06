// `lagrangelab lesson LESSON.lesson --out DIR [--format pdf|png|mp4] [--size WxH] [--notes]`
// `lagrangelab lesson LESSON.lesson --embed OUT.json`
// A lesson (core/io/lesson_file.hpp) exported as the lecture shows it: the window presents
// the lesson at --size (16:9, 1920x1080 by default) and each view, restored as the clicker
// restores it (ui/window/lesson_mode.hpp), is grabbed whole: a PDF with a page per view (its
// title and note under it with --notes), a PNG per view, or, for each view that plays
// (playback.play [t0, t1], or playing), an MP4 of the presented window from t0 to t1 at
// 25 frames per second of the run's time (each frame set to its time, not filmed in real
// time). --embed writes the lesson with every view's scene inside it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <QApplication>
#include <QFileInfo>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/event_wait.hpp"
#include "app/offscreen_gui.hpp"
#include "app/output_file.hpp"
#include "app/output_folder.hpp"
#include "app/pixel_size.hpp"
#include "app/settled_screenshot.hpp"
#include "core/io/lesson_file.hpp"
#include "core/present/diagnostic_text.hpp"
#include "core/present/message_text.hpp"
#include "ui/document/app_language.hpp"
#include "ui/paint/ffmpeg_encoder.hpp"
#include "ui/window/lesson_mode.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/presentation_mode.hpp"

namespace ll::cli {

namespace {

// "03-the-mass-matrix": the view's number and title as a file name.
std::string fileStem(std::size_t index, const std::string& title) {
    char number[8];
    std::snprintf(number, sizeof number, "%02zu", index + 1);
    std::string stem = number;
    bool dash = true;
    for (char c : title) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (plain) stem += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c), dash = false;
        else if (!dash) stem += '-', dash = true;
    }
    if (stem.back() == '-') stem.pop_back();
    if (stem.size() > 40) stem.resize(stem.rfind('-', 40) > 2 ? stem.rfind('-', 40) : 40);
    if (stem.size() == 2) stem += "-view";
    else if (stem[2] != '-') stem.insert(2, "-");
    return stem;
}

// The run's times a playing view's video shows: its play range, or (playing without one)
// from its time to the run's end; none for a view that does not play.
std::optional<std::array<double, 2>> playRange(const WindowView& view, double end) {
    if (view.playback.play) return std::array<double, 2>{(*view.playback.play)[0], std::min((*view.playback.play)[1], end)};
    if (view.playback.playing && *view.playback.playing) return std::array<double, 2>{view.playback.time.value_or(0.0), end};
    return std::nullopt;
}

}  // namespace

int lessonCommand(const Args& args) {
    const Options options(args, {"out", "format", "size", "notes", "embed"}, {"notes"});
    if (options.positional().size() != 1) throw UsageError(UsageId::Usage, synopsisLine("lesson"));
    const std::string file = options.positional()[0];
    if (options.has("embed")) {
        const std::string embed = options.text("embed");
        const QString suffix = QFileInfo(QString::fromStdString(embed)).suffix().toLower();
        if (suffix != "json" && suffix != "lesson") throw UsageError(UsageId::EmbedNotLesson, embed);
        requireWritableOutputFile(embed);
        const Lesson lesson = loadLesson(file);
        for (const LessonView& lv : lesson.views)
            if (!lv.problems.empty()) throw InputError(lv.problems);  // a self-contained lesson holds every view whole
        saveLesson(lesson, embed, true);
        std::fprintf(stderr, "lesson with its scenes written to %s\n", embed.c_str());
        if (!options.has("out")) return 0;
    }
    if (!options.has("out")) throw UsageError(UsageId::OutRequired, synopsisLine("lesson"));
    const std::string out = options.text("out");
    const std::string format = options.text("format", "pdf");
    if (format != "pdf" && format != "png" && format != "mp4") throw UsageError(UsageId::ValueExpectedOneOf, "format", format, "pdf, png", "mp4");
    const PixelSize size = parsePixelSize(options.text("size", "1920x1080"));
    const Lesson lesson = loadLesson(file);  // the file itself broken: exit 2 before any window
    if (std::none_of(lesson.views.begin(), lesson.views.end(), [](const LessonView& lv) { return lv.problems.empty(); })) {
        for (const LessonView& lv : lesson.views)
            for (const Diagnostic& d : lv.problems)
                std::cerr << present::messageText(MessageId::WarningLine, presentation().language) << present::diagnosticText(d, presentation().language) << '\n';
        throw UsageError(UsageId::LessonNothingToExport, file);
    }
    prepareOutputFolder(out);
    if (!hasDisplay()) throw UsageError(UsageId::NoDisplay);

    static int argc = 1;
    static char name[] = "lagrangelab";
    static char* argv[] = {name, nullptr};
    providePrivateRuntimeDirectory();
    QApplication app(argc, argv);
    const present::Language language = presentation().language;
    ui::installLanguage(language);
    ui::MainWindow window;
    window.setAskBeforeClosing(false);
    window.resize(size.width, size.height);
    window.presentationMode().setSize(QSize(size.width, size.height));
    window.show();
    if (window.width() != size.width || window.height() != size.height)  // the layout's minimum
        std::fprintf(stderr, "warning: the window cannot be %dx%d; the pictures are %dx%d\n", size.width, size.height, window.width(), window.height());
    QStringList errors, unreadable;
    if (!window.lessons().open(QString::fromStdString(file), &errors, &unreadable)) {
        for (const QString& e : errors) std::cerr << e.toStdString() << '\n';
        return 2;
    }
    for (const QString& u : unreadable) std::cerr << present::messageText(MessageId::WarningLine, language) << u.toStdString() << '\n';

    // Each view as the clicker shows it: restored whole, paused at its time.
    int shown = -1;
    QStringList problems;
    QObject::connect(&window.lessons(), &ui::LessonMode::viewShown, &window, [&](int index, const QStringList& p) {
        shown = index;
        problems = p;
    });
    QPdfWriter* pdf = nullptr;
    std::unique_ptr<QPdfWriter> pdfOwner;
    QPainter painter;
    int written = 0;
    const std::filesystem::path folder(out);
    for (std::size_t i = 0; i < lesson.views.size(); ++i) {
        const LessonView& lv = lesson.views[i];
        if (!lv.problems.empty()) continue;  // said above
        shown = -1;
        if (i == 0 || !window.presentationMode().on()) window.lessons().present(static_cast<int>(i));
        else window.lessons().go(static_cast<int>(i));
        if (!waitFor([&] { return shown == static_cast<int>(i); }, 300)) {
            std::cerr << "error: " << file << ": view " << i + 1 << " was not shown in 300 s\n";
            return 1;
        }
        for (const QString& p : problems)
            std::cerr << present::messageText(MessageId::WarningLine, language) << file << ": " << i + 1 << ". " << p.toStdString() << '\n';
        ui::PlaybackBar& playback = window.playback();
        const auto range = playRange(lv.view, playback.endTime());
        playback.pause();
        if (range) playback.setTime((*range)[0]);
        const std::string stem = fileStem(i, lv.view.name);
        if (format == "mp4") {
            if (!range) continue;  // a still: the PDF or PNGs have it
            constexpr double fps = 25;
            const int frames = std::max(1, static_cast<int>(std::lround(((*range)[1] - (*range)[0]) * fps)) + 1);
            const QImage first = settledScreenshot(window).convertToFormat(QImage::Format_RGBX8888);
            const std::string path = (folder / (stem + ".mp4")).string();
            ui::FfmpegEncoder encoder(path, ui::VideoFormat::Mp4, first.width() & ~1, first.height() & ~1, fps);
            for (int k = 0; k < frames; ++k) {
                if (k > 0) playback.setTime((*range)[0] + k / fps);
                const QImage frame = (k == 0 ? first : settledScreenshot(window).convertToFormat(QImage::Format_RGBX8888))
                                         .copy(0, 0, first.width() & ~1, first.height() & ~1);
                encoder.write(frame.constBits());
            }
            encoder.finish();
            std::fprintf(stderr, "%s: %d frames\n", path.c_str(), frames);
            ++written;
            continue;
        }
        const QImage image = settledScreenshot(window);
        if (format == "png") {
            const std::string path = (folder / (stem + ".png")).string();
            if (!image.save(QString::fromStdString(path), "PNG")) throw std::runtime_error(path + ": cannot save");
            ++written;
            continue;
        }
        // One page per view: 16:9 at the still's pixels; with --notes its title and note below.
        const bool notes = options.has("notes");
        const int below = notes ? image.height() * 3 / 10 : 0;
        const QPageSize page(QSizeF(image.width(), image.height() + below), QPageSize::Point);
        if (!pdf) {
            pdfOwner = std::make_unique<QPdfWriter>(QString::fromStdString((folder / "lesson.pdf").string()));
            pdf = pdfOwner.get();
            pdf->setTitle(QString::fromStdString(lesson.title));
            pdf->setCreator("LagrangeLab");
            pdf->setResolution(72);
            pdf->setPageSize(page);
            pdf->setPageMargins(QMarginsF(0, 0, 0, 0));
            painter.begin(pdf);
        } else {
            pdf->setPageSize(page);
            pdf->newPage();
        }
        painter.drawImage(QRect(0, 0, image.width(), image.height()), image);
        if (notes) {
            QFont font = painter.font();
            font.setPixelSize(image.height() / 30);
            painter.setFont(font);
            const QRect text(image.height() / 30, image.height() + image.height() / 60, image.width() - image.height() / 15, below);
            painter.drawText(text, Qt::TextWordWrap, QString("%1. %2\n%3").arg(i + 1).arg(QString::fromStdString(lv.view.name),
                                                                                   QString::fromStdString(lv.view.note)));
        }
        ++written;
    }
    if (pdf) {
        painter.end();
        pdfOwner.reset();
        std::fprintf(stderr, "%s: %d pages\n", (folder / "lesson.pdf").string().c_str(), written);
    } else {
        std::fprintf(stderr, "%d %s written to %s\n", written, format == "png" ? "stills" : written == 1 ? "video" : "videos", out.c_str());
    }
    return 0;
}

}  // namespace ll::cli
