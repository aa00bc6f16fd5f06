// The main of a test folder's program: runs the test named by the first argument with
// the rest (Qt Test's options and test functions), or lists the tests it holds.
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "test_registry.hpp"

namespace ll::test {
namespace {

std::map<std::string, TestProgram>& registry() {
    static std::map<std::string, TestProgram> tests;
    return tests;
}

}  // namespace

bool registerTest(const char* file, TestProgram program) {
    std::string name = file;
    name = name.substr(name.find_last_of('/') + 1);
    name = name.substr(0, name.find('.'));
    return registry().emplace(name, program).second;
}

}  // namespace ll::test

int main(int argc, char** argv) {
    const auto& tests = ll::test::registry();
    const auto it = argc >= 2 ? tests.find(argv[1]) : tests.end();
    if (it == tests.end()) {
        std::fprintf(stderr, "usage: %s TEST [Qt Test options and functions]\ntests:", argc ? argv[0] : "tests");
        for (const auto& [name, program] : tests) std::fprintf(stderr, " %s", name.c_str());
        std::fprintf(stderr, "\n");
        return 2;
    }
    // The test sees its own name as the program's (Qt's application name, so each test
    // has its own settings and data folders) and then its own arguments, as if it were alone.
    std::vector<char*> args{argv[1]};
    for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
    args.push_back(nullptr);
    return it->second(argc - 1, args.data());
}
