#include "core/symbolic/code_export.hpp"

#include "core/model/one_based.hpp"
#include <regex>
#include <set>
#include <sstream>

namespace ll::symbolic {
namespace {

class Writer {
public:
    Writer(const StructuredDynamics& s, CodeLanguage language) : s_(s), python_(language == CodeLanguage::Python) {}

    std::string expr(const GiNaC::ex& e) const {
        std::ostringstream out;
        e.print(GiNaC::print_csrc_double(out));
        std::string text = out.str();
        if (python_) {
            static const std::regex call(R"(\b(pow|sqrt|cos|sin|tan|exp|log|tanh|fabs)\()");
            text = std::regex_replace(text, call, "math.$1(");
        }
        return text;
    }

    // Assignments of every input and name the outputs need, in table order.
    std::string body(const std::vector<GiNaC::ex>& outputs, bool velocities, const std::string& indent) const {
        std::set<int> cone;
        std::set<std::string> used;
        for (const GiNaC::ex& e : outputs) {
            for (int k : s_.table->coneOf(e)) cone.insert(k);
            collect(e, used);
        }
        for (int k : cone) collect(s_.table->entries()[k].value, used);
        std::ostringstream out;
        const auto assign = [&](const std::string& name, const std::string& value) {
            out << indent << (python_ ? "" : "const double ") << name << " = " << value << (python_ ? "" : ";") << "\n";
        };
        if (used.count("Pi")) assign("Pi", python_ ? "math.pi" : "3.14159265358979323846");
        for (const GiNaC::ex& rel : s_.parameterValues) {
            const std::string name = GiNaC::ex_to<GiNaC::symbol>(rel.lhs()).get_name();
            if (used.count(name)) assign(name, expr(rel.rhs()));
        }
        for (int i = 0; i < s_.n; ++i) {
            const std::string at = "[" + std::to_string(i) + "]";
            if (used.count("q" + idx(i))) assign("q" + idx(i), "q" + at);
            if (used.count("c" + idx(i))) assign("c" + idx(i), std::string(python_ ? "math." : "") + "cos(q" + at + ")");
            if (used.count("s" + idx(i))) assign("s" + idx(i), std::string(python_ ? "math." : "") + "sin(q" + at + ")");
            if (velocities && used.count("qd" + idx(i))) assign("qd" + idx(i), "qd" + at);
        }
        for (int k : cone) {
            const NamedDefinition& d = s_.table->entries()[k];
            out << indent << (python_ ? "# " : "/* ") << d.meaning.english() << (python_ ? "" : " */") << "\n";
            assign(d.name, expr(d.value));
        }
        return out.str();
    }

private:
    static void collect(const GiNaC::ex& e, std::set<std::string>& names) {
        for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
            if (GiNaC::is_a<GiNaC::symbol>(*it)) names.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name());
            if (GiNaC::is_a<GiNaC::constant>(*it)) names.insert("Pi");
        }
    }

    const StructuredDynamics& s_;
    bool python_;
};

std::string headerLines(const StructuredDynamics& s, const Scene& scene, const std::string& date, const std::string& prefix) {
    std::ostringstream out;
    out << prefix << "LagrangeLab: the Euler-Lagrange model of \"" << scene.name << "\" (" << s.n << " joints), structured form\n"
        << prefix << "generated " << date << " from " << s.table->size() << " named quantities\n"
        << prefix << "DH table (" << (s.convention == DhConvention::Standard ? "standard" : "modified") << " convention):\n"
        << prefix << "  joint  type       a           alpha       d           theta\n";
    for (int i = 0; i < s.n; ++i) {
        const DhRow& dh = scene.robot.joints[i].dh;
        char line[200];
        std::snprintf(line, sizeof line, "  %-5d  %-9s  %-10.6g  %-10.6g  %-10.6g  %-10.6g", i + 1,
                      dh.type == JointType::Revolute ? "revolute" : "prismatic", dh.a, dh.alpha, dh.d, dh.theta);
        out << prefix << line << "\n";
    }
    out << prefix << "B(q) qdd + C(q, qd) qd + g(q) = tau; tau: the non-conservative generalized forces\n"
        << prefix << "(torques, friction); gravity and joint springs are in g. Units: SI, angles in rad.\n";
    return out.str();
}

