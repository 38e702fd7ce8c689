#pragma once
// Runs SampleAnalyzer over a file, recognised by content (CaptureSource): a capture (decoded
// through CaptureDecoder, the live path), a raw byte dump (converted to one, the device's
// clock for time) or a CSV written by the vendor's PC tool. Used by `imudesk-cli analyze` and the
// analysis window (which calls it from a worker thread).
#include "record/sample_analyzer.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <functional>

namespace imudesk::record {

class FileAnalysis {
    Q_DECLARE_TR_FUNCTIONS(FileAnalysis)

public:
    struct Outcome {
        bool ok = false;
        bool cancelled = false;
        QString error;
        QStringList warnings;   // truncated capture, malformed CSV lines (with line numbers)
        SampleAnalyzer::Result result;
    };
    // progress: fraction 0..1 of the file read; return false to cancel.
    static Outcome run(const QString &path, const std::string &frameType = {}, double tauMax = 1000.0,
                       const std::function<bool(double)> &progress = {});
};

} // namespace imudesk::record
