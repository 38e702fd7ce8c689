#include "file_size_limit.h"

namespace imudesk::cli {

void outliveFileSizeLimit()
{
    // Windows has no file size limit that raises a signal: a write past a quota or a full disk
    // fails, and the recorder says so.
}

} // namespace imudesk::cli
