#pragma once
// Exports a capture (or a time range of it) to vendor CSV, tidy CSV, JSON Lines, MCAP
// (format/mcap: ROS 2 messages in CDR and a JSON channel per device, the device's identity as
// metadata, its configuration snapshot as an attachment) or MATLAB .mat (record/mat_export.h)
// (docs/FILE_FORMATS.md, "CSV layouts"), streaming: the capture is read chunk by chunk and the output
// written in 1 MB blocks, so memory does not grow with the file. Progress is reported as
// a fraction of the capture read; returning false from it cancels (the partial outputs
// are removed).
#include "model/device_identity.h"
#include "model/sample.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <functional>
#include <limits>
#include <optional>
#include <string>

namespace imudesk::record {

class CaptureExporter {
    Q_DECLARE_TR_FUNCTIONS(CaptureExporter)

public:
    enum class Format { VendorCsv, TidyCsv, JsonLines, Mcap, Mat };
    struct Options {
        Format format = Format::TidyCsv;
        // Output file. Vendor CSV has a layout per frame type: a capture of one type goes to this
        // file, one of several to a file per type, run.csv -> run_HI91.csv, run_HI81.csv,
        // run_HI83.csv, run_NMEA.txt (Result::notes says so, Result::files names them).
        QString output;
        double fromS = 0;                                     // seconds since the recording started
        double toS = std::numeric_limits<double>::infinity(); // inclusive
    };
    struct Result {
        bool ok = false;
        bool cancelled = false;
        QString error;
        QString warning;         // e.g. the capture ends inside a chunk
        QStringList notes;       // what reading a vendor CSV or a raw byte dump involved (CaptureSource)
        QStringList files;
        uint64_t frames = 0;     // rows/objects written (samples and NMEA sentences)
        uint64_t skipped = 0;    // packets the format has no layout for (HI92 in vendor CSV)
    };
    // fraction 0..1; return false to cancel.
    using Progress = std::function<bool(double fraction)>;

    // capturePath: a capture, a vendor CSV or a raw byte dump (CaptureSource).
    static Result run(const QString &capturePath, const Options &options, const Progress &progress = {});

    static std::optional<Format> parseFormat(const QString &name); // "vendor-csv", "csv", "jsonl", "mcap", "mat"
    static QString vendorPath(const QString &output, const QString &type);
    // ".csv", ".jsonl", ".mcap" or ".mat": the default output's suffix.
    static QString extension(Format format);

    // The tidy CSV: one header row, time_s from the device clock, SI units in the names. A
    // module set to NWU names its attitude columns so (roll_nwu_deg ... quat_nwu_z).
    static const char *tidyHeader(model::WorldFrame worldFrame = model::WorldFrame::Enu);
    // originNs: the host time that host_time_s and common_time_s count from.
    static void appendTidyRow(std::string &out, const model::Sample &s, int frameTag, int64_t originNs);
};

} // namespace imudesk::record
