#pragma once
// Reads HI91 CSV files in the layout of the vendor's PC tool (decode/hipnuc_vendor_csv.h) back into
// samples, streaming, so old logs can be replayed, plotted, analysed and used for
// magnetometer calibration. Columns are found by their header names (the vendor's order
// is not required); a malformed line is reported with its line number and skipped.
#include "model/sample.h"

#include <QCoreApplication>
#include <QIODevice>
#include <QString>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace imudesk::decode {

class VendorCsvImporter {
    Q_DECLARE_TR_FUNCTIONS(VendorCsvImporter)

public:
    static constexpr size_t kMaxLine = 4096;
    static constexpr size_t kMaxReportedErrors = 100;

    struct LineError {
        uint64_t line = 0; // 1-based
        QString message;
    };
    struct Result {
        bool ok = false;          // the file could be read and had a vendor header
        QString error;            // why not
        uint64_t samples = 0;
        uint64_t badLines = 0;
        std::vector<LineError> errors; // the first kMaxReportedErrors bad lines
    };
    using SampleFn = std::function<void(const model::Sample &)>;
    // A row as the file has it: the header's names and the row's cells (as many; trimmed).
    struct Row {
        const std::vector<std::string> &names;
        const std::vector<std::string_view> &cells;
    };
    using RowFn = std::function<void(const model::Sample &, const Row &)>;

    static Result read(const QString &path, const SampleFn &onSample);
    static Result read(QIODevice &device, const SampleFn &onSample);
    // The same, with each row's cells beside its sample (the converter keeps what HI91 lacks).
    static Result readRows(const QString &path, const RowFn &onRow);
    static Result readRows(QIODevice &device, const RowFn &onRow);
    // Does the file start with the vendor's HI91 header?
    static bool looksLikeVendorCsv(const QString &path);
};

} // namespace imudesk::decode
