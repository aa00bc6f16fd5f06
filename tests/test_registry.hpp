#pragma once
// One program per test folder (tests/core, tests/ui, tests/app): each test file registers
// its test class under its own name (test_cholesky for test_cholesky.cpp), and ctest runs
// the folder's program once per test, the name first: `core_tests test_cholesky -v2`.
// One link and one compiled main per folder instead of one per test (see tests/CMakeLists.txt).
//
// LL_TEST_MAIN, LL_TEST_GUILESS_MAIN and LL_TEST_APPLESS_MAIN are QTEST_MAIN,
// QTEST_GUILESS_MAIN and QTEST_APPLESS_MAIN with a registration for a main: the same
// application object, attributes and source path. A test that needs its own set-up
// before the application exists registers a function: LL_TEST_PROGRAM(function).
#include <QtTest>

namespace ll::test {

using TestProgram = int (*)(int argc, char** argv);
// Registers `program` under the stem of `file` (a test's __FILE__); the value is only
// for the static initialiser that calls it.
bool registerTest(const char* file, TestProgram program);

}  // namespace ll::test

#define LL_TEST_REGISTER(TestObject, ...)                                  \
    static int llRun##TestObject(int argc, char* argv[]) {                 \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>(); \
        __VA_ARGS__                                                        \
        TestObject tc;                                                     \
        QTEST_SET_MAIN_SOURCE_PATH                                         \
        return QTest::qExec(&tc, argc, argv);                              \
    }                                                                      \
    [[maybe_unused]] static const bool llRegistered##TestObject = ll::test::registerTest(__FILE__, &llRun##TestObject);

#define LL_TEST_MAIN(TestObject) LL_TEST_REGISTER(TestObject, QTEST_MAIN_SETUP())
#define LL_TEST_GUILESS_MAIN(TestObject) LL_TEST_REGISTER(TestObject, QTEST_QAPP_SETUP(QCoreApplication))
#define LL_TEST_APPLESS_MAIN(TestObject) LL_TEST_REGISTER(TestObject)
#define LL_TEST_PROGRAM(function) [[maybe_unused]] static const bool llRegistered##function = ll::test::registerTest(__FILE__, &function);
