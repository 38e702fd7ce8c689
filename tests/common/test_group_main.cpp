// The main of a test group (common/test_main.h): `GROUP NAME [Qt Test arguments]` runs the test
// class of tst_NAME.cpp as that file's own executable would have, with argv[0] named after the
// test (Qt takes the application's name, and so its settings' file, from it); `GROUP --list`
// names the tests the group holds.
#include "test_registry.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace imudesk::test {

namespace {

std::map<std::string, TestEntry> &registry()
{
    static std::map<std::string, TestEntry> tests;
    return tests;
}

std::string testName(const char *sourceFile)
{
    std::string name(sourceFile);
    const auto slash = name.find_last_of("/\\");
    if (slash != std::string::npos)
        name.erase(0, slash + 1);
    const auto dot = name.rfind('.');
    if (dot != std::string::npos)
        name.erase(dot);
    return name;
}

// Temporary files in memory when the caller chose no TMPDIR. On a disk mounted with `discard`
// (virtual machines often are), deleting files and fdatasync() stall for seconds while other
// tests run beside this one, and the kernel's tty layer waits behind that I/O: poll() on a
// pseudo-terminal blocked in n_tty_poll -> flush_work for up to 4 s under `ctest -j2` (seen with
// perf's sched_switch call chains), which a simulated module on a pty cannot tell from a dead
// link. /dev/shm is a tmpfs on Debian; where it is missing, /tmp stays.
void tempFilesInMemory()
{
    if (std::getenv("TMPDIR"))
        return;
    struct stat shm {};
    if (::stat("/dev/shm", &shm) != 0 || !S_ISDIR(shm.st_mode) || ::access("/dev/shm", W_OK) != 0)
        return;
    const std::string dir = "/dev/shm/imudesk-tests-" + std::to_string(::getuid());
    // Searchable by others like /tmp: a test runs the CLI as another user on its own files.
    if (::mkdir(dir.c_str(), 0755) != 0 && errno != EEXIST)
        return;
    struct stat st {};
    if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::getuid())
        return; // someone else's, or not a folder: leave it alone
    ::chmod(dir.c_str(), 0755);
    ::setenv("TMPDIR", dir.c_str(), 1);
}

void listTests(FILE *out)
{
    for (const auto &[name, entry] : registry())
        std::fprintf(out, "%s\n", name.c_str());
}

} // namespace

bool registerTest(const char *sourceFile, TestEntry entry)
{
    const auto [it, added] = registry().emplace(testName(sourceFile), entry);
    if (!added) {
        std::fprintf(stderr, "test group: two test files are named %s\n", it->first.c_str());
        std::abort();
    }
    return true;
}

} // namespace imudesk::test

int main(int argc, char **argv)
{
    using namespace imudesk::test;
    if (argc >= 2 && std::strcmp(argv[1], "--list") == 0) {
        listTests(stdout);
        return 0;
    }
    if (argc < 2 || argv[1][0] == '-') {
        std::fprintf(stderr, "usage: %s TEST [Qt Test arguments]\n       %s --list\nthe tests of this group:\n",
                     argv[0], argv[0]);
        listTests(stderr);
        return 2;
    }
    const auto found = registry().find(argv[1]);
    if (found == registry().end()) {
        std::fprintf(stderr, "%s: no test named %s in this group; these are:\n", argv[0], argv[1]);
        listTests(stderr);
        return 2;
    }
    tempFilesInMemory();
    // argv[0] becomes <this executable's folder>/<test>: the folder stays (applicationDirPath),
    // the name is the test's, as when each test was an executable of its own.
    std::string self(argv[0]);
    const auto slash = self.rfind('/');
    std::string program = (slash == std::string::npos ? std::string() : self.substr(0, slash + 1)) + found->first;
    std::vector<char *> args{program.data()};
    for (int i = 2; i < argc; ++i)
        args.push_back(argv[i]);
    args.push_back(nullptr);
    int count = argc - 1; // outlives the application object, which keeps a reference to it
    return found->second(count, args.data());
}
