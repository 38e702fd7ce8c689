#pragma once
// Every file a capture is accepted in place of (replay, export, analysis, File > Open),
// recognised by its content, never its name:
//   * a capture (capture/capture_format.h, the magic "IMUDCAP1");
//   * a CSV written by the vendor's PC tool (first line "HI91,..."), converted as
//     CsvCaptureConverter does;
//   * a raw byte dump, as a serial terminal or the vendor's tools write what the module sent:
//     HiPNUC frames and NMEA sentences found in its first kSniffBytes. It has no arrival
//     times, so its chunks are stamped with the device's clock (HI91 system_time, HI83
//     system_time_us, else the UTC time of NMEA sentences) and the header says so
//     (CaptureHeader::kHostTime = "absent").
// A converted file lives in a temporary directory that this object owns: keep it while the
// capture is read.
#include "capture/capture_header.h"

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
    static constexpr qint64 kSniffBytes = 64 * 1024;
    static constexpr size_t kRawChunkBytes = 512; // a raw dump's bytes per chunk (one time stamp each)

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

    struct RawResult {
        bool ok = false;
        QString error;
        uint64_t bytes = 0;
        uint64_t frames = 0;     // CRC-valid HiPNUC frames
        uint64_t sentences = 0;  // NMEA sentences with a valid checksum
        uint64_t clockJumps = 0; // device clock restarts or jumps the times were carried across
        bool deviceClock = false; // false: nothing in the dump carried a time, every stamp is 0
    };
    // Writes rawPath's bytes, unchanged, as a capture at capturePath (kRawChunkBytes per chunk).
    static RawResult convertRawDump(const QString &rawPath, const QString &capturePath);

private:
    Kind m_kind = Kind::Unknown;
    QString m_capturePath;
    QStringList m_notes;
    std::unique_ptr<QTemporaryDir> m_temp;
};

} // namespace imudesk::record
