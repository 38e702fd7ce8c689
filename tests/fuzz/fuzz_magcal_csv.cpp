// libFuzzer target: the sample CSV readers behind `imudesk-cli magcal` (parseColumns, only the
// magnetometer's columns of a wider file) and the calibration history (parse), followed by the
// magnetometer fit on whatever mag columns it finds.
//
// Whatever the input, parsing must not crash. When it parses, every row has one value per
// column and all values are finite; writing the table and parsing it again gives the same
// table. When the mag columns are there, the fit runs (bounded to the first 2000 rows to
// keep iterations fast) and its verdict always comes with a reason.
//
// The full fit's accuracy figures come from refitting resampled copies of the data (32 refits
// by default). Each refit is the same Huber-LM code as the fit itself, so two of them exercise
// that path as well as 32 do; with 32, an input that keeps every refit at its iteration cap took
// 34 s under the sanitizers, past libFuzzer's per-input timeout.
#include "calib/mag_calibrator.h"
#include "calib/sample_csv.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>

#define FUZZ_CHECK(cond)                                                                              \
    do {                                                                                              \
        if (!(cond)) {                                                                                \
            std::fprintf(stderr, "fuzz_magcal_csv: invariant failed: %s (line %d)\n", #cond, __LINE__); \
            __builtin_trap();                                                                         \
        }                                                                                             \
    } while (0)

using namespace imudesk::calib;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    // The reader `magcal` uses on every CSV (vendor, tidy, session export): only the
    // magnetometer's columns are read, each row has one finite value per wanted column.
    {
        SampleCsv::ColumnChoice choice;
        choice.wanted = SampleCsv::magnetometerColumns();
        choice.keyColumn = QStringLiteral("device");
        SampleTable picked;
        SampleCsv::ColumnInfo info;
        if (SampleCsv::parseColumns(QByteArrayView(reinterpret_cast<const char *>(data), qsizetype(size)), choice, picked,
                                    nullptr, &info)) {
            FUZZ_CHECK(picked.columns.size() == 3);
            for (const auto &row : picked.rows) {
                FUZZ_CHECK(row.size() == 3);
                for (double v : row)
                    FUZZ_CHECK(std::isfinite(v));
            }
            FUZZ_CHECK(info.keys.size() <= 100);
            std::vector<Eigen::Vector3d> picks;
            FUZZ_CHECK(SampleCsv::magnetometer(picked, picks));
            FUZZ_CHECK(picks.size() == picked.rows.size());
        }
    }
    SampleTable table;
    if (!SampleCsv::parse(QByteArrayView(reinterpret_cast<const char *>(data), qsizetype(size)), table))
        return 0;
    for (const auto &row : table.rows) {
        FUZZ_CHECK(row.size() == size_t(table.columns.size()));
        for (double v : row)
            FUZZ_CHECK(std::isfinite(v));
    }
    SampleTable again;
    FUZZ_CHECK(SampleCsv::parse(SampleCsv::write(table), again));
    FUZZ_CHECK(again.columns.size() == table.columns.size());
    FUZZ_CHECK(again.rows == table.rows);

    std::vector<Eigen::Vector3d> mag;
    if (!SampleCsv::magnetometer(table, mag))
        return 0;
    if (mag.size() > 2000)
        mag.resize(2000);
    MagCalibrator::Options options;
    options.replicates = 2;
    for (MagCalMode mode : {MagCalMode::Full3D, MagCalMode::HardIronOnly, MagCalMode::Planar2D}) {
        const MagCalResult r = MagCalibrator(options).calibrate(mag, mode);
        FUZZ_CHECK(!r.reason.isEmpty());
        FUZZ_CHECK(r.samples == int(mag.size()));
    }
    return 0;
}
