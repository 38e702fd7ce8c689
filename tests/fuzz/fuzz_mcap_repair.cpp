// libFuzzer target: imudesk-cli repair's MCAP reader (format/mcap/mcap_repair.h), which reads
// files that were cut short, and so any bytes at all.
//
// Whatever the bytes, the repair must not crash and must end; it keeps no more messages than
// the input has room for (a message record is at least 31 bytes), and what it writes is a
// complete MCAP file: the magic at both ends.
#include "format/mcap/mcap_repair.h"

#include <QBuffer>
#include <QByteArray>
#include <QDir>
#include <QFile>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#define FUZZ_CHECK(cond)                                                                                \
    do {                                                                                                \
        if (!(cond)) {                                                                                  \
            std::fprintf(stderr, "fuzz_mcap_repair: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                           \
        }                                                                                               \
    } while (0)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const QString out = QDir::temp().filePath(QStringLiteral("fuzz_mcap_repair_%1.mcap").arg(::getpid()));
    QByteArray bytes(reinterpret_cast<const char *>(data), qsizetype(size));
    QBuffer in(&bytes);
    in.open(QIODevice::ReadOnly);
    const auto r = imudesk::format::mcap::repairMcap(in, out);
    FUZZ_CHECK(r.ok || !r.error.isEmpty());
    FUZZ_CHECK(r.messages <= size / 31);
    if (r.ok) {
        QFile f(out);
        FUZZ_CHECK(f.open(QIODevice::ReadOnly));
        const QByteArray written = f.readAll();
        FUZZ_CHECK(written.size() >= 16 && written.startsWith("\x89MCAP0\r\n") && written.endsWith("\x89MCAP0\r\n"));
    }
    QFile::remove(out);
    return 0;
}
