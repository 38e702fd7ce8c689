#pragma once
// Turns a CSV written by the vendor's PC tool (HI91 layout, see decode/hipnuc_vendor_csv.h) into a
// capture file, so that old logs are replayed, exported and analysed like recordings:
// each row becomes an HI91 frame (main_status 0: the layout has no status column) in its
// own chunk, stamped with pc_counter as the arrival time. Malformed lines are reported
// with their line numbers and left out.
#include "record/vendor_csv_importer.h"

#include <QCoreApplication>
#include <QString>

namespace imudesk::record {

class CsvCaptureConverter {
    Q_DECLARE_TR_FUNCTIONS(CsvCaptureConverter)

public:
    struct Result {
        bool ok = false;
        QString error;
        VendorCsvImporter::Result import; // samples, malformed lines
    };
    static Result convert(const QString &csvPath, const QString &capturePath);
};

} // namespace imudesk::record
