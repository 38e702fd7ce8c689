#pragma once
// Where the tests find what they read at run time: this checkout's test data, this build's
// imudesk-cli and its compiled translations. Those paths are absolute, so two clones of the same
// sources differ in them; they are written into one small file of the build
// (tests/CMakeLists.txt generates test_paths.cpp) instead of every test's command line, and
// ccache serves every test object of a second clone (CI's clean clone) from the first one's
// cache (issue 33: with the paths on the command line, 113 of 194 compilations of a clean clone
// missed the cache).
namespace imudesk::test::paths {
const char *testData(); // <source>/tests/data (need not exist: clean a path built on it)
const char *cli();      // imudesk-cli of this build
const char *gui();      // imudesk of this build ("" when the GUI is not built)
const char *qmDir();    // the .qm files of this build ("" when the GUI is not built)
} // namespace imudesk::test::paths

#define IMUDESK_TEST_DATA (::imudesk::test::paths::testData())
#define IMUDESK_CLI_PATH (::imudesk::test::paths::cli())
// IMUDESK_GUI_PATH and IMUDESK_QM_DIR (paths::gui(), paths::qmDir()) are defined for the
// widget tests only (tests/CMakeLists.txt, app/gui/CMakeLists.txt).
