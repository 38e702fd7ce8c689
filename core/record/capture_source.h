#pragma once
// Every file a capture is accepted in place of (replay, export, analysis, File > Open),
// recognised by its content, never its name:
//   * a capture (capture/capture_format.h, the magic "IMUDCAP1");
//   * a file of a family's own that an importer of core/decode takes (decode/file_import.h: a
//     vendor's CSV, a raw dump of what a module sent), converted to a capture in a temporary
//     directory that this object owns: keep it while the capture is read. A file without
//     arrival times gets its chunks stamped with the device's clock, and the header says so
//     (CaptureHeader::kHostTime = "absent").
#include "capture/capture_header.h"
#include "decode/file_import.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>

class QTemporaryDir;

namespace imudesk::record {

class CaptureSource {
    Q_DECLARE_TR_FUNCTIONS(CaptureSource)

public:
    enum class Kind { Capture, VendorCsv, RawDump, Unknown };

    CaptureSource();
    ~CaptureSource();
    CaptureSource(const CaptureSource &) = delete;
    CaptureSource &operator=(const CaptureSource &) = delete;

    // What the file holds. Unknown with *error saying why (unreadable, empty, no frames).
    static Kind detect(const QString &path, QString *error = nullptr);
    static const char *kindName(Kind k); // "capture", "vendor CSV", "raw byte dump", "unknown"

    // Makes path readable as a capture: the file itself, or a conversion in a temporary
    // directory. False with a message that says what the file is and what to do.
    bool prepare(const QString &path, QString *error);
    Kind kind() const { return m_kind; }
    const QString &capturePath() const { return m_capturePath; }
    // What the conversion did, for the user (no arrival times, malformed CSV lines, ...).
    const QStringList &notes() const { return m_notes; }

    struct Converted {
        bool ok = false;
        QString error;
        Kind kind = Kind::Unknown;
        QStringList notes;                    // as notes() says them
        decode::FileImporter::Result import;  // what the importer read (rows, frames, clock jumps, ...)
    };
    // Converts a file an importer takes (not a capture) to a capture at capturePath.
    static Converted convert(const QString &path, const QString &capturePath);

private:
    static const decode::FileImporter *importerOf(const QString &path, Kind *kind, QString *error);
    static Converted convertWith(const decode::FileImporter &importer, Kind kind, const QString &path,
                                 const QString &capturePath);

    Kind m_kind = Kind::Unknown;
    QString m_capturePath;
    QStringList m_notes;
    std::unique_ptr<QTemporaryDir> m_temp;
};

} // namespace imudesk::record
