#pragma once
// A recorded session of two synthetic HI91 modules (synthetic_capture.h) for the export tests:
// "A" (serial AAA1, 1000 frames) and "B" (BBB2, 1500 frames) with their session.json, started
// at 2026-11-29T20:00:00Z.
#include "record/session_manifest.h"
#include "synthetic_capture.h"

#include <QDir>
#include <QString>

namespace imudesk::test {

// Writes the session into folder (made if needed); false with *error.
inline bool writeTwoDeviceSession(const QString &folder, record::SessionManifest *manifest, QString *error)
{
    if (!QDir().mkpath(folder)) {
        *error = QStringLiteral("cannot make %1").arg(folder);
        return false;
    }
    manifest->startedUtc = QStringLiteral("2026-11-29T20:00:00.000Z");
    manifest->startedHostNs = 4'900'000'000;
    manifest->devices.clear();
    for (int i = 0; i < 2; ++i) {
        synthetic::CaptureSpec spec;
        spec.frames = 1000 + 500 * uint64_t(i);
        spec.seed = uint32_t(7 + i);
        spec.serial = i == 0 ? "AAA1" : "BBB2";
        spec.config = {{"device", std::to_string(i)}};
        const QString file = QStringLiteral("%1.imucap").arg(QLatin1Char('A' + i));
        if (synthetic::writeCapture(QDir(folder).filePath(file), spec) <= 0) {
            *error = QStringLiteral("cannot write %1").arg(file);
            return false;
        }
        record::SessionManifest::Device d;
        d.name = QString(QLatin1Char('A' + i));
        d.linkKind = QStringLiteral("HiPNUC serial");
        d.file = file;
        manifest->devices.push_back(d);
    }
    return manifest->save(folder, error);
}

} // namespace imudesk::test
