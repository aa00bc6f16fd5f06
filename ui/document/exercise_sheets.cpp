#include "ui/document/exercise_sheets.hpp"

#include <QBuffer>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>
#include <functional>
#include <map>
#include <stdexcept>

#include "core/io/atomic_file.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/present/labels.hpp"
#include "core/present/message_text.hpp"
#include "ui/paint/headless_renderer.hpp"
#include "ui/paint/math_typesetter.hpp"
#include "ui/paint/osg_scene.hpp"

namespace ll::ui {
namespace {

constexpr double kPageWidth = 595, kPageHeight = 842;  // A4 portrait [pt]
constexpr double kMargin = 50;
constexpr double kFontPt = 11;
constexpr double kDevicePerPt = 10;  // the PDF at 720 dpi: fine positions for text
constexpr double kContentWidth = kPageWidth - 2 * kMargin;
constexpr double kUnitPt = kFontPt / mathUnitsPerEm;  // points per layout unit at size 1

// One piece of a page's flow: its height [pt] and how it paints with its top at y [pt].
struct SheetBlock {
    double height = 0;
    std::function<void(QPainter&, double y)> paint;
    double keep = 0;         // room [pt] it wants below it on the same page (a heading)
    bool pageBreak = false;  // starts a new page
};

QPointF device(double x, double y) { return {x * kDevicePerPt, y * kDevicePerPt}; }

void drawBox(QPainter& p, const MathBox& box, double x, double baseline) { paintMath(p, box, device(x, baseline), kDevicePerPt * kUnitPt); }

// A flow of blocks laid onto A4 pages, with a footer on each ("page k of n").
class SheetFlow {
public:
    explicit SheetFlow(present::Language language) : language_(language) {}

    QString words(const Message& m) const { return QString::fromStdString(present::messageText(m, language_)); }

    void add(SheetBlock block) { blocks_.push_back(std::move(block)); }
    void gap(double pt) {
        add({pt, [](QPainter&, double) {}});
    }
    void pageBreak() { add({0, {}, 0, true}); }

    // Prose wrapped to the width, `indent` pt from the margin: symbols like q_i set as
    // math (Prose), or the words as typed (Plain: an id, what a student types), or bold.
    enum class Set { Prose, Plain, Bold };
    void text(const QString& prose, double size = 1, Set set = Set::Prose, double indent = 0, QColor colour = Qt::black) {
        const QStringList wordsOf = prose.split(' ', Qt::SkipEmptyParts);
        const double width = (kContentWidth - indent) / kUnitPt;
        const auto layout = [&](const QString& line) {
            return set == Set::Prose ? layoutProse(line, size) : layoutText(line, size, set == Set::Bold);
        };
        QString line;
        auto flush = [&] {
            if (line.isEmpty()) return;
            const MathBox box = layout(line);
            const double height = 1.45 * size * kFontPt;
            add({height, [box, indent, size, colour](QPainter& p, double y) {
                     p.setPen(colour);
                     drawBox(p, box, kMargin + indent, y + 1.05 * size * kFontPt);
                     p.setPen(Qt::black);
                 }});
            line.clear();
        };
        for (const QString& word : wordsOf) {
            const QString candidate = line.isEmpty() ? word : line + ' ' + word;
            // layoutText measures bold as regular: a fifth more for the bold letters
            if (!line.isEmpty() && layout(candidate).width * (set == Set::Bold ? 1.2 : 1.0) > width) {
                flush();
                line = word;
            } else {
                line = candidate;
            }
        }
        flush();
    }

    void heading(const QString& words, double size = 1.25) {
        gap(6);
        text(words, size, Set::Bold);
        blocks_.back().keep = 60;
        gap(2);
    }

