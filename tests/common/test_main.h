#pragma once
// A test class's entry point in a test group (issue 33: build time). Each tests/<folder> is
// linked into a few executables instead of one per class; every class still runs on its own,
// in a process of its own: `tests_unit tst_attitude [Qt Test arguments]`, which ctest does for
// each name (tests/CMakeLists.txt). The macros replace Qt Test's QTEST_*MAIN and do what they
// do (the same application object, initMain), in a function the group's main
// (test_group_main.cpp) calls by the file's name instead of in main(). Not Qt's source path
// (QTEST_SET_MAIN_SOURCE_PATH, for QFINDTESTDATA): the tests find their data through
// common/test_paths.h, and nothing reads Qt's QT_TESTCASE_BUILDDIR and QT_TESTCASE_SOURCEDIR, so
// ccache leaves those out of its hash (CMakeLists.txt).
#include "test_registry.h"

#include <QTest>

#define IMUDESK_TEST_REGISTER_(entry)                                                                            \
    namespace {                                                                                                  \
    [[maybe_unused]] const bool imudeskTestRegistered = ::imudesk::test::registerTest(__FILE__, entry);         \
    }

#define IMUDESK_TEST_ENTRY_(TestObject, ...)                                                                     \
    namespace {                                                                                                  \
    int imudeskTestEntry(int argc, char *argv[])                                                                 \
    {                                                                                                            \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                                       \
        __VA_ARGS__                                                                                              \
        TestObject tc;                                                                                           \
        return QTest::qExec(&tc, argc, argv);                                                                    \
    }                                                                                                            \
    }                                                                                                            \
    IMUDESK_TEST_REGISTER_(imudeskTestEntry)

// QTEST_MAIN: a QApplication, QGuiApplication or QCoreApplication, as the file links widgets,
// Gui or neither.
#define IMUDESK_TEST_MAIN(TestObject) IMUDESK_TEST_ENTRY_(TestObject, QTEST_MAIN_SETUP())
// QTEST_GUILESS_MAIN: a QCoreApplication.
#define IMUDESK_TEST_GUILESS_MAIN(TestObject) IMUDESK_TEST_ENTRY_(TestObject, QTEST_QAPP_SETUP(QCoreApplication))
// QTEST_APPLESS_MAIN: no application object.
#define IMUDESK_TEST_APPLESS_MAIN(TestObject) IMUDESK_TEST_ENTRY_(TestObject)
// A test that makes its own application (a screen of a given size, say): `function` is its
// main, int function(int argc, char **argv).
#define IMUDESK_TEST_CUSTOM_MAIN(function) IMUDESK_TEST_REGISTER_(function)
