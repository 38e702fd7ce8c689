#include "file_size_limit.h"

#include <csignal>

namespace imudesk::cli {

void outliveFileSizeLimit()
{
    std::signal(SIGXFSZ, SIG_IGN);
}

} // namespace imudesk::cli
