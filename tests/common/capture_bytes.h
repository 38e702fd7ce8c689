#pragma once
// The bytes a capture recorded, as a serial terminal would have saved them: its received-bytes
// chunks one after the other, without the header, times or idle markers.
#include "capture/capture_reader.h"

#include <QByteArray>
#include <QString>

namespace imudesk::test {

inline QByteArray receivedBytes(const QString &capturePath)
{
    capture::CaptureReader reader;
    QString error;
    QByteArray raw;
    if (!reader.open(capturePath, &error))
        return raw;
    capture::CaptureReader::Chunk c;
    while (reader.next(c) == capture::CaptureReader::Result::Chunk)
        if (c.kind == capture::ChunkReceived)
            raw.append(reinterpret_cast<const char *>(c.data), qsizetype(c.size));
    return raw;
}

} // namespace imudesk::test
