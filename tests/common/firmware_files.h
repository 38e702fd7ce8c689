#pragma once
// Helpers shared by the firmware update tests (serial KBOOT and CANopen): a simulated
// application image, writing it to a file, and the "result" line of `update --json`.
#include "protocol/ihex/firmware_image.h"
#include "sim/kboot_bootloader.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QTemporaryDir>

#include <cstdint>
#include <string>

namespace imudesk::test {

// The last {"event":"result",...} line of `imudesk-cli update --json` output; empty when none.
inline QJsonObject resultLine(const QString &out)
{
    const auto lines = out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        const auto o = QJsonDocument::fromJson(it->toUtf8()).object();
        if (o.value(QStringLiteral("event")).toString() == QStringLiteral("result"))
            return o;
    }
    return {};
}

// A simulated application of size bytes reporting version, placed at start.
inline protocol::ihex::FirmwareImage appImage(const std::string &version, size_t size, uint64_t seed,
                                              uint32_t start = 0x8000)
{
    protocol::ihex::FirmwareImage img;
    img.startAddress = start;
    img.data = sim::KbootBootloader::makeApplication(version, size, seed);
    return img;
}

// Writes content to name in dir and returns its path.
inline QString writeFile(const QTemporaryDir &dir, const QString &name, const std::string &content)
{
    const QString path = dir.filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(content.data(), qint64(content.size()));
    return path;
}

} // namespace imudesk::test
