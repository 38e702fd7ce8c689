#pragma once
// The magnetometer samples (uT) of any file ImuDesk writes or imports that carries them, for
// `imudesk-cli magcal` (issue 53). Recognised by content, through the readers that already
// exist:
//   * a recorded session (a folder with session.json, session_manifest.h): one member's capture,
//     chosen by device name (the only one when the session has one device);
//   * a capture, or a raw byte dump (CaptureSource): decoded through CaptureDecoder like a
//     replay; the first frame type that carries a magnetometer in uT is read (an HEC495's
//     relative field has no unit and is not);
//   * JSON Lines (the export, `imudesk-cli decode --json`): each object's "mag" [x, y, z];
//   * a CSV (calib::SampleCsv::parseColumns): the vendor's layout (any frame type), ImuDesk's
//     tidy export (mag_x_uT, ...), a session's export (its "device" column chooses the rows)
//     or a plain table of mag_x, mag_y, mag_z. Only the magnetometer's columns are read.
// A missing magnetometer, or a bad number where one is needed, is an error naming the line
// and the column (or key).
#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <vector>

namespace imudesk::record {

class MagnetometerFile {
    Q_DECLARE_TR_FUNCTIONS(MagnetometerFile)

public:
    static constexpr qint64 kMaxTextBytes = 512ll * 1024 * 1024; // a text file is read whole
    static constexpr size_t kMaxSamples = 2000000;

    struct Result {
        bool ok = false;
        QString error;           // why not, with what to do
        QString kind;            // "session", "capture", "raw byte dump", "JSON Lines", "CSV"
        QString source;          // the frame type or the columns read, e.g. "HI91", "mag_x_uT, ..."
        QString device;          // the device of a session (or of a session's export) read
        QStringList notes;       // frames without a magnetometer passed over, conversions, ...
        std::vector<Eigen::Vector3d> samples;
    };
    // device: which device of a session (folder or export) to read; empty: the only one.
    static Result read(const QString &path, const QString &device = QString());
};

} // namespace imudesk::record
