// `lagrangelab codegen SCENE --lang c|python [--out FILE] [--numeric]`: the structured
// model as a program (core/symbolic/code_export.hpp).
#include <chrono>
#include <ctime>
#include <iostream>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/scene_loading.hpp"
#include "core/io/atomic_file.hpp"
#include "core/symbolic/code_export.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::cli {

int codegenCommand(const Args& args) {
    const Options options(args, {"lang", "out"}, {"numeric"});
    if (options.positional().size() != 1) throw UsageError(usageLine("codegen"));
    const std::string lang = options.text("lang", "");
    if (lang != "c" && lang != "python") throw UsageError(UsageId::ExpectedOneOf, "lang", "c", "python", lang);
    const std::string path = options.positional()[0];
    const Scene scene = loadSceneReportingWarnings(path);
    if (scene.lagrangian) throw UsageError(UsageId::CodegenNeedsRobot, path);
    symbolic::DerivationOptions derivation;
    derivation.mode = options.has("numeric") ? symbolic::ParameterMode::Numeric : symbolic::ParameterMode::Parametric;
    const auto lock = symbolic::lockGinac();
    const symbolic::StructuredDynamics s = inSceneFile(path, [&] { return symbolic::deriveStructured(scene, derivation); });
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    const std::string code = symbolic::exportCode(s, scene, lang == "c" ? symbolic::CodeLanguage::C : symbolic::CodeLanguage::Python, date);
    if (options.has("out")) saveFileAtomically(options.text("out"), code, Backup::None);
    else std::cout << code;
    return 0;
}

}  // namespace ll::cli
