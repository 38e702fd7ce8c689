#include "io/file_sync.h"

#include <QFileDevice>

#include <unistd.h>

namespace imudesk::io {

bool syncFileData(QFileDevice &file)
{
    file.flush();
    const int fd = file.handle();
    return fd >= 0 && ::fdatasync(fd) == 0;
}

} // namespace imudesk::io