    // Math lines (an equation broken to the width), `indent` pt from the margin.
    void math(const std::vector<MathBox>& lines, double indent = 0) {
        for (const MathBox& box : lines) {
            const double ascent = box.ascent * kUnitPt, descent = box.descent * kUnitPt;
            add({ascent + descent + 5,
                 [box, ascent, indent](QPainter& p, double y) { drawBox(p, box, kMargin + indent, y + 2 + ascent); }});
        }
    }

    // A table of cells set as prose, a header row in bold, columns sized to their contents
    // (at least `minWidth` pt) and spread over the width; empty rows of `emptyHeight` pt
    // where a row has no cells (a table to fill in).
    void table(const std::vector<QString>& header, const std::vector<std::vector<QString>>& rows, double emptyHeight = 0) {
        const std::size_t columns = header.size();
        std::vector<std::vector<MathBox>> boxes;
        boxes.emplace_back();
        for (const QString& h : header) boxes.back().push_back(layoutText(h, 0.9, true));
        for (const auto& row : rows) {
            boxes.emplace_back();
            for (std::size_t c = 0; c < columns; ++c) boxes.back().push_back(layoutProse(c < row.size() ? row[c] : QString(), 0.9));
        }
        std::vector<double> widths(columns, 0);
        for (const auto& row : boxes)
            for (std::size_t c = 0; c < columns; ++c) widths[c] = std::max(widths[c], row[c].width * kUnitPt + 10);
        double total = 0;
        for (double w : widths) total += w;
        if (total < kContentWidth)
            for (double& w : widths) w += (kContentWidth - total) / static_cast<double>(columns);
        else
            for (double& w : widths) w *= kContentWidth / total;
        const double rowHeight = 1.7 * kFontPt;
        for (std::size_t r = 0; r < boxes.size(); ++r) {
            const bool filled = r == 0 || !rows[r - 1].empty();
            const double height = filled ? rowHeight : std::max(rowHeight, emptyHeight);
            add({height, [row = boxes[r], widths, height, header = r == 0](QPainter& p, double y) {
                     double x = kMargin;
                     if (header) p.fillRect(QRectF(device(x, y), device(x + kContentWidth, y + height)), QColor(236, 236, 236));
                     p.setPen(QPen(QColor(120, 120, 120), 0.6 * kDevicePerPt));
                     for (std::size_t c = 0; c < row.size(); ++c) {
                         p.drawRect(QRectF(device(x, y), device(x + widths[c], y + height)));
                         x += widths[c];
                     }
                     p.setPen(Qt::black);
                     x = kMargin;
                     for (std::size_t c = 0; c < row.size(); ++c) {
                         drawBox(p, row[c], x + 5, y + height / 2 + 0.33 * 0.9 * kFontPt);
                         x += widths[c];
                     }
                 }});
        }
    }

    // A task: its label ("b₁₁ =", as the derivation's pages name the entry) and a box to write in.
    void answerBox(const std::string& entry, double height) {
        MathBox box = layoutMath(*present::displayLabel(entry, entryLatex(entry)), 1.1);
        hcat(box, layoutText("=", 1.1), 0.3 * mathUnitsPerEm);
        const double labelWidth = std::max(55.0, box.width * kUnitPt + 8);
        add({height + 8, [box, labelWidth, height](QPainter& p, double y) {
                 drawBox(p, box, kMargin, y + 4 + 1.2 * kFontPt);
                 p.setPen(QPen(QColor(150, 150, 150), 0.7 * kDevicePerPt));
                 p.drawRoundedRect(QRectF(device(kMargin + labelWidth, y + 2), device(kMargin + kContentWidth, y + 2 + height)),
                                   3 * kDevicePerPt, 3 * kDevicePerPt);
                 p.setPen(Qt::black);
             }});
    }

