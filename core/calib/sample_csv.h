#pragma once
// Numeric CSV tables as ImuDesk writes and reads calibration samples: a header row of
// column names, then one row of numbers per sample (',' separated; blank lines and lines
// starting with '#' skipped; CR LF or LF). `imudesk-cli magcal` reads the columns
// mag_x, mag_y, mag_z (uT) from such a file, in any order, among other columns.
// Bounded: kMaxLineLength per line, kMaxRows rows, kMaxColumns columns; errors name the line.
#include <Eigen/Core>

#include <QByteArray>
#include <QByteArrayView>
#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <vector>

namespace imudesk::calib {

struct SampleTable {
    QStringList columns;
    std::vector<std::vector<double>> rows; // each rows[i].size() == columns.size()
    int columnIndex(const QString &name) const; // case-insensitive; -1 when absent
};

class SampleCsv {
    Q_DECLARE_TR_FUNCTIONS(SampleCsv)

public:
    static constexpr qsizetype kMaxLineLength = 4096;
    static constexpr size_t kMaxRows = 2000000;
    static constexpr int kMaxColumns = 64;

    // false with *error (translated, with the line number) on malformed input.
    static bool parse(QByteArrayView data, SampleTable &out, QString *error = nullptr);
    static QByteArray write(const SampleTable &table);
    // The mag_x, mag_y, mag_z columns as vectors; false when a column is missing.
    static bool magnetometer(const SampleTable &table, std::vector<Eigen::Vector3d> &out, QString *error = nullptr);
};

} // namespace imudesk::calib
