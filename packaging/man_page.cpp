// Build-time tool: writes the lagrangelab(1) man page from the program's own help
// texts. Runs the built binary (`lagrangelab --help`, `--version`, `help COMMAND` for
// each command the overview lists) and turns that text into roff.
//   usage: lagrangelab_man_page PATH/TO/lagrangelab OUT.1 DATE
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

std::string run(const std::string& command) {
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run " + command);
    std::string out;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    if (::pclose(pipe) != 0) throw std::runtime_error(command + " failed");
    return out;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(' ');
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// Text as roff: backslashes escaped, minus signs as \-, no control character at a line start.
std::string roff(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '\\' ? "\\e" : c == '-' ? "\\-" : std::string(1, c);
    // Combining dots over a letter (q̇, q̈) are lost by groff: primes, as in the description.
    for (const auto& [dots, primes] : {std::pair<std::string, std::string>{"\u0308", "''"}, {"\u0307", "'"}})
        for (std::size_t at; (at = out.find(dots)) != std::string::npos;) out.replace(at, dots.size(), primes);
    if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
    return out;
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: lagrangelab_man_page LAGRANGELAB OUT.1 DATE\n";
        return 2;
    }
    try {
        const std::string cli = quoted(argv[1]);
        const std::string version = trimmed(lines(run(cli + " --version")).at(0));  // "lagrangelab X.Y.Z"
        const std::vector<std::string> overview = lines(run(cli + " --help"));

        std::ostringstream man;
        man << ".TH LAGRANGELAB 1 \"" << argv[3] << "\" \"" << version << "\" \"User Commands\"\n"
            << ".SH NAME\nlagrangelab \\- Euler\\(enLagrange modelling of robot manipulators: derive, simulate, render\n"
            << ".SH SYNOPSIS\n.nf\n";
        std::size_t i = 0;
        for (; i < overview.size() && !overview[i].empty(); ++i) {
            std::string line = overview[i];
            if (line.rfind("usage: ", 0) == 0) line = line.substr(7);
            man << roff(trimmed(line)) << "\n";
        }
        man << ".fi\n.SH DESCRIPTION\nLagrangeLab builds the model B(q) q\\(aq\\(aq + C(q, q\\(aq) q\\(aq + g(q) = Q of a robot or "
               "Lagrangian system described in a scene file (JSON, \\fB\"format\": \"lagrangelab\\-scene/1\"\\fR, "
               "extension \\fB.lagrange\\fR or \\fB.json\\fR), derives it step by step, simulates and renders it.\n"
            << ".SH COMMANDS\n";
        std::string exitCodes;
        for (; i < overview.size(); ++i) {
            const std::string& line = overview[i];
            if (line.rfind("exit codes:", 0) == 0) exitCodes = line.substr(11);
            // A command starts a line indented by exactly two spaces.
            if (line.size() < 3 || line.compare(0, 2, "  ") != 0 || line[2] < 'a' || line[2] > 'z') continue;
            const std::string name = line.substr(2, line.find(' ', 2) - 2);
            const std::vector<std::string> usage = lines(run(cli + " help " + name));
            // "usage: lagrangelab NAME …" and its continuation lines, a blank line, the summary.
            std::size_t k = 0;
            std::string synopsis;
            for (; k < usage.size() && !usage[k].empty(); ++k)
                synopsis += (synopsis.empty() ? "" : " ") + trimmed(k == 0 ? usage[k].substr(19) : usage[k]);
            man << ".TP\n.B " << roff(synopsis) << "\n";
            bool first = true;
            for (++k; k < usage.size(); ++k) {
                if (trimmed(usage[k]).empty()) continue;
                man << (first ? "" : ".br\n") << roff(trimmed(usage[k])) << "\n";
                first = false;
            }
        }
        man << ".SH EXIT STATUS\n"
            << roff(trimmed(exitCodes)) << ".\n"
            << ".SH FILES\n.TP\n.I PREFIX/share/lagrangelab/examples/\n"
               "Example scenes, found relative to the executable (PREFIX/bin/lagrangelab).\n"
            << ".SH SEE ALSO\nThe README of LagrangeLab; \\fBlagrangelab help\\fR \\fIcommand\\fR.\n";

        const std::string path = argv[2];
        std::ofstream out(path + ".tmp", std::ios::binary);
        out << man.str();
        out.close();
        if (!out || std::rename((path + ".tmp").c_str(), path.c_str()) != 0) throw std::runtime_error("cannot write " + path);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 1;
    }
}