    // A picture centred, `maxHeight` pt high at most and no wider than the text.
    void image(const QImage& picture, double maxHeight) {
        if (picture.isNull()) return;
        const double aspect = double(picture.width()) / picture.height();
        const double height = std::min(maxHeight, kContentWidth / aspect), width = height * aspect;
        add({height + 4, [picture, width, height](QPainter& p, double y) {
                 const double x = kMargin + (kContentWidth - width) / 2;
                 p.drawImage(QRectF(device(x, y + 2), device(x + width, y + 2 + height)), picture);
                 p.setPen(QPen(QColor(200, 200, 200), 0.5 * kDevicePerPt));
                 p.drawRect(QRectF(device(x, y + 2), device(x + width, y + 2 + height)));
                 p.setPen(Qt::black);
             }});
    }

    // Lays the blocks onto pages and writes the PDF; `footer` is the left part of each
    // page's footer. Returns the page count.
    int write(const std::string& path, const QString& title, const QString& footer) const {
        const double top = kMargin, bottom = kPageHeight - kMargin - 14;
        std::vector<std::vector<std::pair<const SheetBlock*, double>>> pages(1);
        double y = top;
        for (std::size_t i = 0; i < blocks_.size(); ++i) {
            const SheetBlock& b = blocks_[i];
            if (b.pageBreak) {
                if (!pages.back().empty()) pages.emplace_back(), y = top;
                continue;
            }
            if (y > top && y + b.height + b.keep > bottom) pages.emplace_back(), y = top;
            if (y == top && !b.paint) continue;
            pages.back().emplace_back(&b, y);
            y += b.height;
        }
        QByteArray bytes;
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        {
            QPdfWriter pdf(&buffer);
            pdf.setResolution(static_cast<int>(72 * kDevicePerPt));
            pdf.setPageSize(QPageSize(QPageSize::A4));
            pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
            pdf.setTitle(title);
            pdf.setCreator("LagrangeLab");
            QPainter painter(&pdf);
            painter.setRenderHint(QPainter::Antialiasing);
            const int n = static_cast<int>(pages.size());
            for (int k = 0; k < n; ++k) {
                if (k) pdf.newPage();
                for (const auto& [block, at] : pages[static_cast<std::size_t>(k)])
                    if (block->paint) block->paint(painter, at);
                painter.setPen(QColor(110, 110, 110));
                drawBox(painter, layoutText(footer, 0.75), kMargin, kPageHeight - kMargin + 4);
                const MathBox page = layoutText(words(message(MessageId::ExercisePage, k + 1, n)), 0.75);
                drawBox(painter, page, kPageWidth - kMargin - page.width * kUnitPt * 1, kPageHeight - kMargin + 4);
                painter.setPen(Qt::black);
            }
        }
        try {
            saveFileAtomically(path, bytes.toStdString(), Backup::None);
        } catch (const std::exception& e) {
            throw std::runtime_error(path + ": " + e.what());
        }
        return static_cast<int>(pages.size());
    }

private:
    present::Language language_;
    std::vector<SheetBlock> blocks_;
};

QString qs(const std::string& s) { return QString::fromStdString(s); }

// "a1 = 0.93 m, m1 = 2.2 kg, …": the numbers of every parameter the robot uses, with their units.
QString valuesLine(const Scene& scene) {
    const std::map<std::string, std::string> units = parameterUnits(scene);
    const std::vector<std::string> used = usedParameters(scene);
    QStringList parts;
    for (const auto& [name, value] : scene.parameters) {
        if (std::find(used.begin(), used.end(), name) == used.end()) continue;
        const auto unit = units.find(name);
        parts << qs(name + " = " + shortNumber(value) + (unit != units.end() ? "\u00a0" + unit->second : ""));
    }
    return parts.join(",  ");
}

QString convention(const SheetFlow& flow, const Scene& scene) {
    return flow.words(
        Message(scene.robot.convention == DhConvention::Modified ? MessageId::HintConventionModified : MessageId::HintConventionStandard));
}

// The DH table, the links' table, the gravity and the student's numbers.
void robotTables(SheetFlow& flow, const Scene& scene, bool dhToFill) {
    const std::vector<RobotTableRow> rows = robotTable(scene);
    if (!rows.empty()) {
        const bool modified = scene.robot.convention == DhConvention::Modified;
        flow.heading(flow.words(Message(modified ? MessageId::TitleDhModified : MessageId::TitleDhStandard)), 1.0);
        std::vector<std::vector<QString>> dh;
        for (std::size_t i = 0; i < rows.size(); ++i) {
            if (dhToFill) {
                dh.emplace_back();  // empty: to be filled in from the picture
                continue;
            }
            const RobotTableRow& r = rows[i];
            dh.push_back({QString::number(i + 1), qs(r.a), qs(r.alpha), qs(r.d), qs(r.theta)});
        }
        flow.table({flow.words(Message(MessageId::ExerciseJoint)), "a", "α", "d", "θ"}, dh, 26);
        if (dhToFill) flow.text(flow.words(message(MessageId::ExerciseTaskDh, convention(flow, scene).toStdString())), 0.9);
        flow.heading(flow.words(Message(MessageId::ExerciseLinks)), 1.0);
        std::vector<std::vector<QString>> links;
        for (std::size_t i = 0; i < rows.size(); ++i) {
            const RobotTableRow& r = rows[i];
            QStringList inertia;
            for (const std::string& v : r.inertia) inertia << qs(v);
            links.push_back(
                {QString::number(i + 1), qs(r.mass), qs("[" + r.com[0] + ", " + r.com[1] + ", " + r.com[2] + "]"), inertia.join(", ")});
        }
        flow.table({flow.words(Message(MessageId::ExerciseJoint)), flow.words(Message(MessageId::ExerciseMass)),
                    flow.words(Message(MessageId::ExerciseCom)), flow.words(Message(MessageId::ExerciseInertia))},
                   links);
    } else if (scene.lagrangian) {
        flow.gap(6);
        flow.text(qs("E_kin = " + scene.lagrangian->kinetic));
        flow.text(qs("E_pot = " + scene.lagrangian->potential));
    }
    flow.gap(6);
    if (scene.effects.gravity) {
        const Eigen::Vector3d& g = *scene.effects.gravity;
        flow.text(flow.words(
            message(MessageId::ExerciseGravity, "[" + shortNumber(g[0]) + ", " + shortNumber(g[1]) + ", " + shortNumber(g[2]) + "]")));
    }
    if (!usedParameters(scene).empty()) {
        flow.heading(flow.words(Message(MessageId::ExerciseParameters)), 1.0);
        flow.text(valuesLine(scene));
    }
}

// The student's robot's name: its scene's, without the " (id)" the set added.
std::string robotName(const Scene& scene, const ExerciseStudent& student) {
    const std::string suffix = " (" + student.id + ")";
    const std::string& name = scene.name;
    return name.size() > suffix.size() && name.ends_with(suffix) ? name.substr(0, name.size() - suffix.size()) : name;
}

QString footerOf(const ExerciseSet& set, const ExerciseStudent& student, const Scene& scene,
                 const SheetFlow& flow) {  // name · student · robot
    return qs(robotName(scene, student)) + "  ·  " + flow.words(message(MessageId::ExerciseStudent, student.id)) + "  ·  " +
           flow.words(message(MessageId::ExerciseRobotId, student.fingerprint, std::to_string(set.seed)));
}

}  // namespace

QImage robotPicture(const Scene& scene, int width, int height) {
    VisualScene visual = visualScene(scene);
    const Eigen::VectorXd q = Eigen::VectorXd::Zero(visual.dof());
    visual.pose(q, 0);
    std::vector<Eigen::Vector4d> hold;
    visual.currentExtent(hold);
    OsgSceneOptions options;
    options.trail = false;
    options.dropLines = false;
    options.labelPixels = std::max(14.0, height / 28.0);
    OsgScene graph(visual, options);
    HeadlessRenderer gl(width, height);
    gl.setBackground(1, 1, 1);
    gl.setScene(graph.root());
    const CameraView camera = cameraView(visual, CameraSpec{}, gl.aspect(), &hold);
    applyCameraView(*gl.camera(), camera, gl.aspect());
    graph.update(visual);
    graph.placeLabels(visual, camera, width, height);
    QImage image;
    gl.render(image);
    // Cropped to the robot, its frames and labels (what is darker or more coloured than the
    // ground grid), with a margin: the camera frames the whole scene.
    int left = width, right = -1, top = height, bottom = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.value() < 150 || c.saturation() > 60) {
                left = std::min(left, x), right = std::max(right, x);
                top = std::min(top, y), bottom = std::max(bottom, y);
            }
        }
    if (right < 0) return image.convertToFormat(QImage::Format_RGB32);
    const int margin = height / 12;
    QRect ink = QRect(QPoint(left, top), QPoint(right, bottom)).adjusted(-margin, -margin, margin, margin);
    if (ink.height() < ink.width() / 3) ink.adjust(0, -(ink.width() / 3 - ink.height()) / 2, 0, (ink.width() / 3 - ink.height()) / 2);
    return image.copy(ink.intersected(image.rect())).convertToFormat(QImage::Format_RGB32);
}

