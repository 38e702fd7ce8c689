// The line speed through termios2 (TCGETS2), which reports any rate, including
// non-standard ones set with BOTHER (e.g. 256000). <asm/termbits.h> redefines
// struct termios, so this file must not include <termios.h>.
#include <asm/termbits.h>
#include <sys/ioctl.h>

namespace imudesk::sim::detail {

int readTermios2Speed(int fd)
{
    struct termios2 t {};
    if (::ioctl(fd, TCGETS2, &t) != 0)
        return -1;
    return int(t.c_ospeed);
}

} // namespace imudesk::sim::detail
