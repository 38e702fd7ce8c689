#pragma once
// Puts a file's data on its disk (not only in the system's cache), so that a recording keeps what
// it wrote before a power loss. One platform file each: file_sync_posix.cpp (fdatasync) and
// file_sync_windows.cpp (FlushFileBuffers).
class QFileDevice;

namespace imudesk::io {

// Flushes file's buffer, then asks the system to write its data to the disk. False when the file
// is not open on a descriptor or the system refused.
bool syncFileData(QFileDevice &file);

} // namespace imudesk::io
