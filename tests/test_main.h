#pragma once
// Every tests/test_*.cpp ends with one of these instead of Qt's QTEST_*_MAIN: the test file
// then adds its class to the executable of its family (granota-tests-core, -cli, -gui,
// -allocation, see tests/CMakeLists.txt) under its own file name, and tests/family_main.cpp runs it when that
// name is the first argument:
//     build/tests/granota-tests-core test_rational [Qt Test's options and functions…]
// ctest keeps one entry per file (`ctest -R test_rational`), each its own process, so a test
// still gets a fresh QApplication, a home of its own and its own exit code. What each macro
// sets up is what the Qt macro of the same name does (qtest.h), word for word.
#include <QtTest>

// QSKIP("why") is how Qt documents it; clang's -Wpedantic objects to the empty "..." of
// Qt's macro (GCC does not). For the rest of each test file.
#ifdef __clang__
#pragma clang diagnostic ignored "-Wgnu-zero-variadic-macro-arguments"
#endif

namespace granota::test {

/// A test file's main(): Qt Test's arguments, the test's own name already taken off.
using TestMain = int (*)(int argc, char* argv[]);

/// Adds `main` under the base name of `sourceFile` (test_rational for …/test_rational.cpp).
struct Registration {
    Registration(const char* sourceFile, TestMain main);
};

} // namespace granota::test

// A static function and a static object of internal linkage: each test file has its own.
#define GRANOTA_TEST_ENTRY(TestObject, setup)                                                                                    \
    static int granotaTestMain(int argc, char* argv[])                                                                           \
    {                                                                                                                            \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                                                       \
        setup;                                                                                                                   \
        TestObject tc;                                                                                                           \
        QTEST_SET_MAIN_SOURCE_PATH                                                                                               \
        return QTest::qExec(&tc, argc, argv);                                                                                    \
    }                                                                                                                            \
    static const granota::test::Registration granotaTestRegistration(__FILE__, &granotaTestMain);

/// QTEST_MAIN: a QApplication (a QGuiApplication where the family has no widgets).
#define GRANOTA_TEST_MAIN(TestObject) GRANOTA_TEST_ENTRY(TestObject, QTEST_MAIN_SETUP())
/// QTEST_GUILESS_MAIN: a QCoreApplication.
#define GRANOTA_TEST_GUILESS_MAIN(TestObject) GRANOTA_TEST_ENTRY(TestObject, QTEST_QAPP_SETUP(QCoreApplication))
/// QTEST_APPLESS_MAIN: no application object.
#define GRANOTA_TEST_NO_APP
#define GRANOTA_TEST_APPLESS_MAIN(TestObject) GRANOTA_TEST_ENTRY(TestObject, GRANOTA_TEST_NO_APP)
