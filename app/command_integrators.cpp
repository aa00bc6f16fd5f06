// `lagrangelab integrators`: the integrators with order, kind and when to use each.
#include <cstdio>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "core/simulation/integrators.hpp"

namespace ll::cli {

int integratorsCommand(const Args& args) {
    const Options options(args, {});
    std::printf("%-17s %-6s %-9s %s\n", "name", "order", "step", "kind / when to use");
    for (const IntegratorInfo& info : integratorCatalogue()) {
        const std::string order = info.order > 0 ? std::to_string(info.order) : "var.";
        std::printf("%-17s %-6s %-9s %s\n%-34s %s\n", info.name.c_str(), order.c_str(), info.adaptive ? "adaptive" : "fixed",
                    info.kind.c_str(), "", info.whenToUse.c_str());
    }
    return 0;
}

}  // namespace ll::cli
