#include "io/file_sync.h"

#include <QFileDevice>

#include <io.h>
#include <windows.h>

namespace imudesk::io {

bool syncFileData(QFileDevice &file)
{
    file.flush();
    const int fd = file.handle();
    if (fd < 0)
        return false;
    const auto handle = reinterpret_cast<HANDLE>(::_get_osfhandle(fd));
    return handle != INVALID_HANDLE_VALUE && ::FlushFileBuffers(handle) != 0;
}

} // namespace imudesk::io