std::vector<GiNaC::ex> entries(const GiNaC::matrix& m) {
    std::vector<GiNaC::ex> out;
    for (unsigned r = 0; r < m.rows(); ++r)
        for (unsigned c = 0; c < m.cols(); ++c) out.push_back(m(r, c));
    return out;
}

std::string cCode(const StructuredDynamics& s, const Scene& scene, const std::string& date) {
    const Writer w(s, CodeLanguage::C);
    const std::string N = std::to_string(s.n);
    std::ostringstream out;
    out << "/*\n"
        << headerLines(s, scene, date, " * ") << " * C99, only <math.h>. Matrices are row-major n*n arrays.\n */\n"
        << "#include <math.h>\n\n#define LL_DOF " << N << "\n\n";
    const auto function = [&](const std::string& signature, const GiNaC::matrix& m, const std::string& target, bool velocities) {
        out << signature << " {\n" << w.body(entries(m), velocities, "    ");
        for (unsigned r = 0; r < m.rows(); ++r)
            for (unsigned c = 0; c < m.cols(); ++c)
                out << "    " << target << "[" << r * m.cols() + c << "] = " << w.expr(m(r, c)) << ";\n";
        out << "}\n\n";
    };
    out << "/* B(q): the mass matrix */\n";
    function("void ll_mass_matrix(const double q[LL_DOF], double B[LL_DOF * LL_DOF])", s.B, "B", false);
    out << "/* C(q, qd): Coriolis and centrifugal matrix from the Christoffel symbols of B */\n";
    function("void ll_coriolis_matrix(const double q[LL_DOF], const double qd[LL_DOF], double C[LL_DOF * LL_DOF])", s.C, "C", true);
    out << "/* g(q) = dE_pot/dq: gravity and springs */\n";
    function("void ll_gravity(const double q[LL_DOF], double g[LL_DOF])", s.g, "g", false);
    out << "/* qdd = B^-1 (tau - C qd - g) by Cholesky; returns 0, or -1 when B is not positive definite */\n"
           "int ll_forward_dynamics(const double q[LL_DOF], const double qd[LL_DOF], const double tau[LL_DOF], double qdd[LL_DOF]) {\n"
           "    double B[LL_DOF * LL_DOF], C[LL_DOF * LL_DOF], g[LL_DOF], L[LL_DOF * LL_DOF];\n"
           "    int i, j, k;\n"
           "    ll_mass_matrix(q, B);\n    ll_coriolis_matrix(q, qd, C);\n    ll_gravity(q, g);\n"
           "    for (i = 0; i < LL_DOF; ++i) {\n"
           "        double r = tau[i] - g[i];\n"
           "        for (j = 0; j < LL_DOF; ++j) r -= C[i * LL_DOF + j] * qd[j];\n"
           "        qdd[i] = r;\n"
           "    }\n"
           "    for (i = 0; i < LL_DOF; ++i)\n"
           "        for (j = 0; j <= i; ++j) {\n"
           "            double sum = B[i * LL_DOF + j];\n"
           "            for (k = 0; k < j; ++k) sum -= L[i * LL_DOF + k] * L[j * LL_DOF + k];\n"
           "            if (i == j) {\n"
           "                if (sum <= 0.0) return -1;\n"
           "                L[i * LL_DOF + i] = sqrt(sum);\n"
           "            } else {\n"
           "                L[i * LL_DOF + j] = sum / L[j * LL_DOF + j];\n"
           "            }\n"
           "        }\n"
           "    for (i = 0; i < LL_DOF; ++i) {\n"
           "        for (k = 0; k < i; ++k) qdd[i] -= L[i * LL_DOF + k] * qdd[k];\n"
           "        qdd[i] /= L[i * LL_DOF + i];\n"
           "    }\n"
           "    for (i = LL_DOF - 1; i >= 0; --i) {\n"
           "        for (k = i + 1; k < LL_DOF; ++k) qdd[i] -= L[k * LL_DOF + i] * qdd[k];\n"
           "        qdd[i] /= L[i * LL_DOF + i];\n"
           "    }\n"
           "    return 0;\n"
           "}\n";
    return out.str();
}

