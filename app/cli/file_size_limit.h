#pragma once
// A file size limit (ulimit -f) must end a recording with a message, not kill the process: on
// POSIX systems the signal it raises (SIGXFSZ) is ignored, so that the write fails with EFBIG
// and the recorder says so. Windows has no such limit or signal. One platform file each:
// file_size_limit_posix.cpp, file_size_limit_windows.cpp.
namespace imudesk::cli {

void outliveFileSizeLimit();

} // namespace imudesk::cli