int writeExerciseSheet(const ExerciseSet& set, const SheetStudent& s, present::Language language, const std::string& path) {
    SheetFlow flow(language);
    const ExerciseStudent& student = *s.student;
    flow.text(flow.words(message(MessageId::ExerciseSheetTitle, robotName(s.scene, student))), 1.5, SheetFlow::Set::Bold);
    flow.text(flow.words(message(MessageId::ExerciseStudent, student.id)) + "     " +
                  flow.words(message(MessageId::ExerciseRobotId, student.fingerprint, std::to_string(set.seed))),
              0.9, SheetFlow::Set::Plain);
    flow.gap(4);
    if (!s.picture.isNull()) {
        flow.image(s.picture, 140);
        flow.text(flow.words(Message(s.scene.lagrangian ? MessageId::ExercisePictureSystem : MessageId::ExercisePicture)), 0.85,
                  SheetFlow::Set::Prose, 0, QColor(90, 90, 90));
    }
    robotTables(flow, s.scene, set.dhTable);
    flow.heading(flow.words(Message(MessageId::ExerciseTasks)));
    const bool numeric = set.mode == symbolic::ParameterMode::Numeric;
    const bool system = s.scene.lagrangian.has_value();  // a typed Lagrangian: its own coordinates, no joints
    flow.text(flow.words(Message(numeric ? (system ? MessageId::ExerciseTaskIntroNumericSystem : MessageId::ExerciseTaskIntroNumeric)
                                         : (system ? MessageId::ExerciseTaskIntroSymbolsSystem : MessageId::ExerciseTaskIntroSymbols))));
    flow.gap(4);
    for (const std::string& entry : set.entries) {
        const bool long_ = entry.rfind("equation", 0) == 0 || entry.rfind("E_", 0) == 0 || entry.rfind("c", 0) == 0;
        flow.answerBox(entry, long_ ? 60 : 42);
    }
    flow.gap(6);
    flow.text(flow.words(Message(MessageId::ExerciseHandIn)), 0.9, SheetFlow::Set::Plain, 0, QColor(60, 60, 60));
    return flow.write(path, flow.words(message(MessageId::ExerciseSheetTitle, robotName(s.scene, student))),
                      footerOf(set, student, s.scene, flow));
}