std::string pythonCode(const StructuredDynamics& s, const Scene& scene, const std::string& date) {
    const Writer w(s, CodeLanguage::Python);
    std::ostringstream out;
    out << headerLines(s, scene, date, "# ") << "# Python 3, standard library only. Matrices are lists of rows.\n"
        << "# Run as a script: python3 FILE --q v1,v2,... --qd v1,... [--tau v1,...] prints B, C, g, qdd as JSON.\n"
        << "import json\nimport math\nimport sys\n\nDOF = " << s.n << "\n\n";
    const auto function = [&](const std::string& signature, const GiNaC::matrix& m, bool velocities) {
        out << "def " << signature << ":\n" << w.body(entries(m), velocities, "    ") << "    return [";
        for (unsigned r = 0; r < m.rows(); ++r) {
            if (m.cols() > 1) out << "[";
            for (unsigned c = 0; c < m.cols(); ++c) out << w.expr(m(r, c)) << (c + 1 < m.cols() ? ", " : "");
            if (m.cols() > 1) out << "]";
            out << (r + 1 < m.rows() ? ",\n            " : "");
        }
        out << "]\n\n\n";
    };
    out << "# B(q): the mass matrix\n";
    function("mass_matrix(q)", s.B, false);
    out << "# C(q, qd): Coriolis and centrifugal matrix from the Christoffel symbols of B\n";
    function("coriolis_matrix(q, qd)", s.C, true);
    out << "# g(q) = dE_pot/dq: gravity and springs\n";
    function("gravity(q)", s.g, false);
    out << "def forward_dynamics(q, qd, tau):\n"
           "    \"\"\"qdd = B^-1 (tau - C qd - g), by Cholesky.\"\"\"\n"
           "    B, C, g = mass_matrix(q), coriolis_matrix(q, qd), gravity(q)\n"
           "    n = DOF\n"
           "    r = [tau[i] - g[i] - sum(C[i][j] * qd[j] for j in range(n)) for i in range(n)]\n"
           "    L = [[0.0] * n for _ in range(n)]\n"
           "    for i in range(n):\n"
           "        for j in range(i + 1):\n"
           "            s = B[i][j] - sum(L[i][k] * L[j][k] for k in range(j))\n"
           "            if i == j:\n"
           "                if s <= 0.0:\n"
           "                    raise ValueError('B is not positive definite')\n"
           "                L[i][i] = math.sqrt(s)\n"
           "            else:\n"
           "                L[i][j] = s / L[j][j]\n"
           "    y = [0.0] * n\n"
           "    for i in range(n):\n"
           "        y[i] = (r[i] - sum(L[i][k] * y[k] for k in range(i))) / L[i][i]\n"
           "    x = [0.0] * n\n"
           "    for i in reversed(range(n)):\n"
           "        x[i] = (y[i] - sum(L[k][i] * x[k] for k in range(i + 1, n))) / L[i][i]\n"
           "    return x\n\n\n"
           "def _vector(name, args):\n"
           "    if name not in args:\n"
           "        return [0.0] * DOF\n"
           "    values = [float(v) for v in args[args.index(name) + 1].split(',')]\n"
           "    if len(values) != DOF:\n"
           "        sys.exit('error: %s: expected %d numbers' % (name, DOF))\n"
           "    return values\n\n\n"
           "if __name__ == '__main__':\n"
           "    q, qd, tau = (_vector(n, sys.argv) for n in ('--q', '--qd', '--tau'))\n"
           "    print(json.dumps({'B': mass_matrix(q), 'C': coriolis_matrix(q, qd), 'g': gravity(q),\n"
           "                      'qdd': forward_dynamics(q, qd, tau)}))\n";
    return out.str();
}

}  // namespace

std::string exportCode(const StructuredDynamics& s, const Scene& scene, CodeLanguage language, const std::string& date) {
    return language == CodeLanguage::C ? cCode(s, scene, date) : pythonCode(s, scene, date);
}

}  // namespace ll::symbolic
