// `lagrangelab export-urdf SCENE --out ROBOT.urdf`: a robot scene as URDF
// (core/io/urdf_export.hpp); what URDF cannot hold is said on stderr.
#include <iostream>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/output_file.hpp"
#include "app/scene_loading.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/urdf_export.hpp"
#include "core/present/message_text.hpp"

namespace ll::cli {

int exportUrdfCommand(const Args& args) {
    const Options options(args, {"out"});
    if (options.positional().size() != 1 || !options.has("out")) throw UsageError(usageLine("export-urdf"));
    requireWritableOutputFile(options.text("out"));
    const std::string path = options.positional()[0];
    const Scene scene = loadSceneReportingWarnings(path);
    const UrdfExport urdf = inSceneFile(path, [&] { return exportUrdf(scene); });
    for (const Message& note : urdf.notes) std::cerr << present::messageText(note, presentation().language) << '\n';
    saveFileAtomically(options.text("out"), urdf.xml, Backup::None);
    return 0;
}

}  // namespace ll::cli
