#pragma once
// HiPNUC's files read as captures (decode/file_import.h):
//   * the CSV its PC tool writes (first line "HI91,..."; decode/hipnuc_vendor_csv_reader.h):
//     each row an HI91 frame (main_status 0: the layout has no status column) in a chunk of
//     its own, stamped with pc_counter as the arrival time, and the cells the frame cannot give
//     back (pps_sync_stamp, incli_x, ...) in a chunk beside it; malformed lines are reported
//     with their line numbers and left out;
//   * a raw dump of what a module sent, as a serial terminal or the vendor's tools write it:
//     HiPNUC frames and NMEA sentences in its first kSniffBytes. The bytes go in unchanged,
//     kRawChunkBytes a chunk; it has no arrival times, so each chunk is stamped with the
//     device's clock (HI91 system_time, HI83 system_time_us, else the UTC time of NMEA
//     sentences).
#include "decode/file_import.h"

#include <QCoreApplication>

namespace imudesk::decode {

class HipnucVendorCsvImport : public FileImporter {
    Q_DECLARE_TR_FUNCTIONS(HipnucVendorCsvImport)

public:
    Kind kind() const override { return Kind::VendorCsv; }
    Times times() const override { return Times::PcCounter; }
    const char *family() const override;
    const char *linkKind() const override { return "vendor CSV import"; }
    bool recognises(const QByteArray &head, bool whole) const override;
    QString looksLike() const override;
    Result convert(const QString &path, ChunkSink &out) const override;
};

class HipnucRawDumpImport : public FileImporter {
    Q_DECLARE_TR_FUNCTIONS(HipnucRawDumpImport)

public:
    static constexpr size_t kRawChunkBytes = 512; // bytes per chunk (one time stamp each)

    Kind kind() const override { return Kind::RawDump; }
    Times times() const override { return Times::DeviceClock; }
    const char *family() const override;
    const char *linkKind() const override { return "raw byte dump"; }
    bool recognises(const QByteArray &head, bool whole) const override;
    QString looksLike() const override;
    Result convert(const QString &path, ChunkSink &out) const override;
};

} // namespace imudesk::decode
