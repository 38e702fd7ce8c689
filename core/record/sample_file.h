#pragma once
// Every sample of a recording, whatever file holds it: a capture, a vendor CSV or a raw byte
// dump (CaptureSource, decoded through CaptureDecoder as a replay decodes it), or one member of
// a recorded session (a folder with session.json), chosen by device name (the only one when
// the session has one). For the readers that need a quantity from any file ImuDesk writes or
// imports: MagnetometerFile (`imudesk-cli magcal`), `imudesk-cli verify`.
#include "model/sample.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <functional>

namespace imudesk::record {

class SampleFile {
    Q_DECLARE_TR_FUNCTIONS(SampleFile)

public:
    struct Opened {
        bool ok = false;
        QString error;       // why not, with what to do
        QString kind;        // "session", "capture", "vendor CSV", "raw byte dump"
        QString device;      // the session's device read
        QStringList notes;   // conversions, a truncated end, ...
    };
    // Calls onSample with each decoded sample in the file's order (a HiPNUC packet's sample
    // carries its source frame type, e.g. "HI91").
    static Opened forEachSample(const QString &path, const QString &device,
                                const std::function<void(const model::Sample &)> &onSample);
    // A capture, vendor CSV or raw dump only (no session).
    static Opened forEachCaptureSample(const QString &path, const std::function<void(const model::Sample &)> &onSample);
};

} // namespace imudesk::record
