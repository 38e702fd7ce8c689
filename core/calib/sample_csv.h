#pragma once
// Numeric CSV tables as ImuDesk writes and reads calibration samples: a header row of
// column names, then one row of numbers per sample (',' separated; blank lines and lines
// starting with '#' skipped; CR LF or LF). `imudesk-cli magcal` reads the columns
// mag_x, mag_y, mag_z (uT) from such a file, in any order, among other columns.
// Bounded: kMaxLineLength per line, kMaxRows rows, kMaxColumns columns; errors name the line.
//
// parseColumns reads only the columns a caller needs from a wider table: every CSV ImuDesk
// writes or imports (the vendor's layout, whose first column is the frame tag "HI91" under a
// header "HI91"; the tidy export, empty where a frame lacks a quantity; a session's export,
// whose "device" column names the device). The other columns may hold anything and are not
// read; a needed column that is missing, or a needed cell that is not a number, is an error
// naming the line and the column. A row whose needed cells are all empty is a frame without
// those quantities and is passed over (counted).
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
    static constexpr int kMaxFileColumns = 1024; // parseColumns: columns of the file (few are read)

    struct ColumnChoice {
        // One entry per column to read: the names it may have (case-insensitive), e.g.
        // {"mag_x", "mag_x_uT"}. The table's columns are the names the header has, in this order.
        QList<QStringList> wanted;
        // A text column rows are chosen by (a session export's "device"); empty: none. Rows whose
        // keyColumn differs from keyValue are passed over; keyValue empty: every row.
        QString keyColumn;
        QString keyValue;
    };
    struct ColumnInfo {
        size_t emptyRows = 0;   // rows whose needed cells were all empty
        size_t otherRows = 0;   // rows of another keyValue
        QStringList keys;       // keyColumn's values, in the order first met (at most 100)
    };

    // false with *error (translated, with the line number) on malformed input.
    static bool parse(QByteArrayView data, SampleTable &out, QString *error = nullptr);
    static bool parseColumns(QByteArrayView data, const ColumnChoice &choice, SampleTable &out, QString *error = nullptr,
                             ColumnInfo *info = nullptr);
    static QByteArray write(const SampleTable &table);
    // The magnetometer's columns by the names ImuDesk's files give them (plain and vendor CSV:
    // mag_x; tidy CSV: mag_x_uT), for parseColumns.
    static QList<QStringList> magnetometerColumns();
    // The mag_x, mag_y, mag_z (or mag_x_uT, ...) columns as vectors; false when a column is missing.
    static bool magnetometer(const SampleTable &table, std::vector<Eigen::Vector3d> &out, QString *error = nullptr);
};

} // namespace imudesk::calib
