#pragma once
// The tests a test group holds (test_main.h, test_group_main.cpp); no Qt here, so the group's
// main compiles once for every group.

namespace imudesk::test {

using TestEntry = int (*)(int argc, char **argv);
// Registers the class of the file `sourceFile` (its __FILE__; the test is named after the file,
// e.g. tst_attitude). Returns true; called while the executable's statics are made.
bool registerTest(const char *sourceFile, TestEntry entry);

} // namespace imudesk::test