int writeSolutions(const ExerciseSet& set, const std::vector<SolutionStudent>& students, present::Language language,
                   const std::string& path) {
    SheetFlow flow(language);
    const QString title = flow.words(message(MessageId::ExerciseSolutionsTitle, set.name));
    for (std::size_t k = 0; k < students.size(); ++k) {
        const SolutionStudent& s = students[k];
        if (k) flow.pageBreak();
        flow.text(title, 1.3, SheetFlow::Set::Bold);
        flow.text(flow.words(Message(MessageId::ExerciseSolutionsNote)), 0.85, SheetFlow::Set::Prose, 0, QColor(90, 90, 90));
        if (set.scenes.size() > 1) flow.text(qs(robotName(s.scene, *s.student)), 1.0, SheetFlow::Set::Bold);  // a family: which member
        flow.heading(flow.words(message(MessageId::ExerciseStudent, s.student->id)) + "     " +
                         flow.words(message(MessageId::ExerciseRobotId, s.student->fingerprint, std::to_string(set.seed))),
                     1.05);
        if (set.dhTable) robotTables(flow, s.scene, false);
        else flow.text(valuesLine(s.scene));
        flow.heading(flow.words(Message(MessageId::ExerciseTasks)), 1.05);
        for (const present::DisplayPtr& answer : s.answers) {
            flow.math(layoutEquation(*answer, (kContentWidth - 10) / kUnitPt), 10);
            flow.gap(3);
        }
    }
    return flow.write(path, title, qs(set.name));
}

