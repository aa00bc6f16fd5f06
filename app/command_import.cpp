// `lagrangelab import ROBOT.urdf --out SCENE.json [--base LINK] [--tip LINK]
// [--convention standard|modified]`: a URDF robot as a scene, its DH table found from the
// joint axes by the textbook's rules (core/io/urdf_import.hpp). The table, and the case
// that placed each frame, go to stderr.
#include <cstdio>
#include <iostream>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/output_file.hpp"
#include "app/scene_loading.hpp"
#include "core/io/scene_file.hpp"
#include "core/io/urdf_import.hpp"
#include "core/model/validation.hpp"
#include "core/present/diagnostic_text.hpp"
#include "core/present/message_text.hpp"

namespace ll::cli {

int importCommand(const Args& args) {
    const Options options(args, {"out", "base", "tip", "convention"});
    if (options.positional().size() != 1 || !options.has("out")) throw UsageError(usageLine("import"));
    requireWritableOutputFile(options.text("out"));
    const std::string convention = options.text("convention", "standard");
    if (convention != "standard" && convention != "modified")
        throw UsageError(UsageId::ExpectedOneOf, "convention", "standard", "modified", convention);
    UrdfImportOptions how;
    how.base = options.text("base", "");
    how.tip = options.text("tip", "");
    how.convention = convention == "standard" ? DhConvention::Standard : DhConvention::Modified;
    const std::string path = options.positional()[0];
    const UrdfImport imported = importUrdfFile(path, how);
    requireValidSceneFrom(imported.scene, path);
    const present::Language language = presentation().language;
    for (const Message& note : imported.notes) std::cerr << present::messageText(note, language) << '\n';
    saveScene(imported.scene, options.text("out"));

    // The table as the notes print it, and the case of the two axes that placed each frame.
    static const MessageId cases[] = {MessageId::AxisPairSkew, MessageId::AxisPairIntersecting, MessageId::AxisPairParallel,
                                      MessageId::AxisPairCoincident, MessageId::AxisPairLast};
    const auto words = [&](const Message& m) { return present::messageText(m, language); };
    std::cerr << words(message(MessageId::ImportSummary, imported.scene.name, imported.baseLink, imported.tipLink, imported.scene.dof(),
                               convention))
              << "\n  " << words(message(MessageId::ImportTableHeader)) << '\n';
    for (int i = 0; i < imported.scene.dof(); ++i) {
        const DhRow& r = imported.dh.rows[static_cast<std::size_t>(i)];
        const DhFrameRule& f = imported.dh.frames[static_cast<std::size_t>(i) + 1];
        Message why = message(cases[static_cast<int>(f.pair)]);
        if (f.antiparallel) why = message(MessageId::AxisPairAntiparallel, why);
        char numbers[96];
        std::snprintf(numbers, sizeof numbers, "%.6g, %.6g, %.6g, %.6g", r.a, r.alpha, r.d, r.theta);
        std::cerr << "  " << i + 1 << ". " << imported.jointNames[static_cast<std::size_t>(i)] << ", " << toString(r.type) << ", "
                  << numbers << ", " << words(why) << '\n';
    }
    return 0;
}

}  // namespace ll::cli