int writeFeedback(const ExerciseSet& set, const ExerciseStudent& student, const Scene& scene, const std::vector<GradedTask>& tasks,
                  present::Language language, const std::string& path) {
    SheetFlow flow(language);
    const QString title = flow.words(message(MessageId::ExerciseFeedbackTitle, robotName(scene, student)));
    flow.text(title, 1.5, SheetFlow::Set::Bold);
    flow.text(flow.words(message(MessageId::ExerciseStudent, student.id)) + "     " +
                  flow.words(message(MessageId::ExerciseRobotId, student.fingerprint, std::to_string(set.seed))),
              0.9, SheetFlow::Set::Plain);
    int right = 0;
    for (const GradedTask& t : tasks) right += !t.typed.empty() && t.check.verdict == AnswerVerdict::Right;
    flow.gap(4);
    flow.text(flow.words(message(MessageId::ExerciseScore, right, static_cast<int>(tasks.size()))), 1.1, SheetFlow::Set::Bold);
    for (const GradedTask& t : tasks) {
        flow.gap(8);
        QString verdict;
        QColor colour(0, 0, 0);
        if (t.typed.empty()) verdict = flow.words(Message(MessageId::ExerciseUnanswered)), colour = QColor(110, 110, 110);
        else if (t.check.verdict == AnswerVerdict::Right)
            verdict = flow.words(Message(MessageId::AnswerRight)), colour = QColor(0, 120, 40);
        else if (t.check.verdict == AnswerVerdict::Wrong)
            verdict = flow.words(Message(MessageId::AnswerWrong)), colour = QColor(190, 30, 30);
        else verdict = flow.words(Message(MessageId::AnswerUnreadable)), colour = QColor(190, 110, 0);
        flow.text(qs(t.entry) + ":  " + verdict, 1.1, SheetFlow::Set::Bold, 0, colour);
        if (t.typed.empty()) continue;
        flow.text(flow.words(message(MessageId::ExerciseYourAnswer, t.typed)), 0.95, SheetFlow::Set::Plain, 14);
        if (t.check.verdict == AnswerVerdict::Unreadable) {
            flow.text(flow.words(t.check.problem), 0.95, SheetFlow::Set::Plain, 14);
            continue;
        }
        flow.text(flow.words(message(MessageId::AnswerReadAs, t.check.readAs)), 0.95, SheetFlow::Set::Plain, 14);
        if (t.check.writtenDifferently)
            flow.text(flow.words(Message(MessageId::AnswerWrittenDifferently)), 0.95, SheetFlow::Set::Prose, 14);
        if (t.check.withValues) flow.text(flow.words(Message(MessageId::AnswerWithValues)), 0.95, SheetFlow::Set::Prose, 14);
        for (const Message& hint : t.check.hints) flow.text("– " + flow.words(hint), 0.95, SheetFlow::Set::Prose, 14);
    }
    return flow.write(path, title, footerOf(set, student, scene, flow));
}

}  // namespace ll::ui
